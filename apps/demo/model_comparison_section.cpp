// Demo section "model comparison": `hyst compare` on every measured data set that has an input
// and an output record. Each model with a fitter is fitted with its default options on the first
// 75 % of one record and ranked by its free-run error on the last 25 %; the ranking table, its
// CSV, the loop and error plots and a self-contained HTML report go to model_comparison/<set>/.
// Where a data set has several records (the five piezo amplitudes, the nested B(H) loops, the
// FORCs), the models are first ranked on records they were not fitted on (hyst compare
// --fit-records/--validate-records): those tables go to model_comparison/<set>/ too.

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "demo_sections.hpp"

#include "hyst/core/error.hpp"
#include "hyst/identify/compare.hpp"
#include "hyst/identify/cross_record_compare.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/magic_table.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/io/micromag_loop.hpp"
#include "hyst/plot/comparison_html.hpp"
#include "hyst/plot/comparison_plots.hpp"
#include "hyst/registry/model_registry.hpp"

namespace {

namespace fs = std::filesystem;

struct DataSet {
  std::string name;         // folder name under model_comparison/
  std::string description;  // what the record is, for the Markdown
  std::vector<double> input;
  std::vector<double> output;
};

// The last period of a record made of `periods` identical ones (the steady state).
std::vector<double> last_period(const std::vector<double>& record, std::size_t periods) {
  const std::size_t length = record.size() / periods;
  return {record.end() - static_cast<std::ptrdiff_t>(length), record.end()};
}

std::vector<DataSet> read_data_sets(const fs::path& data_dir) {
  std::vector<DataSet> sets;
  const auto piezo = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat";
  sets.push_back({"piezo_19kv",
                  "piezo_pzt_aixacct_butterfly/MeasurementData.mat: one period of the 1.9 kV "
                  "bipolar triangle, voltage [V] -> displacement [nm]",
                  hyst::io::read_mat_vector(piezo, "Vplus_19kv"),
                  hyst::io::read_mat_vector(piezo, "Displacement_19kv")});
  for (const std::string material : {"MnZn_ferrite", "M130_27s", "amorf"}) {
    const auto folder = data_dir / "bh_loops_jamodel";
    const auto h = hyst::io::read_mat_columns(folder / ("H_" + material + ".mat"), "HmeasT");
    const auto b = hyst::io::read_mat_columns(folder / ("B_" + material + ".mat"), "BmeasT");
    sets.push_back({"bh_" + material,
                    fmt::format("bh_loops_jamodel/{{H,B}}_{}.mat: the largest measured loop, "
                                "H [A/m] -> B [T]",
                                material),
                    h.back(), b.back()});
  }
  const auto bouc_wen = data_dir / "boucwen_benchmark";
  sets.push_back({"bouc_wen_benchmark",
                  "boucwen_benchmark/{uest,yest}_multisine.mat: the last of the 4 periods "
                  "(8192 samples at 750 Hz), force [N] -> displacement [m]",
                  last_period(hyst::io::read_mat_vector(bouc_wen / "uest_multisine.mat", "u"), 4),
                  last_period(hyst::io::read_mat_vector(bouc_wen / "yest_multisine.mat", "y"), 4)});
  // The FORCs one after the other: a field history full of internal loops.
  const auto forc = hyst::io::read_micromag_forc(data_dir / "pmagpy_forc_micromag_agm" /
                                                 "conventional_example.forc");
  DataSet curves{"forc_conventional",
                 "pmagpy_forc_micromag_agm/conventional_example.forc: the first-order reversal "
                 "curves one after the other, field -> moment",
                 {},
                 {}};
  for (const auto& curve : forc.curves) {
    curves.input.insert(curves.input.end(), curve.field.begin(), curve.field.end());
    curves.output.insert(curves.output.end(), curve.moment.begin(), curve.moment.end());
  }
  sets.push_back(std::move(curves));
  // VSM loops: the HystLab paper's figure 1 (the measured moment, before the software's slope
  // correction) and the first of its 120 noise repeats.
  const auto vsm = data_dir / "hystlab_vsm_hysteresis_loops";
  const auto cp4q = hyst::io::read_micromag_loop(vsm / "fig01" / "CP4Q.hyst");
  sets.push_back({"vsm_cp4q",
                  "hystlab_vsm_hysteresis_loops/fig01/CP4Q.hyst: the measured loop (columns Raw "
                  "Field, Raw Moment; down and up branch), field [T] -> moment [A m^2]",
                  cp4q.field(), cp4q.moment()});
  const auto repeat =
      hyst::io::read_micromag_loop(vsm / "fig03a-f_noise_repeats" / "Noise_test_c100.000");
  sets.push_back({"vsm_noise_test_c100",
                  "hystlab_vsm_hysteresis_loops/fig03a-f_noise_repeats/Noise_test_c100.000: the "
                  "first repeat of the continuous-sweep series, field [T] -> moment [A m^2]",
                  repeat.field(), repeat.moment()});
  // A loop of the MagIC table (IS06a-1, the first, is in another moment unit than the rest).
  const auto magic = hyst::io::magic_hysteresis_loops(hyst::io::read_magic_table(
      data_dir / "pmagpy_forc_micromag_agm" / "hysteresis_magic_example.dat"));
  const auto& is06a2 = magic.at(1);
  sets.push_back({"magic_is06a_2",
                  fmt::format("pmagpy_forc_micromag_agm/hysteresis_magic_example.dat: the "
                              "hysteresis loop of specimen {} (+0.6 T -> -0.6 T -> +0.6 T), field "
                              "[T] -> moment (the unit as stored; see the data set's "
                              "PROVENANCE.md)",
                              is06a2.specimen),
                  is06a2.field, is06a2.moment});
  return sets;
}

std::string compare_one(const DataSet& set, const fs::path& folder) {
  fs::create_directories(folder);
  const hyst::CompareOptions options;
  const auto comparison = hyst::compare_models(set.input, set.output, options);
  const auto markdown = hyst::model_comparison_markdown(comparison);
  hyst::io::write_file_atomically(folder / "ranking.md", markdown);
  hyst::io::write_file_atomically(folder / "ranking.csv", hyst::model_comparison_csv(comparison));
  std::string figures;
  try {
    hyst::plot::write_model_comparison_plots(comparison, set.input, set.output,
                                             folder / "loops.png", folder / "errors.png");
    hyst::plot::write_model_comparison_html(folder / "report.html", comparison, set.input,
                                            set.output, "Model comparison: " + set.name);
    figures =
        fmt::format("Plots and report: `{0}/loops.png`, `{0}/errors.png`, `{0}/report.html`.\n\n",
                    folder.filename().string());
  } catch (const hyst::Error& error) {
    figures = fmt::format("(no plots: {})\n\n", error.what());
  }
  return fmt::format("### {}\n\n{} ({} samples).\n\n{}\n{}", set.name, set.description,
                     set.input.size(), markdown, figures);
}

// One ranking on separate records, written to `folder` (ranking.md, ranking.csv); returns its
// part of results.md: a heading, what was compared, the command that does the same, the table.
std::string cross_record_ranking(const std::string& heading, const std::string& what,
                                 const std::vector<hyst::NamedRecord>& fit,
                                 const std::vector<hyst::NamedRecord>& held_out,
                                 const hyst::CrossRecordOptions& options, const fs::path& folder) {
  fmt::print(stderr, "model comparison: {} (ranked on separate records)\n",
             folder.filename().string());
  const auto comparison = hyst::compare_across_records(fit, held_out, options);
  fs::create_directories(folder);
  const auto markdown = hyst::cross_record_markdown(comparison);
  hyst::io::write_file_atomically(folder / "ranking.md", markdown);
  hyst::io::write_file_atomically(folder / "ranking.csv", hyst::cross_record_csv(comparison));
  return fmt::format("### {}: {}\n\n{} Tables: `{}/ranking.md`, `{}/ranking.csv`.\n\n{}\n",
                     folder.filename().string(), heading, what, folder.filename().string(),
                     folder.filename().string(), markdown);
}

// The five piezo amplitudes: every model fitted on 1.5 kV and ranked on the other four, each
// predicted from its own periodic state and zeroed at its first sample like the measurement (the
// rule of the PI section and of docs/results.md).
std::string piezo_amplitudes(const fs::path& data_dir, const fs::path& folder) {
  const auto mat = data_dir / "piezo_pzt_aixacct_butterfly" / "MeasurementData.mat";
  auto record = [&](const std::string& suffix) {
    return hyst::NamedRecord{fmt::format("Vplus_{0}:Displacement_{0}", suffix),
                             hyst::io::read_mat_vector(mat, "Vplus_" + suffix),
                             hyst::io::read_mat_vector(mat, "Displacement_" + suffix)};
  };
  std::vector<hyst::NamedRecord> held_out;
  for (const std::string suffix : {"08kv", "1kv", "11kv", "19kv"})
    held_out.push_back(record(suffix));
  hyst::CrossRecordOptions options;
  options.validation = {hyst::ValidationStart::periodic, hyst::ValidationAlignment::first_sample};
  return cross_record_ranking(
      "ranked on records the models did not see",
      "piezo_pzt_aixacct_butterfly/MeasurementData.mat, one period per amplitude: every model "
      "with its default options fitted on 1.5 kV, ranked on 0.8, 1.0, 1.1 and 1.9 kV. The "
      "same as `hyst compare --data MeasurementData.mat --fit-records "
      "Vplus_15kv:Displacement_15kv --validate-records "
      "Vplus_08kv:Displacement_08kv,Vplus_1kv:Displacement_1kv,Vplus_11kv:Displacement_11kv,"
      "Vplus_19kv:Displacement_19kv --validation-start periodic --validation-align "
      "first-sample`.",
      {record("15kv")}, held_out, options, folder);
}

// The nested B(H) loops of one material: every model fitted on the largest loop and ranked on
// the smaller ones, each predicted from its own periodic state (one closed loop, cycled).
std::string nested_bh_loops(const fs::path& data_dir, const std::string& material,
                            const fs::path& folder) {
  const auto data = data_dir / "bh_loops_jamodel";
  const auto h = hyst::io::read_mat_columns(data / ("H_" + material + ".mat"), "HmeasT");
  const auto b = hyst::io::read_mat_columns(data / ("B_" + material + ".mat"), "BmeasT");
  std::vector<hyst::NamedRecord> loops;
  for (std::size_t i = 0; i < h.size(); ++i)
    loops.push_back({fmt::format("loop{}", i + 1), h.at(i), b.at(i)});
  const hyst::NamedRecord largest = loops.back();
  loops.pop_back();
  hyst::CrossRecordOptions options;
  options.validation = {hyst::ValidationStart::periodic, hyst::ValidationAlignment::none};
  return cross_record_ranking(
      "the largest loop predicts the nested ones",
      fmt::format(
          "bh_loops_jamodel/{{H,B}}_{0}.mat, H [A/m] -> B [T], one closed loop per column "
          "(loop1 the smallest): every model with its default options fitted on {1}, ranked "
          "on the {2} nested loops, each from its own periodic state. Written by `make demo` "
          "(hyst::compare_across_records with each column as a record: the command line takes "
          "whole variables of a .mat file, not the columns of one matrix).",
          material, largest.name, loops.size()),
      {largest}, loops, options, folder);
}

// The FORCs of the AGM run split in two: every model fitted on the even-numbered curves and
// ranked on the odd-numbered ones. Each curve is kept with the drift-calibration point measured
// just before it, near saturation, so a record carries the history a FORC needs (saturate, go
// down to the reversal field, sweep up) and the model state is saturated at each curve's start.
std::string every_other_forc(const fs::path& data_dir, const fs::path& folder) {
  const auto file = hyst::io::read_micromag_forc(data_dir / "pmagpy_forc_micromag_agm" /
                                                 "conventional_example.forc");
  hyst::NamedRecord even{"even FORCs", {}, {}};
  hyst::NamedRecord odd{"odd FORCs", {}, {}};
  for (std::size_t i = 0; i < file.curves.size(); ++i) {
    const auto& curve = file.curves[i];
    auto& record = i % 2 == 0 ? even : odd;
    record.input.push_back(curve.calibration_field);
    record.output.push_back(curve.calibration_moment);
    record.input.insert(record.input.end(), curve.field.begin(), curve.field.end());
    record.output.insert(record.output.end(), curve.moment.begin(), curve.moment.end());
  }
  const hyst::CrossRecordOptions options;  // start rest: the calibration point saturates the state
  return cross_record_ranking(
      "every other FORC",
      fmt::format(
          "pmagpy_forc_micromag_agm/conventional_example.forc, field [T] -> moment [A m^2]: "
          "the {} curves, each after the drift-calibration point measured before it near "
          "saturation; every model with its default options fitted on the even-numbered "
          "curves joined ({} samples), ranked on the odd-numbered ones joined ({} samples), "
          "predicted from rest (each curve's calibration point saturates the state).",
          file.curves.size(), even.input.size(), odd.input.size()),
      {even}, {odd}, options, folder);
}

}  // namespace

std::string model_comparison_section(const fs::path& data_dir, const fs::path& folder) {
  std::string markdown =
      "## Which model fits? Every model with a fitter on every measured record\n\n"
      "Default fit options for every model; the ranking is by the NRMSE of the free run on the "
      "held-out last 25 % of the record. Not compared: `magnet_ferrite_bwaveform_loss` (B(t) "
      "only, no H: no input-output pair to fit). A time split measures extrapolation; where a "
      "data set has several records, the first table ranks on separate records instead.\n\n";
  const auto comparisons = folder / "model_comparison";
  markdown += piezo_amplitudes(data_dir, comparisons / "piezo_amplitudes");
  markdown += nested_bh_loops(data_dir, "MnZn_ferrite", comparisons / "bh_MnZn_ferrite_nested");
  markdown += nested_bh_loops(data_dir, "M130_27s", comparisons / "bh_M130_27s_nested");
  markdown += every_other_forc(data_dir, comparisons / "forc_every_other");
  for (const auto& set : read_data_sets(data_dir)) {
    fmt::print(stderr, "model comparison: {} ({} samples)\n", set.name, set.input.size());
    markdown += compare_one(set, folder / "model_comparison" / set.name);
  }
  return markdown;
}
