// hyst.io: CSV tables as dicts of numpy columns, and numeric vectors in MATLAB .mat files.

#include <optional>
#include <utility>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst::python {
namespace {

// A one-character option given as a Python string; None or "" means 0 (automatic / none).
char single_character(const std::optional<std::string>& text, std::string_view name) {
  if (!text || text->empty()) return 0;
  if (text->size() != 1) {
    throw Error(fmt::format("{} '{}' must be a single character", name, *text));
  }
  return (*text)[0];
}

// Columns of a table moved into numpy arrays, in file order.
py::dict table_to_dict(io::Table&& table) {
  py::dict columns;
  for (std::size_t j = 0; j < table.cols(); ++j)
    columns[py::str(table.names[j])] = to_array(std::move(table.columns[j]));
  return columns;
}

// Any mapping of name -> 1-D sequence of numbers.
io::Table dict_to_table(const py::handle& columns) {
  io::Table table;
  for (const auto& item : columns.attr("items")()) {
    const auto pair = item.cast<py::tuple>();
    const auto name = pair[0].cast<std::string>();
    const auto values = pair[1].cast<InputArray>();
    table.add_column(name, as_vector(values, fmt::format("column '{}'", name)));
  }
  return table;
}

std::vector<std::pair<std::string, std::vector<double>>> mat_variables(
    const py::handle& variables) {
  // A mapping (name -> values) or a sequence of (name, values) pairs.
  py::object items = py::hasattr(variables, "items")
                         ? variables.attr("items")()
                         : py::reinterpret_borrow<py::object>(variables);
  std::vector<std::pair<std::string, std::vector<double>>> result;
  for (const auto& item : items) {
    const auto pair = item.cast<py::tuple>();
    if (pair.size() != 2) throw Error("write_mat_vectors: expected (name, values) pairs");
    const auto name = pair[0].cast<std::string>();
    result.emplace_back(name,
                        as_vector(pair[1].cast<InputArray>(), fmt::format("variable '{}'", name)));
  }
  return result;
}

}  // namespace

void bind_io(py::module_& module) {
  auto io_module = module.def_submodule(
      "io",
      "Files: CSV tables (dict of column name -> float64 array, in file order) and numeric "
      "vectors in MATLAB .mat files (v4/v5/v7.3 read, v5/v7.3 written). Errors raise hyst.Error "
      "naming the file, line and column or variable. Writes replace files atomically.");
  py::module_::import("sys").attr("modules")["hyst.io"] = io_module;

  io_module.def(
      "read_csv",
      [](const std::filesystem::path& path, std::optional<std::string> separator,
         std::optional<std::string> comment) {
        io::CsvReadOptions options;
        options.separator = single_character(separator, "separator");
        options.comment = single_character(comment, "comment");
        return table_to_dict(io::read_csv(path, options));
      },
      "path"_a, "separator"_a = py::none(), "comment"_a = "#",
      "Reads a delimited text file: {column name: float64 array}. separator None = detect "
      "(tab, ';', ',' or spaces); comment None = no comment lines.");
  io_module.def(
      "parse_csv",
      [](std::string_view text, std::string_view source_name, std::optional<std::string> separator,
         std::optional<std::string> comment) {
        io::CsvReadOptions options;
        options.separator = single_character(separator, "separator");
        options.comment = single_character(comment, "comment");
        return table_to_dict(io::parse_csv(text, source_name, options));
      },
      "text"_a, "source_name"_a = "<text>", "separator"_a = py::none(), "comment"_a = "#",
      "read_csv() on a string; `source_name` prefixes error messages.");
  io_module.def(
      "write_csv",
      [](const std::filesystem::path& path, const py::object& columns, const std::string& separator,
         int significant_digits) {
        io::CsvWriteOptions options;
        options.separator = single_character(separator, "separator");
        options.significant_digits = significant_digits;
        io::write_csv(path, dict_to_table(columns), options);
      },
      "path"_a, "columns"_a, "separator"_a = ",", "significant_digits"_a = 17,
      "Writes a mapping {name: 1-D values} (equal lengths) as a CSV file, atomically; 17 "
      "significant digits give back every double exactly.");
  io_module.def(
      "format_csv",
      [](const py::object& columns, const std::string& separator, int significant_digits) {
        io::CsvWriteOptions options;
        options.separator = single_character(separator, "separator");
        options.significant_digits = significant_digits;
        return io::format_csv(dict_to_table(columns), options);
      },
      "columns"_a, "separator"_a = ",", "significant_digits"_a = 17,
      "The text write_csv() would write.");

  io_module.def("list_mat_variables", &io::list_mat_variables, "path"_a,
                "Names of the variables in a MAT file, in file order.");
  io_module.def(
      "read_mat_vector",
      [](const std::filesystem::path& path, std::string_view variable) {
        return to_array(io::read_mat_vector(path, variable));
      },
      "path"_a, "variable"_a, "A 1 x N or N x 1 real numeric variable as a float64 array.");
  io_module.def(
      "read_mat_columns",
      [](const std::filesystem::path& path, std::string_view variable) {
        py::list columns;
        for (auto& column : io::read_mat_columns(path, variable))
          columns.append(to_array(std::move(column)));
        return columns;
      },
      "path"_a, "variable"_a,
      "The columns of a 2-d real numeric variable (e.g. one measured loop per column), as a list "
      "of float64 arrays.");
  io_module.def(
      "write_mat_vectors",
      [](const std::filesystem::path& path, const py::object& variables, std::string_view version) {
        io::write_mat_vectors(path, mat_variables(variables), io::mat_version_from_string(version));
      },
      "path"_a, "variables"_a, "version"_a = "v5",
      "Writes {name: 1-D values} (or (name, values) pairs) as N x 1 double variables; version "
      "\"v5\" or \"v7.3\".");
}

}  // namespace hyst::python
