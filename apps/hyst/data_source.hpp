#pragma once
// Columns of a data file for the commands: hyst::io::DataFile, and a checked input/output pair.

#include <string_view>
#include <vector>

#include "hyst/io/data_file.hpp"

namespace hyst::cli {

using DataSource = io::DataFile;
using io::read_if_aixacct;

//! Two columns of one file, checked to have the same length; `what` ("data", "validation data")
//! starts the message: "validation data 'v.mat': input 'a' has 401 samples but output 'b' has 300".
struct ColumnPair {
  std::vector<double> input;
  std::vector<double> output;
};
ColumnPair read_column_pair(const DataSource& source, std::string_view input,
                            std::string_view output, std::string_view what);

}  // namespace hyst::cli
