#include "hyst/io/data_file.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/io/micromag_loop.hpp"
#include "text_encoding.hpp"

namespace hyst::io {
bool has_mat_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".mat";
}

std::optional<AixacctFile> read_if_aixacct(const std::filesystem::path& path) {
  if (has_mat_extension(path)) return std::nullopt;
  const std::string text = read_file(path);
  if (!looks_like_aixacct(text)) return std::nullopt;
  return parse_aixacct(text, path.string());
}

DataFile::DataFile(std::filesystem::path path, std::optional<std::size_t> table)
    : path_(std::move(path)), mat_(has_mat_extension(path_)) {
  if (mat_) {
    names_ = list_mat_variables(path_);
  } else {
    const std::string text = read_file(path_);
    check_text_encoding(text, path_.string());
    if (looks_like_aixacct(text)) {
      aixacct_ = parse_aixacct(text, path_.string());
      const auto& tables = aixacct_->measurements;
      if (!table && tables.size() > 1) {
        throw Error(fmt::format(
            "{}: the aixACCT export has {} measurement tables; choose one with --table N "
            "(Python: table=N), or extract one with 'hyst data extract {} --table N --out "
            "t.csv' (see 'hyst data info {}')",
            path_.string(), tables.size(), path_.string(), path_.string()));
      }
      const auto& chosen = table ? aixacct_->measurement(*table) : tables.front();
      aixacct_table_ = static_cast<std::size_t>(&chosen - tables.data());
      table_ = chosen.to_table(path_.string());
    } else if (looks_like_micromag_forc(text)) {
      throw Error(fmt::format(
          "{}: a MicroMag FORC file; its first-order reversal curves, each measured after "
          "saturation, are not one input/output record: identify the Preisach model with 'hyst "
          "fit preisach --forc {}' (Python: hyst.fit_preisach_forcs), and see its curves with "
          "'hyst data info {}'",
          path_.string(), path_.string(), path_.string()));
    } else if (looks_like_micromag_loop(text)) {
      micromag_loop_ = true;
      const auto loop = parse_micromag_loop(text, path_.string());
      table_ = loop.to_table();
      units_ = loop.units;
    } else {
      table_ = parse_csv(text, path_.string());
    }
    names_ = table_.names;
  }
  if (table && !aixacct_) {
    throw Error(fmt::format(
        "{}: --table (Python: table=) chooses a table of an aixACCT export; this file is {}",
        path_.string(), mat_ ? "a MAT file" : (micromag_loop_ ? "a MicroMag loop file" : "CSV")));
  }
}

bool DataFile::has_column(std::string_view name) const {
  if (aixacct_ && aixacct_->measurements[aixacct_table_].find(name)) return true;
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::string DataFile::unit(std::string_view name) const {
  if (!units_.empty()) {
    const auto found = std::find(names_.begin(), names_.end(), name);
    return found == names_.end() ? std::string() : units_[std::size_t(found - names_.begin())];
  }
  if (!aixacct_) return {};
  const auto* column = aixacct_->measurements[aixacct_table_].find(name);
  return column ? column->unit : std::string();
}

std::string DataFile::column_list() const {
  std::string list;
  for (const auto& name : names_)
    list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::vector<double> DataFile::column(std::string_view name) const {
  if (aixacct_) return aixacct_->measurements[aixacct_table_].column(name, path_.string()).values;
  if (!has_column(name) && names_.empty()) {  // e.g. a MAT file cut after its header
    throw Error(fmt::format("{}: no {} '{}' (the file has none)", path_.string(),
                            mat_ ? "variable" : "column", name));
  }
  if (!has_column(name)) {
    throw Error(fmt::format("{}: no {} '{}' ({}: {})", path_.string(), mat_ ? "variable" : "column",
                            name, mat_ ? "variables" : "columns", column_list()));
  }
  if (mat_) return read_mat_vector(path_, name);
  return table_.column(name);
}

std::string DataFile::choose(std::string_view given, std::string_view preferred,
                             std::string_view option) const {
  if (!given.empty()) {
    static_cast<void>(column(given));  // throws when missing
    return std::string(given);
  }
  if (names_.size() == 1) return names_.front();
  if (!preferred.empty() && has_column(preferred)) return std::string(preferred);
  throw Error(fmt::format("{}: {} columns ({}) and none is named '{}'; choose one with {}",
                          path_.string(), names_.size(), column_list(), preferred, option));
}

Table DataFile::columns_table(const std::vector<std::string>& names) const {
  Table table;
  table.source = path_.string();
  for (const auto& name : names.empty() ? names_ : names) {
    auto values = column(name);
    if (!table.columns.empty() && values.size() != table.rows()) {
      throw Error(fmt::format(
          "{}: column '{}' has {} samples but '{}' has {}; extract columns of equal length",
          path_.string(), name, values.size(), table.names.front(), table.rows()));
    }
    table.add_column(name, std::move(values));
  }
  return table;
}

}  // namespace hyst::io
