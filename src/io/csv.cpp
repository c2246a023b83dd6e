#include "hyst/io/csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "line_reader.hpp"
#include "text_encoding.hpp"

namespace hyst::io {
namespace {

constexpr std::string_view kBlank = " \t";
//! Separators in the order automatic detection prefers them; ' ' stands for runs of blanks.
constexpr std::string_view kDetectionOrder = "\t;, ";

std::string_view trim_blanks(std::string_view text) {
  const auto first = text.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(kBlank);
  return text.substr(first, last - first + 1);
}

//! "data.csv: " or "" for an unnamed source.
std::string prefix(std::string_view source) {
  return source.empty() ? std::string() : fmt::format("{}: ", source);
}

//! A field or name as shown in a message: a long one is cut, so that an error stays one short
//! line even for a megabyte-long field.
std::string excerpt(std::string_view text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown + 20) return std::string(text);
  return fmt::format("{}... ({} characters)", text.substr(0, kShown), text.size());
}

//! "data.csv:7: " or "line 7: " for an unnamed source.
std::string prefix(std::string_view source, std::size_t line) {
  return source.empty() ? fmt::format("line {}: ", line) : fmt::format("{}:{}: ", source, line);
}

std::string describe_separator(char separator) {
  if (separator == '\t') return "tab";
  if (separator == ' ') return "space";
  if (static_cast<unsigned char>(separator) < 0x20 || separator == 0x7f) {
    return fmt::format("character {:#04x}", static_cast<unsigned char>(separator));
  }
  return fmt::format("'{}'", separator);
}

//! Splits a line into trimmed fields. separator ' ' means runs of blanks.
void split(std::string_view line, char separator, std::vector<std::string_view>& fields) {
  fields.clear();
  if (separator == ' ') {
    std::string_view rest = trim_blanks(line);
    while (!rest.empty()) {
      const auto end = std::min(rest.find_first_of(kBlank), rest.size());
      fields.push_back(rest.substr(0, end));
      rest = trim_blanks(rest.substr(end));
    }
    return;
  }
  std::size_t start = 0;
  while (true) {
    const auto end = line.find(separator, start);
    if (end == std::string_view::npos) {
      fields.push_back(trim_blanks(line.substr(start)));
      return;
    }
    fields.push_back(trim_blanks(line.substr(start, end - start)));
    start = end + 1;
  }
}

char detect_separator(std::string_view header) {
  // Characters inside a quoted name ("a;b") separate nothing. A quote opens a quoted name only
  // at the start of a name (after a possible separator and blanks), as header_names() reads it;
  // one inside a name (a"b) is a character of the name.
  const auto may_separate = [](char c) {
    return kDetectionOrder.find(c) != std::string_view::npos;
  };
  std::string outside;
  bool quoted = false;
  bool name_start = true;
  for (std::size_t k = 0; k < header.size(); ++k) {
    const char c = header[k];
    if (quoted) {
      if (c == '"' && k + 1 < header.size() && header[k + 1] == '"') {
        ++k;  // "" stands for one quote
      } else if (c == '"') {
        quoted = false;
      }
      continue;
    }
    if (c == '"' && name_start) {
      quoted = true;
      name_start = false;
      continue;
    }
    outside.push_back(c);
    name_start = may_separate(c) || (name_start && (c == ' ' || c == '\t'));
  }
  for (const char candidate : kDetectionOrder) {
    if (candidate == ' ' || outside.find(candidate) != std::string::npos) return candidate;
  }
  return ' ';
}

//! The column names of a header line, split like the rows (split()), except that a name in
//! double quotes (RFC 4180) is the text between them, with "" standing for one quote; it may hold
//! the separator and blanks. Throws for a quote left open or text after a closing quote.
std::vector<std::string> header_names(std::string_view line, char separator,
                                      const std::string& where) {
  // Blanks around a name; a tab that separates is not one of them.
  const auto blank = [separator](char c) {
    return (c == ' ' || c == '\t') && (separator == ' ' || c != separator);
  };
  std::vector<std::string> names;
  std::size_t k = 0;
  const auto skip_blanks = [&] {
    while (k < line.size() && blank(line[k]))
      ++k;
  };
  skip_blanks();
  while (true) {
    std::string name;
    const std::size_t column = names.size() + 1;
    if (k < line.size() && line[k] == '"') {
      for (++k;; ++k) {
        if (k >= line.size()) {
          throw Error(fmt::format("{}column {} of the header: the quoted name has no closing quote",
                                  where, column));
        }
        if (line[k] == '"') {
          if (k + 1 < line.size() && line[k + 1] == '"') {
            name.push_back('"');
            ++k;
            continue;
          }
          ++k;
          break;
        }
        name.push_back(line[k]);
      }
      const std::size_t closed = k;
      skip_blanks();
      const bool next = k < line.size();
      if (next && (separator == ' ' ? k == closed : line[k] != separator)) {
        throw Error(
            fmt::format("{}column {} of the header: text after the closing quote of the name '{}'",
                        where, column, excerpt(name)));
      }
    } else {
      const std::size_t start = k;
      while (k < line.size() && (separator == ' ' ? !blank(line[k]) : line[k] != separator))
        ++k;
      name = std::string(trim_blanks(line.substr(start, k - start)));
      skip_blanks();
    }
    names.push_back(std::move(name));
    if (k >= line.size()) return names;
    if (separator != ' ') {
      ++k;  // the separator
      skip_blanks();
      if (k >= line.size()) {  // a trailing separator: an empty last name, as split() gives
        names.emplace_back();
        return names;
      }
    }
  }
}

//! Parses one field as a finite double; throws naming file, line and column.
double parse_number(std::string_view field, std::string_view source, std::size_t line,
                    std::size_t column, std::string_view name) {
  const auto where = [&] {
    return fmt::format("{}column {} ('{}')", prefix(source, line), column + 1, excerpt(name));
  };
  if (field.empty()) throw Error(fmt::format("{}: empty field, expected a number", where()));
  // from_chars does not accept a leading '+'; accept one, but not "+-1".
  std::string_view digits = field;
  if (digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  std::from_chars_result result{digits.data(), std::errc::invalid_argument};
  if (!digits.empty() && !(digits.size() < field.size() && digits.front() == '-')) {
    result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  }
  if (result.ec == std::errc::result_out_of_range) {
    throw Error(fmt::format("{}: '{}' is out of range for a double", where(), excerpt(field)));
  }
  if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    const bool decimal_comma = field.find(',') != std::string_view::npos;
    throw Error(fmt::format("{}: '{}' is not a number{}", where(), excerpt(field),
                            decimal_comma ? " (decimal commas are not supported; use '.')" : ""));
  }
  if (!std::isfinite(value)) {
    throw Error(fmt::format("{}: {} is not finite", where(), excerpt(field)));
  }
  return value;
}

//! Rules for a column name that hold for every table: returns an error text or "".
std::string name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (trim_blanks(name).size() != name.size()) return "has leading or trailing spaces";
  if (name.find_first_of("\r\n") != std::string_view::npos) return "contains a line break";
  // Written first in a file, it would be read as the file's byte order mark and dropped.
  if (name.starts_with(detail::kByteOrderMark)) return "starts with a byte order mark (U+FEFF)";
  // Written first, they would make the file read as UTF-16 (text_encoding.hpp); neither byte
  // occurs in UTF-8.
  if (name.starts_with("\xFE\xFF") || name.starts_with("\xFF\xFE")) {
    return "starts with the bytes of a UTF-16 byte order mark (FE FF or FF FE)";
  }
  return {};
}

std::string format_table(const Table& table, const CsvWriteOptions& options,
                         const std::string& where) {
  const char separator = options.separator;
  const auto position = kDetectionOrder.find(separator);
  if (separator == 0 || position == std::string_view::npos) {
    throw Error(fmt::format("{}csv separator {} must be ',', ';', tab or space", where,
                            describe_separator(separator)));
  }
  if (options.significant_digits < 1 || options.significant_digits > 17) {
    throw Error(fmt::format("{}csv significant_digits = {} must be in [1, 17]", where,
                            options.significant_digits));
  }
  if (table.names.size() != table.columns.size()) {
    throw Error(fmt::format("{}table has {} names but {} columns", where, table.names.size(),
                            table.columns.size()));
  }
  if (table.names.empty()) throw Error(fmt::format("{}table has no columns", where));

  // Names containing the separator, or one that detection prefers to it, would split differently.
  // A single name has no separator beside it in the header line, so detection would take any
  // separator character in it.
  const std::string_view forbidden =
      table.names.size() == 1 ? kDetectionOrder : kDetectionOrder.substr(0, position + 1);
  for (std::size_t j = 0; j < table.names.size(); ++j) {
    const std::string& name = table.names[j];
    if (const std::string problem = name_problem(name); !problem.empty()) {
      throw Error(fmt::format("{}column {} name '{}' {}", where, j + 1, name, problem));
    }
    if (const auto at = name.find_first_of(forbidden); at != std::string::npos) {
      throw Error(fmt::format(
          "{}column {} name '{}' contains {}, which read_csv would take for a separator", where,
          j + 1, name, describe_separator(name[at])));
    }
    if (j == 0 && name.front() == '#') {
      throw Error(fmt::format(
          "{}column 1 name '{}' starts with '#', which read_csv would take for a comment line",
          where, name));
    }
    for (std::size_t i = 0; i < j; ++i) {
      if (table.names[i] == name) {
        throw Error(fmt::format("{}column {} ('{}') has the same name as column {}", where, j + 1,
                                name, i + 1));
      }
    }
  }
  const std::size_t rows = table.columns.front().size();
  for (std::size_t j = 1; j < table.columns.size(); ++j) {
    if (table.columns[j].size() != rows) {
      throw Error(fmt::format("{}column {} ('{}') has {} values but column 1 ('{}') has {}", where,
                              j + 1, table.names[j], table.columns[j].size(), table.names[0],
                              rows));
    }
  }
  if (rows == 0) {
    throw Error(
        fmt::format("{}table has no rows (a file without data rows cannot be read back)", where));
  }

  std::string out;
  auto sink = std::back_inserter(out);
  for (std::size_t j = 0; j < table.names.size(); ++j) {
    if (j > 0) out.push_back(separator);
    const std::string& name = table.names[j];
    if (name.find('"') == std::string::npos) {
      out += name;
      continue;
    }
    // A name with a quote in it (RFC 4180): quoted, each quote doubled, so that neither the
    // separator detection nor the header reader takes the quote for the start of a quoted name.
    out.push_back('"');
    for (const char c : name) {
      if (c == '"') out.push_back('"');
      out.push_back(c);
    }
    out.push_back('"');
  }
  out.push_back('\n');
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t j = 0; j < table.columns.size(); ++j) {
      const double value = table.columns[j][r];
      if (!std::isfinite(value)) {
        throw Error(fmt::format("{}column {} ('{}'), row {}: {} is not finite", where, j + 1,
                                table.names[j], r + 1, value));
      }
      if (j > 0) out.push_back(separator);
      fmt::format_to(sink, "{:.{}g}", value, options.significant_digits);
    }
    out.push_back('\n');
  }
  return out;
}

}  // namespace

bool Table::has_column(std::string_view name) const {
  return std::find(names.begin(), names.end(), name) != names.end();
}

const std::vector<double>& Table::column(std::string_view name) const {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end() || static_cast<std::size_t>(found - names.begin()) >= columns.size()) {
    throw Error(fmt::format(
        "{}no column '{}' (columns: {})", prefix(source), name,
        names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))));
  }
  return columns[static_cast<std::size_t>(found - names.begin())];
}

void Table::add_column(std::string name, std::vector<double> values) {
  if (const std::string problem = name_problem(name); !problem.empty()) {
    throw Error(fmt::format("{}column name '{}' {}", prefix(source), name, problem));
  }
  if (has_column(name)) {
    throw Error(fmt::format("{}column '{}' already exists", prefix(source), name));
  }
  if (!columns.empty() && values.size() != rows()) {
    throw Error(fmt::format("{}column '{}' has {} values but the table has {} rows", prefix(source),
                            name, values.size(), rows()));
  }
  names.push_back(std::move(name));
  columns.push_back(std::move(values));
}

Table parse_csv(std::string_view text, std::string_view source_name,
                const CsvReadOptions& options) {
  check_text_encoding(text, source_name);
  const std::string_view source = source_name;
  detail::LineReader reader(text);
  std::string_view line;
  std::vector<std::string_view> fields;

  const auto skipped = [&](std::string_view trimmed) {
    return trimmed.empty() || (options.comment != 0 && trimmed.front() == options.comment);
  };

  // Header: the first line that is neither blank nor a comment.
  bool any_text = false;
  bool found_header = false;
  while (!found_header && reader.next(line)) {
    any_text = any_text || !trim_blanks(line).empty();
    found_header = !skipped(trim_blanks(line));
  }
  if (!found_header) {
    throw Error(fmt::format("{}file is empty{}", prefix(source),
                            any_text ? " (it has only blank and comment lines)" : ""));
  }
  const char separator =
      options.separator != 0 ? options.separator : detect_separator(trim_blanks(line));
  const std::size_t header_line = reader.number();

  Table table;
  table.source = std::string(source);
  const std::vector<std::string> names = header_names(line, separator, prefix(source, header_line));
  std::unordered_map<std::string_view, std::size_t> column_of_name;
  for (std::size_t j = 0; j < names.size(); ++j) {
    const std::string_view name = names[j];
    if (name.empty()) {
      throw Error(fmt::format("{}column {} of the header has an empty name",
                              prefix(source, header_line), j + 1));
    }
    if (const std::string problem = name_problem(name); !problem.empty()) {
      throw Error(fmt::format("{}column {} of the header: the name {}", prefix(source, header_line),
                              j + 1, problem));
    }
    // A map, not a pairwise comparison: a header may have a million columns.
    if (const auto [first, inserted] = column_of_name.emplace(name, j); !inserted) {
      throw Error(fmt::format("{}column {} ('{}') has the same name as column {}",
                              prefix(source, header_line), j + 1, excerpt(name),
                              first->second + 1));
    }
    table.names.emplace_back(name);
  }
  table.columns.resize(table.names.size());

  while (reader.next(line)) {
    if (skipped(trim_blanks(line))) continue;
    split(line, separator, fields);
    if (fields.size() != table.names.size()) {
      throw Error(fmt::format("{}row has {} fields but the header has {}",
                              prefix(source, reader.number()), fields.size(), table.names.size()));
    }
    for (std::size_t j = 0; j < fields.size(); ++j) {
      table.columns[j].push_back(
          parse_number(fields[j], source, reader.number(), j, table.names[j]));
    }
  }
  if (table.rows() == 0) {
    throw Error(fmt::format("{}no data rows after the header", prefix(source)));
  }
  return table;
}

Table read_csv(const std::filesystem::path& path, const CsvReadOptions& options) {
  return parse_csv(read_file(path), path.string(), options);
}

std::string format_csv(const Table& table, const CsvWriteOptions& options) {
  return format_table(table, options, prefix(table.source));
}

void write_csv(const std::filesystem::path& path, const Table& table,
               const CsvWriteOptions& options) {
  const std::string text =
      format_table(table, options, fmt::format("cannot write '{}': ", path.string()));
  write_file_atomically(path, text);
}

}  // namespace hyst::io
