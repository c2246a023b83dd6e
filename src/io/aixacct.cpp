#include "hyst/io/aixacct.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "line_reader.hpp"
#include "text_encoding.hpp"
#include "text_fields.hpp"

namespace hyst::io {
namespace {

using detail::parse_number;
using detail::trim;

//! "file:line: " or "line N: " for an unnamed source.
std::string where(std::string_view source, std::size_t line) {
  return detail::location(source, line) + ": ";
}

//! "Table 12" -> 12.
std::optional<std::size_t> table_number(std::string_view line) {
  constexpr std::string_view kTable = "Table ";
  line = trim(line);
  if (!line.starts_with(kTable)) return std::nullopt;
  const auto digits = line.substr(kTable.size());
  std::size_t number = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
    return std::nullopt;
  }
  return number;
}

//! Tab-separated fields, trimmed; trailing tabs (an empty last field) are dropped.
std::vector<std::string_view> split_tabs(std::string_view line) {
  return detail::split_fields(trim(line), '\t');
}

//! "V+ [V]" -> {"V+", "V"}; "Averages []" -> {"Averages", ""}; "Time" -> {"Time", ""}.
std::pair<std::string, std::string> name_and_unit(std::string_view field) {
  if (field.ends_with(']')) {
    const auto open = field.rfind('[');
    if (open != std::string_view::npos && open > 0) {
      return {std::string(trim(field.substr(0, open))),
              std::string(field.substr(open + 1, field.size() - open - 2))};
    }
  }
  return {std::string(field), std::string()};
}

std::string column_list(const AixacctTable& table) {
  std::string list;
  for (const auto& column : table.columns)
    list += (list.empty() ? "" : ", ") + column.header();
  return list.empty() ? std::string("none") : list;
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view source) : lines_(text), source_(source) {
    file_.source = std::string(source);
  }

  AixacctFile run() {
    std::string_view line;
    if (!lines_.next(line) || !is_kind_line(trim(line))) {
      throw Error(fmt::format(
          "{}not an aixACCT export (the first line is '{}', expected a word ending in 'Result' "
          "such as 'PiezoResult')",
          where(source_, 1), trim(line)));
    }
    file_.kind = std::string(trim(line));
    bool pending = lines_.next(line);
    while (pending) {
      const auto content = trim(line);
      if (content.empty()) {
        pending = lines_.next(line);
      } else if (const auto number = table_number(content)) {
        pending = read_table(*number, line);
      } else if (const auto colon = content.find(':');
                 colon != std::string_view::npos && content.find('\t') == std::string_view::npos) {
        file_.header.emplace_back(std::string(trim(content.substr(0, colon))),
                                  std::string(trim(content.substr(colon + 1))));
        pending = lines_.next(line);
      } else if (content.find('\t') == std::string_view::npos) {
        file_.titles.emplace_back(content);
        pending = lines_.next(line);
      } else {
        throw Error(fmt::format("{}a table row outside a table (no 'Table N' line before it)",
                                where(source_, lines_.number())));
      }
    }
    if (file_.measurements.empty()) {
      throw Error(fmt::format("{}: the file has no measurement table", source_));
    }
    return std::move(file_);
  }

 private:
  static bool is_kind_line(std::string_view line) {
    return line.size() > 6 && line.ends_with("Result") &&
           line.find_first_of(" \t") == std::string_view::npos;
  }

  //! Reads one table starting at its "Table N" line; returns whether `line` holds the next line.
  bool read_table(std::size_t number, std::string_view& line) {
    AixacctTable table;
    table.number = number;
    table.first_line = lines_.number();
    const bool summary = file_.titles.empty() && file_.header.empty();
    const auto table_where = [&] {
      return fmt::format("{}table {}{}", where(source_, lines_.number()), number,
                         summary ? " (summary)" : "");
    };
    if (summary && file_.summary) {
      throw Error(
          fmt::format("{}: a second table before the file header (only one summary "
                      "table is expected)",
                      table_where()));
    }
    for (const auto& other : file_.measurements) {
      if (!summary && other.number == number) {
        throw Error(fmt::format("{}: table number {} was already used on line {}", table_where(),
                                number, other.first_line));
      }
    }

    // Metadata up to the column header (the first line with a tab).
    bool header_found = false;
    while (!header_found) {
      if (!lines_.next(line) || trim(line).empty()) {
        throw Error(fmt::format("{}: the table ends before its column header line", table_where()));
      }
      // A tab marks the column header, even a lone trailing one after a single column.
      if (line.find('\t') != std::string_view::npos) {
        header_found = true;
        break;
      }
      const auto content = trim(line);
      const auto colon = content.find(':');
      if (colon == std::string_view::npos || colon == 0) {
        throw Error(fmt::format("{}: '{}' is neither 'key: value' metadata nor a column header",
                                table_where(), content));
      }
      table.metadata.emplace_back(std::string(trim(content.substr(0, colon))),
                                  std::string(trim(content.substr(colon + 1))));
    }

    const auto headers = split_tabs(line);
    for (std::size_t j = 0; j < headers.size(); ++j) {
      if (headers[j].empty()) {
        throw Error(
            fmt::format("{}: column {} of the header has an empty name", table_where(), j + 1));
      }
      auto [name, unit] = name_and_unit(headers[j]);
      for (std::size_t i = 0; i < j; ++i) {
        if (table.columns[i].name == name) {
          throw Error(fmt::format("{}: column {} ('{}') has the same name as column {}",
                                  table_where(), j + 1, headers[j], i + 1));
        }
      }
      table.columns.push_back({std::move(name), std::move(unit), {}});
    }

    // Data rows up to a blank line, the next table or the end of the file.
    bool pending = false;
    while (lines_.next(line)) {
      const auto content = trim(line);
      if (content.empty() || table_number(content)) {
        pending = !content.empty();
        break;
      }
      const auto fields = split_tabs(line);
      if (fields.size() != table.columns.size()) {
        throw Error(fmt::format("{}: row has {} fields but the header has {}", table_where(),
                                fields.size(), table.columns.size()));
      }
      for (std::size_t j = 0; j < fields.size(); ++j) {
        const auto value = parse_number(fields[j]);
        if (!value) {
          throw Error(fmt::format("{}: column {} ('{}'): '{}' is not a finite number",
                                  table_where(), j + 1, table.columns[j].header(), fields[j]));
        }
        table.columns[j].values.push_back(*value);
      }
    }
    if (table.rows() == 0) {
      throw Error(fmt::format("{}: the table has a column header but no data rows",
                              fmt::format("{}table {}", where(source_, table.first_line), number)));
    }
    if (summary) {
      file_.summary = std::move(table);
    } else {
      file_.measurements.push_back(std::move(table));
    }
    if (pending) return true;
    return lines_.next(line);
  }

  detail::LineReader lines_;
  std::string_view source_;
  AixacctFile file_;
};

}  // namespace

std::string AixacctColumn::header() const {
  return unit.empty() ? name : fmt::format("{} [{}]", name, unit);
}

const AixacctColumn* AixacctTable::find(std::string_view name) const {
  for (const auto& column : columns) {
    if (column.name == name || column.header() == name) return &column;
  }
  return nullptr;
}

const AixacctColumn& AixacctTable::column(std::string_view name, std::string_view source) const {
  if (const auto* found = find(name)) return *found;
  throw Error(fmt::format("{}table {}: no column '{}' (columns: {})",
                          source.empty() ? std::string() : fmt::format("{}: ", source), number,
                          name, column_list(*this)));
}

std::optional<std::string> AixacctTable::metadata_text(std::string_view key) const {
  return detail::entry_text(metadata, key);
}

std::optional<double> AixacctTable::metadata_number(std::string_view key) const {
  return detail::entry_number(metadata, key);
}

Table AixacctTable::to_table(std::string source) const {
  Table table;
  table.source = std::move(source);
  for (const auto& column : columns)
    table.add_column(column.header(), column.values);
  return table;
}

const AixacctTable& AixacctFile::measurement(std::size_t number) const {
  for (const auto& table : measurements) {
    if (table.number == number) return table;
  }
  std::string numbers;
  for (const auto& table : measurements)
    numbers += fmt::format("{}{}", numbers.empty() ? "" : ", ", table.number);
  throw Error(fmt::format("{}: no measurement table {} (tables: {})", source, number, numbers));
}

bool looks_like_aixacct(std::string_view text) {
  detail::LineReader lines(text);
  std::string_view line;
  if (!lines.next(line)) return false;
  const auto first = trim(line);
  if (!(first.size() > 6 && first.ends_with("Result") &&
        first.find_first_of(" \t") == std::string_view::npos)) {
    return false;
  }
  while (lines.next(line)) {
    if (trim(line).empty()) continue;
    return table_number(line).has_value();
  }
  return false;
}

AixacctFile parse_aixacct(std::string_view text, std::string_view source_name) {
  check_text_encoding(text, source_name);
  return Parser(text, source_name).run();
}

AixacctFile read_aixacct(const std::filesystem::path& path) {
  return parse_aixacct(read_file(path), path.string());
}

}  // namespace hyst::io
