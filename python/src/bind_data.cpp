// hyst.data: measured records as users have them - reversal points, branches, cycles, loop
// figures, offset and drift removal, resampling, preparation for fitting; and hyst.io's reader
// of aixACCT exports.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "hyst/data/backbone.hpp"
#include "hyst/data/branches.hpp"
#include "hyst/data/corrections.hpp"
#include "hyst/data/cycles.hpp"
#include "hyst/data/leakage.hpp"
#include "hyst/data/loop_metrics.hpp"
#include "hyst/data/preprocessing.hpp"
#include "hyst/data/record_info.hpp"
#include "hyst/data/resampling.hpp"
#include "hyst/data/reversal_points.hpp"
#include "hyst/data/sample_time.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/data_file.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::python {
namespace {

py::dict pairs_to_dict(const std::vector<std::pair<std::string, std::string>>& pairs) {
  py::dict dict;
  for (const auto& [key, value] : pairs)
    dict[py::str(key)] = value;
  return dict;
}

ArrayPair record_tuple(data::ResampledRecord&& record) {
  return py::make_tuple(to_array(std::move(record.input)), to_array(std::move(record.output)));
}

void bind_aixacct(py::module_& io_module) {
  py::class_<io::AixacctColumn>(io_module, "AixacctColumn",
                                "One column of an aixACCT table: name, unit and values.")
      .def_readonly("name", &io::AixacctColumn::name, "e.g. 'V+'")
      .def_readonly("unit", &io::AixacctColumn::unit, "e.g. 'V'; '' without a unit")
      .def_property_readonly("header", &io::AixacctColumn::header, "'V+ [V]' as in the file")
      .def_property_readonly(
          "values", [](const io::AixacctColumn& c) { return readonly_copy(c.values); },
          "float64 array (read-only copy)")
      .def("__repr__", [](const io::AixacctColumn& c) {
        return fmt::format("<AixacctColumn '{}', {} values>", c.header(), c.values.size());
      });

  py::class_<io::AixacctTable>(io_module, "AixacctTable",
                               "A table of an aixACCT export: metadata and named columns.")
      .def_readonly("number", &io::AixacctTable::number, "N of its 'Table N' line")
      .def_readonly("first_line", &io::AixacctTable::first_line, "1-based line of 'Table N'")
      .def_property_readonly(
          "metadata", [](const io::AixacctTable& t) { return pairs_to_dict(t.metadata); },
          "{key: text} of the 'key: value' lines, in file order")
      .def_readonly("columns", &io::AixacctTable::columns)
      .def_property_readonly("rows", &io::AixacctTable::rows)
      .def(
          "column",
          [](const io::AixacctTable& t, std::string_view name) {
            return readonly_copy(t.column(name).values);
          },
          "name"_a, "The values of the column named 'V+' or headed 'V+ [V]'.")
      .def("metadata_number", &io::AixacctTable::metadata_number, "key"_a,
           "A numeric metadata entry, or None.")
      .def(
          "to_dict",
          [](const io::AixacctTable& t) -> ArrayDict {
            py::dict columns;
            for (const auto& column : t.columns)
              columns[py::str(column.header())] = readonly_copy(column.values);
            return columns;
          },
          "{header: float64 array} in file order, like hyst.io.read_csv() (hyst.io.write_csv() "
          "writes it as CSV).")
      .def("__repr__", [](const io::AixacctTable& t) {
        return fmt::format("<AixacctTable {}: {} columns, {} rows>", t.number, t.columns.size(),
                           t.rows());
      });

  py::class_<io::AixacctFile>(io_module, "AixacctFile",
                              "An aixACCT aixPlorer export: summary and measurement tables.")
      .def_readonly("source", &io::AixacctFile::source)
      .def_readonly("kind", &io::AixacctFile::kind, "the first line, e.g. 'PiezoResult'")
      .def_readonly("titles", &io::AixacctFile::titles)
      .def_property_readonly(
          "header", [](const io::AixacctFile& f) { return pairs_to_dict(f.header); },
          "{key: text} of the file header")
      .def_readonly("summary", &io::AixacctFile::summary, "the summary table or None")
      .def_readonly("measurements", &io::AixacctFile::measurements)
      .def("measurement", &io::AixacctFile::measurement, "number"_a,
           py::return_value_policy::reference_internal,
           "The measurement table numbered `number` (as in the file).");

  io_module.def("read_aixacct", &io::read_aixacct, "path"_a,
                "Reads an aixACCT aixPlorer text export (errors name file, line, table, column).");
  io_module.def("parse_aixacct", &io::parse_aixacct, "text"_a, "source_name"_a = "<text>",
                "read_aixacct() on a string.");
}

void bind_loops(py::module_& d) {
  py::class_<data::LevelCrossing>(d, "LevelCrossing",
                                  "Where a quantity crosses a level: the other quantity there.")
      .def_readonly("value", &data::LevelCrossing::value)
      .def_readonly("index", &data::LevelCrossing::index, "between samples index and index+1")
      .def_readonly("direction", &data::LevelCrossing::direction)
      .def("__repr__", [](const data::LevelCrossing& c) {
        return fmt::format("<LevelCrossing {} at {} ({})>", c.value, c.index,
                           to_string(c.direction));
      });
  py::class_<data::LoopMetrics>(d, "LoopMetrics", "Figures of one loop (cycle) of a record.")
      .def_readonly("first", &data::LoopMetrics::first)
      .def_readonly("last", &data::LoopMetrics::last)
      .def_readonly("area", &data::LoopMetrics::area, "contour integral of input d(output)")
      .def_readonly("closure_error", &data::LoopMetrics::closure_error)
      .def_readonly("input_mismatch", &data::LoopMetrics::input_mismatch)
      .def_readonly("input_min", &data::LoopMetrics::input_min)
      .def_readonly("input_max", &data::LoopMetrics::input_max)
      .def_readonly("output_min", &data::LoopMetrics::output_min)
      .def_readonly("output_max", &data::LoopMetrics::output_max)
      .def_readonly("coercive", &data::LoopMetrics::coercive)
      .def_readonly("remanent", &data::LoopMetrics::remanent);

  d.def(
      "loop_area",
      [](const InputArray& input, const InputArray& output) {
        return data::loop_area(as_span(input, "input"), as_span(output, "output"));
      },
      "input"_a, "output"_a, "Signed polygon area (counter-clockwise positive).");
  d.def(
      "coercive_inputs",
      [](const InputArray& input, const InputArray& output, double level) {
        return data::coercive_inputs(as_span(input, "input"), as_span(output, "output"), level);
      },
      "input"_a, "output"_a, "output_level"_a = 0.0,
      "Inputs where the output crosses output_level.");
  d.def(
      "remanent_outputs",
      [](const InputArray& input, const InputArray& output, double level) {
        return data::remanent_outputs(as_span(input, "input"), as_span(output, "output"), level);
      },
      "input"_a, "output"_a, "input_level"_a = 0.0, "Outputs where the input crosses input_level.");
  d.def(
      "loop_metrics",
      [](const InputArray& input, const InputArray& output, std::size_t first, std::size_t last,
         double input_level, double output_level) {
        return data::loop_metrics(as_span(input, "input"), as_span(output, "output"), first, last,
                                  input_level, output_level);
      },
      "input"_a, "output"_a, "first"_a, "last"_a, "input_level"_a = 0.0, "output_level"_a = 0.0,
      "LoopMetrics of samples first..last (inclusive).");
  d.def(
      "cycle_metrics",
      [](const InputArray& input, const InputArray& output, double band, double input_level,
         double output_level) {
        return data::cycle_metrics(as_span(input, "input"), as_span(output, "output"), band,
                                   input_level, output_level);
      },
      "input"_a, "output"_a, "band"_a, "input_level"_a = 0.0, "output_level"_a = 0.0,
      "LoopMetrics of every cycle.");
}

void bind_corrections(py::module_& d) {
  py::class_<data::DriftRemoval>(d, "DriftRemoval", "Result of remove_drift().")
      .def_property_readonly("output",
                             [](const data::DriftRemoval& r) { return readonly_copy(r.output); })
      .def_property_readonly("drift",
                             [](const data::DriftRemoval& r) { return readonly_copy(r.drift); })
      .def_readonly("cycles", &data::DriftRemoval::cycles)
      .def_readonly("closure_error", &data::DriftRemoval::closure_error);
  d.def(
      "remove_offset",
      [](const InputArray& values, std::string_view reference)
          -> Typed<py::tuple, "Tuple[numpy.ndarray[numpy.float64], float]"> {
        auto removal = data::remove_offset(as_span(values, "values"),
                                           data::offset_reference_from_string(reference));
        return py::make_tuple(to_array(std::move(removal.values)), removal.offset);
      },
      "values"_a, "reference"_a = "mean",
      "(values - offset, offset); reference 'mean', 'first' or 'midrange'.");
  d.def("leakage_conductance", &data::leakage_conductance, "resistance"_a, "area_mm2"_a,
        "g = 1 / (R A) in uC/cm^2 per V s for R [Ohm] and an electrode area A [mm^2] (e.g. an "
        "aixACCT summary's Rav and a table's Area [mm2]).");
  d.def(
      "sample_time",
      [](const InputArray& times) {
        return data::uniform_sample_time(as_span(times, "times"), "times");
      },
      "times"_a,
      "The uniform step [s] of a time column: increasing, finite, every step within 0.1 % of "
      "the median (plus the rounding of 7 printed digits); hyst.Error names the first step "
      "that is not.");
  d.def(
      "leakage_charge",
      [](const InputArray& voltage, double sample_time) {
        return to_array(data::leakage_charge(as_span(voltage, "voltage"), sample_time));
      },
      "voltage"_a, "sample_time"_a,
      "Q[k] = integral of the voltage from sample 0 to k [V s], trapezoidal, Q[0] = 0.");
  d.def(
      "remove_leakage_charge",
      [](const InputArray& voltage, const InputArray& polarisation, double sample_time,
         double conductance) {
        return to_array(data::remove_leakage_charge(as_span(voltage, "voltage"),
                                                    as_span(polarisation, "polarisation"),
                                                    sample_time, conductance));
      },
      "voltage"_a, "polarisation"_a, "sample_time"_a, "conductance"_a,
      "P - g Q: a measured polarisation without the charge of a leakage conductance g.");
  d.def(
      "remove_drift",
      [](const InputArray& input, const InputArray& output, double band) {
        return data::remove_drift(as_span(input, "input"), as_span(output, "output"), band);
      },
      "input"_a, "output"_a, "band"_a,
      "Removes linear drift between cycles so that every cycle closes.");
  d.def(
      "resample_on_input_grid",
      [](const InputArray& input, const InputArray& output, double band, double step) {
        return record_tuple(data::resample_on_input_grid(as_span(input, "input"),
                                                         as_span(output, "output"), band, step));
      },
      "input"_a, "output"_a, "band"_a, "input_step"_a,
      "(input, output) resampled per branch on a uniform input grid.");
  d.def(
      "resample_by_arc_length",
      [](const InputArray& input, const InputArray& output, double band, double step) {
        return record_tuple(data::resample_by_arc_length(as_span(input, "input"),
                                                         as_span(output, "output"), band, step));
      },
      "input"_a, "output"_a, "band"_a, "step"_a,
      "(input, output) resampled per branch at uniform normalised arc length.");
  d.def(
      "preprocess",
      [](const InputArray& input, const InputArray& output, double band, bool detrend,
         std::optional<std::string> cycles, std::string_view resample, double resample_step)
          -> Typed<py::tuple,
                   "Tuple[numpy.ndarray[numpy.float64], numpy.ndarray[numpy.float64], "
                   "List[str]]"> {
        data::Preprocessing options;
        options.band = band;
        options.detrend = detrend;
        if (cycles) options.cycles = data::cycle_range_from_string(*cycles);
        options.resample = data::resample_method_from_string(resample);
        options.resample_step = resample_step;
        auto prepared =
            data::preprocess(as_span(input, "input"), as_span(output, "output"), options);
        return py::make_tuple(to_array(std::move(prepared.input)),
                              to_array(std::move(prepared.output)), prepared.steps);
      },
      "input"_a, "output"_a, "band"_a = 0.0, "detrend"_a = false, "cycles"_a = py::none(),
      "resample"_a = "none", "resample_step"_a = 0.0,
      "(input, output, steps): drift removed, cycles ('2', '2-4', '2-', 'all') kept, resampled "
      "('input-grid', 'arc-length'); band 0 = 2 % of the input range.");
}

//! hyst.data.info and hyst.data.extract: 'hyst data info --json' and 'hyst data extract'.
void bind_files(py::module_& d) {
  d.def(
      "info",
      [](const std::filesystem::path& path, std::optional<std::size_t> table, double band_fraction,
         std::optional<std::pair<std::string, std::string>> loop,
         const std::string& time) -> StrDict {
        data::RecordInfoOptions options;
        options.table = table;
        options.band_fraction = band_fraction;
        options.loop = std::move(loop);
        options.time = time;
        return py::dict(json_to_python(data::record_info_json(data::record_info(path, options))));
      },
      "path"_a, "table"_a = py::none(), "band_fraction"_a = 0.02, "loop"_a = py::none(),
      "time"_a = "",
      "What a data file (CSV, .mat, aixACCT export, MicroMag loop file) holds, as a dict with the "
      "content of 'hyst "
      "data info --json': its tables, each column's unit, samples, min, max and the counts of "
      "reversals and cycles with a band of band_fraction x its range; loop=(input, output) adds "
      "the figures of every cycle of that loop. table chooses one measurement table of an "
      "aixACCT export. time names the time column [s] (default: an aixACCT table's 'Time'): "
      "each table that has it gets 'time' (column, uniform, sample_time, min_step, max_step, "
      "duration) and its other columns 'largest_rate' [/s] and 'longest_run' [s], the longest "
      "time between reversal points.");
  d.def(
      "extract",
      [](const std::filesystem::path& path, const std::vector<std::string>& columns,
         std::optional<std::size_t> table, std::optional<std::filesystem::path> out) -> ArrayDict {
        // Refused before reading: the output may not be the data file itself (also through links).
        if (out) io::check_outputs({{path, "path"}}, {{*out, "out"}});
        auto extracted = io::DataFile(path, table).columns_table(columns);
        if (out) {
          extracted.source = out->string();
          io::write_csv(*out, extracted);
        }
        py::dict result;
        for (std::size_t j = 0; j < extracted.cols(); ++j)
          result[py::str(extracted.names[j])] = to_array(std::move(extracted.columns[j]));
        return result;
      },
      "path"_a, "columns"_a = std::vector<std::string>{}, "table"_a = py::none(),
      "out"_a = py::none(),
      "{name: float64 array} of the columns (all when empty; aixACCT columns by name 'V+' or "
      "header 'V+ [V]') of one table of a data file, like 'hyst data extract'; out also writes "
      "them as CSV (atomically). Columns must have equal lengths.");
}

}  // namespace

void bind_data(py::module_& module) {
  auto io_module = module.attr("io").cast<py::module_>();
  bind_aixacct(io_module);
  module.attr("read_aixacct") = io_module.attr("read_aixacct");

  auto d = module.def_submodule(
      "data",
      "Measured records: reversal points with a hysteresis band, branches, cycles, loop area, "
      "coercive and remanent values, offset and drift removal, resampling per branch.");
  py::module_::import("sys").attr("modules")["hyst.data"] = d;

  py::enum_<data::Extremum>(d, "Extremum")
      .value("maximum", data::Extremum::maximum)
      .value("minimum", data::Extremum::minimum);
  py::enum_<data::Direction>(d, "Direction")
      .value("ascending", data::Direction::ascending)
      .value("descending", data::Direction::descending);

  py::class_<data::ReversalPoint>(d, "ReversalPoint", "A turning point of the input.")
      .def(py::init([](std::size_t index, double value, data::Extremum kind) {
             return data::ReversalPoint{index, value, kind};
           }),
           "index"_a, "value"_a, "kind"_a)
      .def_readonly("index", &data::ReversalPoint::index)
      .def_readonly("value", &data::ReversalPoint::value)
      .def_readonly("kind", &data::ReversalPoint::kind)
      .def("__repr__", [](const data::ReversalPoint& p) {
        return fmt::format("<ReversalPoint {} {} at {}>", to_string(p.kind), p.value, p.index);
      });
  py::class_<data::Branch>(d, "Branch", "A monotone part of the record between reversals.")
      .def_readonly("first", &data::Branch::first)
      .def_readonly("last", &data::Branch::last, "inclusive")
      .def_readonly("direction", &data::Branch::direction)
      .def_property_readonly("samples", &data::Branch::samples);
  py::class_<data::Cycle>(d, "Cycle", "One period of the input.")
      .def_readonly("first", &data::Cycle::first)
      .def_readonly("last", &data::Cycle::last, "inclusive")
      .def_readonly("ends_at_record_end", &data::Cycle::ends_at_record_end)
      .def_property_readonly("samples", &data::Cycle::samples);

  d.def(
      "reversal_points",
      [](const InputArray& input, double band) {
        return data::reversal_points(as_span(input, "input"), band);
      },
      "input"_a, "band"_a,
      "Turning points the input leaves by more than `band` (alternating maxima and minima).");
  d.def(
      "preisach_memory",
      [](const std::vector<data::ReversalPoint>& points) { return data::preisach_memory(points); },
      "points"_a, "The alternating dominant extrema left after wiping-out.");
  d.def(
      "default_band",
      [](const InputArray& input, double fraction) {
        return data::default_band(as_span(input, "input"), fraction);
      },
      "input"_a, "fraction"_a = 0.02, "fraction x the input's range.");
  d.def(
      "branches",
      [](const InputArray& input, double band) {
        return data::branches(as_span(input, "input"), band);
      },
      "input"_a, "band"_a, "Ascending and descending branches between the reversal points.");
  d.def(
      "cycles",
      [](const InputArray& input, double band) {
        return data::cycles(as_span(input, "input"), band);
      },
      "input"_a, "band"_a, "Complete periods of the input.");

  py::class_<data::Backbone>(d, "Backbone",
                             "Centre line and half-width of a loop on a common input grid.")
      .def_property_readonly("input",
                             [](const data::Backbone& b) { return readonly_copy(b.input); })
      .def_property_readonly("ascending",
                             [](const data::Backbone& b) { return readonly_copy(b.ascending); })
      .def_property_readonly("descending",
                             [](const data::Backbone& b) { return readonly_copy(b.descending); })
      .def_property_readonly("centre",
                             [](const data::Backbone& b) { return readonly_copy(b.centre); })
      .def_property_readonly("half_width",
                             [](const data::Backbone& b) { return readonly_copy(b.half_width); });
  d.def(
      "backbone",
      [](const InputArray& input, const InputArray& output, double band, std::size_t first,
         std::size_t last, std::size_t points) {
        return data::backbone(as_span(input, "input"), as_span(output, "output"), band, first, last,
                              points);
      },
      "input"_a, "output"_a, "band"_a, "first"_a, "last"_a, "points"_a = 101,
      "Backbone (centre line) and half-width of the loop of samples first..last.");

  bind_loops(d);
  bind_corrections(d);
  bind_files(d);
}

}  // namespace hyst::python
