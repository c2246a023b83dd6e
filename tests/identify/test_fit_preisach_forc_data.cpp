// The Preisach model identified from measured first-order reversal curves (shared data set
// pmagpy_forc_micromag_agm, conventional_example.forc: a natural sample on a MicroMag AGM, 120
// FORCs from positive saturation at HSat = 0.3 T, reversal fields H_r from +0.118 T down to
// -0.218 T, field mu0 H [T], moment [A m^2], shown here in nA m^2).
//
// Method: the moments are corrected for the drift of the calibration point (multiplicative,
// io/micromag_forc.hpp); the tabulated Everett function on K = 32 uniform levels over
// [min H_r, HSat] = [-0.218, 0.3] T is fitted by NNLS on its cell weights (fit_preisach.hpp) to
// every point of the fitted curves, from positive saturation. HSat, not the largest measured
// field (0.237 T), is the upper end: the sample is saturated at HSat, and relays that switch up
// between 0.237 and 0.3 T exist but are never switched up again within a FORC.
//
// Validation: (1) every 4th FORC (30 curves, including the lowest one) is left out of the fit and
// predicted; (2) the major loop: its descending branch is the first point of every FORC (each
// measured right after saturation at its H_r), predicted by one continuous descent from positive
// saturation, and its ascending branch is the lowest FORC (H_r = -0.218 T, held out in (1));
// (3) a harder test: 20 consecutive FORCs (H_r from -0.049 to +0.005 T, the steepest part of the
// loop around the coercive field) are left out of a second fit, which must interpolate across a
// 54 mT gap of reversal fields.
//
// `./tests/test_fit_preisach_forc_data` (in the build folder) prints the table of docs/results.md.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hyst/identify/fit_preisach.hpp"
#include "hyst/io/micromag_forc.hpp"

namespace hyst {
namespace {

const char* const kForcDataFile =
    HYST_SHARED_DATA_DIR "/pmagpy_forc_micromag_agm/conventional_example.forc";
constexpr double kNano = 1e9;  // A m^2 -> nA m^2

// The curves with their own samples (ReversalCurve views them), moments in nA m^2.
struct MeasuredCurve {
  std::vector<double> input;
  std::vector<double> output;
};

std::vector<MeasuredCurve> load_curves() {
  const auto file = io::correct_drift(io::read_micromag_forc(kForcDataFile),
                                      io::ForcDriftCorrection::multiplicative);
  std::vector<MeasuredCurve> curves;
  for (const auto& c : file.curves) {
    MeasuredCurve curve{c.field, c.moment};
    for (double& m : curve.output)
      m *= kNano;
    curves.push_back(std::move(curve));
  }
  return curves;
}

std::string row(std::string_view part, const ErrorMetrics& m) {
  return fmt::format("| {} | {} | {:.2f} | {:.3f} % | {:.1f} |\n", part, m.samples, m.rmse,
                     m.nrmse_percent, m.max_error);
}

TEST(FitPreisachForcData, PredictsHeldOutForcsAndTheMajorLoop) {
  if (!std::filesystem::exists(kForcDataFile)) GTEST_SKIP() << "no " << kForcDataFile;
  const auto curves = load_curves();
  ASSERT_EQ(curves.size(), 120U);
  std::vector<std::size_t> held_out;
  for (std::size_t n = 3; n < curves.size(); n += 4)
    held_out.push_back(n);
  // The table spans every reversal field of the protocol, also those of held-out curves.
  const double lowest = curves.back().input.front();
  const PreisachForcFitOptions options{
      .intervals = 32, .lower = lowest, .upper = 0.3, .held_out = held_out};
  const auto fit = fit_preisach_forcs(fit_records_of(curves), options);
  ASSERT_TRUE(fit.report.validation.has_value());
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.full();

  // Major loop: descending branch = FORC start points, ascending = the lowest FORC.
  std::vector<double> start_field;
  std::vector<double> start_moment;
  std::vector<double> held_start_moment;
  for (const auto& c : curves) {
    start_field.push_back(c.input.front());
    start_moment.push_back(c.output.front());
  }
  auto state = fit.model.make_state(PreisachInitialState::positive_saturation);
  std::vector<double> descending;
  std::vector<double> held_descending;
  for (std::size_t n = 0; n < curves.size(); ++n) {
    descending.push_back(fit.model.step(state, start_field[n]));
    if (n % 4 == 3) {
      held_descending.push_back(descending.back());
      held_start_moment.push_back(start_moment[n]);
    }
  }
  const auto descending_metrics = error_metrics(start_moment, descending);
  const auto held_descending_metrics = error_metrics(held_start_moment, held_descending);
  const auto ascending = predict_reversal_curve(fit.model, curves.back().input,
                                                PreisachInitialState::positive_saturation);
  const auto ascending_metrics = error_metrics(curves.back().output, ascending);

  // A block of 20 consecutive FORCs left out of a second fit.
  std::vector<std::size_t> block;
  for (std::size_t n = 40; n < 60; ++n)
    block.push_back(n);
  auto block_options = options;
  block_options.held_out = block;
  const auto block_fit = fit_preisach_forcs(fit_records_of(curves), block_options);
  ASSERT_TRUE(block_fit.report.validation.has_value());

  // Figures of docs/results.md (bounds ~1.5x the values measured on 2026-11-22).
  EXPECT_LT(fit.report.fit.nrmse_percent, 0.09);
  EXPECT_LT(fit.report.validation->nrmse_percent, 0.09);
  EXPECT_LT(descending_metrics.nrmse_percent, 0.15);
  EXPECT_LT(ascending_metrics.nrmse_percent, 0.16);
  EXPECT_LT(block_fit.report.validation->nrmse_percent, 1.3);

  fmt::print("{}\n\n", fit.report.full());
  fmt::print(
      "Drift-corrected (multiplicative) moments in nA m^2; K = {} levels over [{:.3f}, {} T], "
      "F0 = {:.1f} nA m^2, offset {:.1f} nA m^2, fit time {:.2f} s\n\n",
      options.intervals, fit.model.lower(), fit.model.upper(), fit.model.total_weight(),
      fit.model.params().offset, fit.report.seconds);
  fmt::print(
      "| part | points | RMSE [nA m^2] | NRMSE | max error [nA m^2] "
      "|\n|---|---:|---:|---:|---:|\n");
  fmt::print("{}", row("fit: 90 FORCs", fit.report.fit));
  fmt::print("{}", row("held out: every 4th FORC (30)", *fit.report.validation));
  fmt::print("{}", row("major loop, descending (all 120 FORC starts)", descending_metrics));
  fmt::print("{}", row("major loop, descending (30 held-out starts)", held_descending_metrics));
  fmt::print("{}", row("major loop, ascending (lowest FORC, held out)", ascending_metrics));
  fmt::print("{}",
             row(fmt::format("second fit without FORCs 40-59 (H_r {:.3f} .. {:.3f} T): the 20 "
                             "held out",
                             curves[59].input.front(), curves[40].input.front()),
                 *block_fit.report.validation));
}

}  // namespace
}  // namespace hyst
