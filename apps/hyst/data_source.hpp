#pragma once
// Named columns of a data file for the command line: a CSV table (hyst/io/csv.hpp) or the vector
// variables of a MATLAB .mat file (hyst/io/mat_file.hpp), chosen by the file's extension (".mat",
// any case, is a MAT file; everything else is read as CSV).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/io/csv.hpp"

namespace hyst::cli {

class DataSource {
 public:
  //! Reads a CSV file completely, or lists the variables of a MAT file; throws hyst::Error naming
  //! the file (and line and column for CSV syntax errors).
  explicit DataSource(std::filesystem::path path);

  const std::filesystem::path& path() const { return path_; }
  bool is_mat() const { return mat_; }
  //! Column (variable) names in file order.
  const std::vector<std::string>& columns() const { return names_; }
  bool has_column(std::string_view name) const;

  //! The values of one column; throws hyst::Error "d.csv: no column 'x' (columns: t, v, y)", or
  //! for MAT files the reader's message naming the variable (not a vector, not finite, ...).
  std::vector<double> column(std::string_view name) const;

  //! The column to use for an option: `given` when not empty (it must exist); otherwise the only
  //! column of the file, or `preferred` when the file has a column of that name. Throws
  //! hyst::Error listing the columns and naming `option` when neither applies.
  std::string choose(std::string_view given, std::string_view preferred,
                     std::string_view option) const;

  //! "t, v, y".
  std::string column_list() const;

 private:
  std::filesystem::path path_;
  bool mat_ = false;
  io::Table table_;  //!< CSV only
  std::vector<std::string> names_;
};

//! Two columns of one file, checked to have the same length; `what` ("data", "validation data")
//! starts the message: "validation data 'v.mat': input 'a' has 401 samples but output 'b' has 300".
struct ColumnPair {
  std::vector<double> input;
  std::vector<double> output;
};
ColumnPair read_column_pair(const DataSource& source, std::string_view input,
                            std::string_view output, std::string_view what);

}  // namespace hyst::cli
