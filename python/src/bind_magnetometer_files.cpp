// hyst.io's readers of magnetometer files: MicroMag hysteresis loop and FORC files, and MagIC
// tables with their hysteresis loops.

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/io/magic_table.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/io/micromag_loop.hpp"

namespace hyst::python {
namespace {

py::dict header_dict(const std::vector<std::pair<std::string, std::string>>& header) {
  py::dict dict;
  for (const auto& [key, value] : header) {
    if (!dict.contains(key)) dict[py::str(key)] = value;  // the first of a repeated key
  }
  return dict;
}

void bind_micromag_loop(py::module_& io_module) {
  py::class_<io::MicromagLoopFile>(io_module, "MicromagLoopFile",
                                   "A MicroMag hysteresis loop file: header and data columns.")
      .def_readonly("source", &io::MicromagLoopFile::source)
      .def_readonly("format", &io::MicromagLoopFile::format, "the first line")
      .def_readonly("title", &io::MicromagLoopFile::title, "the second line")
      .def_property_readonly(
          "header", [](const io::MicromagLoopFile& f) { return header_dict(f.header); },
          "{key: text} of the header (the first entry of a key used in two sections)")
      .def_readonly("segments", &io::MicromagLoopFile::segments, "rows of the segment table")
      .def_readonly("columns", &io::MicromagLoopFile::columns, "data column names")
      .def_readonly("units", &io::MicromagLoopFile::units,
                    "unit of each column ('T', 'Am²', ...; '' when unknown)")
      .def_readonly("initial_curve_points", &io::MicromagLoopFile::initial_curve_points,
                    "points of the initial (virgin) curve at the start (0 without one)")
      .def_readonly("segment_starts", &io::MicromagLoopFile::segment_starts,
                    "index of the first point of each blank-line separated data block")
      .def_readonly("first_data_line", &io::MicromagLoopFile::first_data_line)
      .def_property_readonly("points", &io::MicromagLoopFile::points)
      .def_property_readonly(
          "field", [](const io::MicromagLoopFile& f) { return readonly_copy(f.field()); },
          "the first column: the measured field (T for 'Hybrid SI')")
      .def_property_readonly(
          "moment", [](const io::MicromagLoopFile& f) { return readonly_copy(f.moment()); },
          "the second column: the measured moment (A m^2 for 'Hybrid SI')")
      .def(
          "column",
          [](const io::MicromagLoopFile& f, std::string_view name) {
            return readonly_copy(f.column(name));
          },
          "name"_a, "The values of the column named e.g. 'Adjusted Moment'.")
      .def("header_number", &io::MicromagLoopFile::header_number, "key"_a,
           "A numeric header entry ('Slope correction'), or None.")
      .def(
          "to_dict",
          [](const io::MicromagLoopFile& f) -> ArrayDict {
            py::dict columns;
            for (std::size_t j = 0; j < f.columns.size(); ++j)
              columns[py::str(f.columns[j])] = readonly_copy(f.values[j]);
            return columns;
          },
          "{column name: float64 array} in file order, like hyst.io.read_csv().")
      .def("__repr__", [](const io::MicromagLoopFile& f) {
        return fmt::format("<MicromagLoopFile '{}': {} points, columns {}>", f.source, f.points(),
                           f.columns.size());
      });
  io_module.def("read_micromag_loop", &io::read_micromag_loop, "path"_a,
                "Reads a MicroMag 2900/3900 hysteresis loop file (.hys, .hyst, .loop, .000); "
                "errors name file, line and column.");
  io_module.def("parse_micromag_loop", &io::parse_micromag_loop, "text"_a,
                "source_name"_a = "<text>", "read_micromag_loop() on a string.");
}

void bind_micromag_forc(py::module_& io_module) {
  using Curve = io::MicromagForcFile::Curve;
  py::class_<Curve>(io_module, "MicromagForcCurve",
                    "One first-order reversal curve with the calibration point measured before it.")
      .def_readonly("calibration_field", &Curve::calibration_field)
      .def_readonly("calibration_moment", &Curve::calibration_moment)
      .def_property_readonly(
          "field", [](const Curve& c) { return readonly_copy(c.field); },
          "field[0] is the reversal field H_r")
      .def_property_readonly("moment", [](const Curve& c) { return readonly_copy(c.moment); })
      .def_property_readonly(
          "more_columns",
          [](const Curve& c) -> ArrayList {
            py::list columns;
            for (const auto& column : c.more_columns)
              columns.append(readonly_copy(column));
            return columns;
          },
          "the columns after field and moment (e.g. 'Normalized Moment'), as measured")
      .def_readonly("first_line", &Curve::first_line, "1-based line of field[0] in the file")
      .def("__len__", [](const Curve& c) { return c.field.size(); })
      .def("__repr__", [](const Curve& c) {
        return fmt::format("<MicromagForcCurve H_r = {}: {} points>", c.field.front(),
                           c.field.size());
      });
  py::class_<io::MicromagForcFile>(
      io_module, "MicromagForcFile",
      "A MicroMag FORC file (Series 0015 or 0016): header, calibration points and curves.")
      .def_readonly("source", &io::MicromagForcFile::source)
      .def_readonly("format", &io::MicromagForcFile::format, "the first line")
      .def_readonly("title", &io::MicromagForcFile::title, "the second line")
      .def_property_readonly(
          "layout",
          [](const io::MicromagForcFile& f) { return std::string(hyst::to_string(f.layout)); },
          "'series_0015' (key = value header, AGM), 'series_0016' (sectioned header, VSM) or "
          "'no_header' (the format and title lines only)")
      .def_property_readonly(
          "header", [](const io::MicromagForcFile& f) { return header_dict(f.header); },
          "{key: text} of the header")
      .def_readonly("columns", &io::MicromagForcFile::columns, "data column names")
      .def_readonly("units", &io::MicromagForcFile::units, "unit of each column")
      .def_readonly("curves", &io::MicromagForcFile::curves, "list of MicromagForcCurve")
      .def_readonly("final_calibration", &io::MicromagForcFile::final_calibration,
                    "(field, moment) of a calibration point after the last curve, or None")
      .def_property_readonly("points", &io::MicromagForcFile::points,
                             "points of all curves (calibration points not counted)")
      .def_property_readonly("calibration_points", &io::MicromagForcFile::calibration_points)
      .def("header_number", &io::MicromagForcFile::header_number, "key"_a,
           "A numeric header entry ('HCal'), or None.")
      .def("__repr__", [](const io::MicromagForcFile& f) {
        return fmt::format("<MicromagForcFile '{}': {} curves, {} points>", f.source,
                           f.curves.size(), f.points());
      });
  io_module.def("read_micromag_forc", &io::read_micromag_forc, "path"_a,
                "Reads a MicroMag 2900/3900 FORC file (Series 0015 AGM or Series 0016 VSM "
                "layout, found from the file); errors name file and line.");
  io_module.def("parse_micromag_forc", &io::parse_micromag_forc, "text"_a,
                "source_name"_a = "<text>", "read_micromag_forc() on a string.");
  io_module.def(
      "correct_drift",
      [](const io::MicromagForcFile& file, std::string_view correction) {
        return io::correct_drift(file, io::forc_drift_correction_from_string(correction));
      },
      "file"_a, "correction"_a = "multiplicative",
      "The file with every moment corrected for the drift of the calibration points: "
      "\"multiplicative\" (sensitivity), \"additive\" (offset) or \"none\".");
}

void bind_magic_table(py::module_& io_module) {
  py::class_<io::MagicHysteresisLoop>(io_module, "MagicHysteresisLoop",
                                      "One hysteresis loop (method code LP-HYS) of a MagIC table.")
      .def_readonly("specimen", &io::MagicHysteresisLoop::specimen)
      .def_readonly("experiment", &io::MagicHysteresisLoop::experiment)
      .def_property_readonly(
          "field", [](const io::MagicHysteresisLoop& l) { return readonly_copy(l.field); },
          "applied field [T], in the order measured")
      .def_property_readonly(
          "moment", [](const io::MagicHysteresisLoop& l) { return readonly_copy(l.moment); })
      .def_readonly("first_line", &io::MagicHysteresisLoop::first_line)
      .def("__repr__", [](const io::MagicHysteresisLoop& l) {
        return fmt::format("<MagicHysteresisLoop '{}': {} points>", l.experiment, l.field.size());
      });
  py::class_<io::MagicTable>(io_module, "MagicTable", "A MagIC table: named text columns.")
      .def_readonly("source", &io::MagicTable::source)
      .def_readonly("name", &io::MagicTable::name, "e.g. 'magic_measurements'")
      .def_readonly("columns", &io::MagicTable::columns)
      .def_readonly("rows", &io::MagicTable::rows, "list of rows, each a list of text cells")
      .def_readonly("row_lines", &io::MagicTable::row_lines, "1-based line of each row")
      .def("__repr__", [](const io::MagicTable& t) {
        return fmt::format("<MagicTable '{}': {} columns, {} rows>", t.name, t.columns.size(),
                           t.rows.size());
      });
  io_module.def("read_magic_table", &io::read_magic_table, "path"_a,
                "Reads a tab-separated MagIC table (PmagPy's text format).");
  io_module.def("parse_magic_table", &io::parse_magic_table, "text"_a, "source_name"_a = "<text>",
                "read_magic_table() on a string.");
  io_module.def("magic_hysteresis_loops", &io::magic_hysteresis_loops, "table"_a,
                "The hysteresis loops (LP-HYS) of a MagIC measurements table, one per "
                "experiment; MagIC 2.5 and 3 column names.");
}

}  // namespace

void bind_magnetometer_files(py::module_& module) {
  auto io_module = module.attr("io").cast<py::module_>();
  bind_micromag_loop(io_module);
  bind_micromag_forc(io_module);
  bind_magic_table(io_module);
}

}  // namespace hyst::python
