// hyst.io: CSV tables as dicts of numpy columns, numeric vectors in MATLAB .mat files, and the
// checks and sets of the outputs (for Python writers of several files, such as hyst.batch).

#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/io/output_paths.hpp"
#include "hyst/io/output_set.hpp"

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
ArrayDict table_to_dict(io::Table&& table) {
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

// io::OutputSet with an explicit end: Python cannot rely on when an object is destroyed, so
// discard() (or leaving a `with` block) removes the staging folder of a set not published.
class PythonOutputSet {
 public:
  PythonOutputSet(const std::filesystem::path& folder, const std::vector<std::string>& names)
      : set_(std::in_place, folder, names) {}

  const io::OutputSet& set() const {
    if (!set_) throw Error("this OutputSet was discarded");
    return *set_;
  }
  void publish() {
    if (!set_) throw Error("this OutputSet was discarded");
    set_->publish();
  }
  void discard() { set_.reset(); }

 private:
  std::optional<io::OutputSet> set_;
};

std::vector<io::NamedPath> named_paths(
    const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::vector<io::NamedPath> paths;
  for (const auto& [path, name] : pairs)
    paths.push_back({path, name});
  return paths;
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
      [](const std::filesystem::path& path, std::string_view variable) -> ArrayList {
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

  io_module.def(
      "check_outputs",
      [](const std::vector<std::pair<std::string, std::string>>& inputs,
         const std::vector<std::pair<std::string, std::string>>& outputs) {
        io::check_outputs(named_paths(inputs), named_paths(outputs));
      },
      "inputs"_a, "outputs"_a,
      "Refuses, before any work, outputs that would replace what they must not, as every hyst "
      "command does: inputs and outputs are (path, name) pairs, the name as messages call it "
      "(\"--data\"). An output that is the same file as an input (also through links and hard "
      "links), two outputs that are one file, an output that is a folder or a socket: hyst.Error "
      "naming both. Inputs that do not exist are skipped.");

  py::class_<PythonOutputSet>(
      io_module, "OutputSet",
      "Several files of one run published as a whole (hyst/io/output_set.hpp, as hyst compare "
      "does): each name in `folder` is a link into the folder of the current set, "
      "`.hyst-current`, switched by one rename in publish(); a run that is killed or fails "
      "leaves the complete previous set. Write every file (or folder of files) under staged(); "
      "leaving a `with` block without publish() removes what was staged.")
      .def(py::init<const std::filesystem::path&, const std::vector<std::string>&>(), "folder"_a,
           "names"_a = std::vector<std::string>{},
           "Creates `folder` (with its parents) and a staging folder in it; `names`, the "
           "published names as far as known, are checked first (hyst.Error for a name that is a "
           "folder or a link not of a set). Set folders of dead runs are removed.")
      .def(
          "staged",
          [](const PythonOutputSet& self, const std::string& name) {
            return self.set().staged(name).string();
          },
          "name"_a = "", "Where to write `name` before publish(); \"\": the staging folder.")
      .def(
          "published",
          [](const PythonOutputSet& self, const std::string& name) {
            return self.set().published(name).string();
          },
          "name"_a, "The path readers use for `name` once published: folder/name.")
      .def("publish", &PythonOutputSet::publish,
           "Makes the staged files the published set, all names at once.")
      .def("discard", &PythonOutputSet::discard,
           "Removes the staging folder unless published; the previous set stays as it was.")
      .def(
          "__enter__", [](PythonOutputSet& self) -> PythonOutputSet& { return self; },
          py::return_value_policy::reference)
      .def("__exit__", [](PythonOutputSet& self, const py::args&) { self.discard(); });
}

}  // namespace hyst::python
