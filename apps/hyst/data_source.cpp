#include "data_source.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst::cli {
namespace {

bool has_mat_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".mat";
}

}  // namespace

DataSource::DataSource(std::filesystem::path path)
    : path_(std::move(path)), mat_(has_mat_extension(path_)) {
  if (mat_) {
    names_ = io::list_mat_variables(path_);
  } else {
    table_ = io::read_csv(path_);
    names_ = table_.names;
  }
}

bool DataSource::has_column(std::string_view name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::string DataSource::column_list() const {
  std::string list;
  for (const auto& name : names_)
    list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::vector<double> DataSource::column(std::string_view name) const {
  if (!has_column(name) && names_.empty()) {  // e.g. a MAT file cut after its header
    throw Error(fmt::format("{}: no {} '{}' (the file has none)", path_.string(),
                            mat_ ? "variable" : "column", name));
  }
  if (!has_column(name)) {
    throw Error(fmt::format("{}: no {} '{}' ({}: {})", path_.string(), mat_ ? "variable" : "column",
                            name, mat_ ? "variables" : "columns", column_list()));
  }
  if (mat_) return io::read_mat_vector(path_, name);
  return table_.column(name);
}

std::string DataSource::choose(std::string_view given, std::string_view preferred,
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

ColumnPair read_column_pair(const DataSource& source, std::string_view input,
                            std::string_view output, std::string_view what) {
  ColumnPair pair{source.column(input), source.column(output)};
  if (pair.input.size() != pair.output.size()) {
    throw Error(fmt::format("{} '{}': input '{}' has {} samples but output '{}' has {}", what,
                            source.path().string(), input, pair.input.size(), output,
                            pair.output.size()));
  }
  if (pair.input.empty()) {
    throw Error(
        fmt::format("{} '{}': input '{}' has no samples", what, source.path().string(), input));
  }
  return pair;
}

}  // namespace hyst::cli
