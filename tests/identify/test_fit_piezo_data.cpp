// PI fitted to measured piezo loops (shared data set piezo_pzt_aixacct_butterfly,
// MeasurementData.mat): one period of a bipolar triangular voltage at five amplitudes (about 800,
// 1000, 1100, 1500 and 1900 V), with the displacement [nm] zeroed at the first sample of each
// record.
//
// Fit on the 1500 V record, predict the four others. Why 1500 V and not the largest, 1900 V: a
// rate-independent model needs a fit record whose reversals excite every threshold, so the largest
// record that PI can represent. The 1900 V record is beyond the coercive field: on its way down to
// -1890 V the displacement falls to -162 nm at -1528 V and then rises again to -19 nm (polarisation
// switching, the start of a butterfly loop). No PI model with a monotone branch can follow that,
// and its loop is so asymmetric that no odd-symmetric model can get below 10 % NRMSE on it
// (TheLargestLoopIsNotAPiLoop). The 1500 V record covers the amplitudes of 800, 1000 and 1100 V
// (interpolation); 1900 V is an extrapolation beyond the identified thresholds.
//
// Each prediction starts from the periodic state of its own input (every record is one period in
// steady state) and, like the measurement, is zeroed at its first sample: the records were zeroed
// separately, so their absolute levels are unrelated and the fitted offset carries no information
// across records.
//
// `./tests/test_fit_piezo_data` (in the build folder) prints the tables of docs/results.md.

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst {
namespace {

const char* const kFile = HYST_SHARED_DATA_DIR "/piezo_pzt_aixacct_butterfly/MeasurementData.mat";

struct Record {
  std::string name;  // suffix of the variable names, e.g. "15kv"
  std::vector<double> voltage, displacement;
  std::size_t top = 0, bottom = 0;  // indices of the voltage maximum and minimum
  double range = 0;                 // max - min of the displacement [nm]
};

Record load(const std::string& name) {
  Record r{name, io::read_mat_vector(kFile, "Vplus_" + name),
           io::read_mat_vector(kFile, "Displacement_" + name)};
  const auto& v = r.voltage;
  r.top = static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin());
  r.bottom = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
  const auto [low, high] = std::minmax_element(r.displacement.begin(), r.displacement.end());
  r.range = *high - *low;
  return r;
}

std::vector<Record> load_all() {
  std::vector<Record> records;
  for (const char* name : {"08kv", "1kv", "11kv", "15kv", "19kv"})
    records.push_back(load(name));
  return records;
}

PiFit fit_record(const Record& r) {
  return fit_prandtl_ishlinskii(r.voltage, r.displacement,
                                {.initial_state = PiFitOptions::InitialState::periodic});
}

// Prediction of a record from its periodic state, zeroed at the first sample like the data.
ErrorMetrics predict(const PrandtlIshlinskii& model, const Record& r) {
  auto state = pi_periodic_state(model, r.voltage);
  auto predicted = simulate(model, state, std::span<const double>(r.voltage));
  const double first = predicted.front();
  for (double& y : predicted)
    y -= first;
  return error_metrics(r.displacement, predicted);
}

// Lower bound on the NRMSE of ANY odd-symmetric model (classical PI in periodic steady state) on
// this record: the input is antiperiodic, v[k + N/2] = -v[k] (to within 6 V of +-800..1900 V),
// so such a model's output satisfies y[k + N/2] - c = -(y[k] - c), and the part of the measured
// displacement that is even over half a period, (y[k] + y[k + N/2]) / 2 - mean, is beyond its
// reach.
double odd_symmetry_floor(const Record& r) {
  const std::size_t n = r.displacement.size() - 1;  // the last sample repeats the first phase
  const std::size_t half = n / 2;
  double mean = 0;
  for (std::size_t k = 0; k < n; ++k)
    mean += r.displacement[k] / static_cast<double>(n);
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double even = 0.5 * (r.displacement[k] + r.displacement[(k + half) % n]) - mean;
    sum += even * even;
  }
  return 100.0 * std::sqrt(sum / static_cast<double>(n)) / r.range;  // in % like the NRMSE
}

// The loop does not close: |y[end] - y[0]| (drift within one period), in % of the range. A
// periodic model output closes exactly.
double closure_gap(const Record& r) {
  return 100.0 * std::abs(r.displacement.back() - r.displacement.front()) / r.range;
}

// A branch after a reversal: input travelled dv from the reversal, output changed by dy.
struct Branch {
  std::vector<double> dv, dy;
  double at(double x) const {  // linear interpolation; linear extrapolation beyond the end
    for (std::size_t i = 1; i < dv.size(); ++i) {
      if (dv[i] >= x)
        return dy[i - 1] + (x - dv[i - 1]) * (dy[i] - dy[i - 1]) / (dv[i] - dv[i - 1]);
    }
    const std::size_t last = dv.size() - 1, from = last - 10;  // slope of the last 10 intervals
    return dy[last] + (x - dv[last]) * (dy[last] - dy[from]) / (dv[last] - dv[from]);
  }
};

Branch descending(const Record& r) {
  Branch b;
  for (std::size_t k = r.top; k <= r.bottom; ++k) {
    b.dv.push_back(r.voltage[r.top] - r.voltage[k]);
    b.dy.push_back(r.displacement[r.top] - r.displacement[k]);
  }
  return b;
}

// From the minimum to the end of the record, then on into the next period (samples 1..top),
// shifted by the closure gap so that the branch is continuous.
Branch ascending(const Record& r) {
  Branch b;
  const auto& v = r.voltage;
  const auto& y = r.displacement;
  for (std::size_t k = r.bottom; k < v.size(); ++k) {
    b.dv.push_back(v[k] - v[r.bottom]);
    b.dy.push_back(y[k] - y[r.bottom]);
  }
  const double shift = y.back() - y.front();
  for (std::size_t k = 1; k <= r.top; ++k) {
    b.dv.push_back(v[k] - v[r.bottom]);
    b.dy.push_back(y[k] + shift - y[r.bottom]);
  }
  return b;
}

// Model-free baseline for predicting record g from record f under PI's own rules. Every PI branch
// after a reversal is y_rev +- 2 phi(dv / 2) with one curve phi for all amplitudes (Masing's rule,
// congruency), the same up and down (odd symmetry). So take f's measured branches, average up and
// down, and lay the result onto g's reversal points: the NRMSE of that on g is what the data allow
// a PI model identified on f to achieve, short of fitting noise. It contains g's asymmetry and
// every violation of congruency between the two amplitudes.
double congruency_baseline(const Record& f, const Record& g) {
  const Branch down_f = descending(f), up_f = ascending(f);
  const auto phi2 = [&](double dv) { return 0.5 * (down_f.at(dv) + up_f.at(dv)); };
  double sum = 0;
  std::size_t count = 0;
  for (const Branch& branch : {descending(g), ascending(g)}) {
    for (std::size_t i = 0; i < branch.dv.size(); ++i, ++count) {
      const double error = phi2(branch.dv[i]) - branch.dy[i];
      sum += error * error;
    }
  }
  return 100.0 * std::sqrt(sum / static_cast<double>(count)) / g.range;  // in %
}

std::string row(const std::string& record, const std::string& part, const ErrorMetrics& m) {
  return fmt::format("| {} | {} | {:.1f} | {:.2f} % | {:.1f} |\n", record, part, m.rmse,
                     m.nrmse_percent, m.max_error);
}

constexpr std::size_t kFitRecord = 3;  // "15kv"

TEST(PiOnMeasuredPiezoLoops, FitsThe1500VLoopUpToItsAsymmetry) {
  const auto records = load_all();
  const Record& r = records[kFitRecord];
  ASSERT_EQ(r.name, "15kv");
  const PiFit fit = fit_record(r);
  fmt::print("{}\n{}\n", fit.report.brief(), fit.report.full());
  EXPECT_EQ(fit.report.termination, Termination::converged) << fit.report.message;
  ASSERT_TRUE(fit.model.is_invertible());
  EXPECT_NO_THROW(InversePrandtlIshlinskii{fit.model});

  // The fit-part bound: the odd-symmetry floor (3.58 % of the range) is out of reach of any PI
  // model; the loop's failure to close (7.1 nm = 0.54 %) is too, a periodic output closes. Both
  // are measured above, the rest a 10-operator PI can fit: fit NRMSE <= floor + gap (4.13 %).
  const double floor = odd_symmetry_floor(r);
  EXPECT_LE(fit.report.fit.nrmse_percent, floor + closure_gap(r));
  // ... and it cannot beat the floor (5 % margin for the input's 6 V deviation from antiperiodic).
  EXPECT_GE(fit.report.fit.nrmse_percent, 0.95 * floor);
}

TEST(PiOnMeasuredPiezoLoops, PredictsTheOtherAmplitudesAsWellAsTheDataAllow) {
  const auto records = load_all();
  const Record& f = records[kFitRecord];
  const PiFit fit = fit_record(f);
  ASSERT_TRUE(fit.model.is_invertible());

  std::string table =
      "| record | part | RMSE [nm] | NRMSE | max error [nm] |\n|---|---|---|---|---|\n";
  table += row(f.name, "fit", fit.report.fit);
  std::string bounds;
  std::string raw;
  for (std::size_t g = 0; g < records.size(); ++g) {
    if (g == kFitRecord) continue;
    SCOPED_TRACE(records[g].name);
    const ErrorMetrics validation = predict(fit.model, records[g]);
    table += row(records[g].name, "validation", validation);
    // Bound: the congruency baseline, computed from the two measured loops alone (no model).
    const double bound = congruency_baseline(f, records[g]);
    bounds += fmt::format("{}: NRMSE {:.2f} % <= baseline {:.2f} % (odd-symmetry floor {:.2f} %)\n",
                          records[g].name, validation.nrmse_percent, bound,
                          odd_symmetry_floor(records[g]));
    EXPECT_LT(validation.nrmse_percent, bound);
    // The two-record overload scores the prediction as it comes out of the model, with the
    // offset fitted on the 1500 V record: the records' separate zeroing then adds to the error.
    const PiFit with_validation = fit_prandtl_ishlinskii(
        f.voltage, f.displacement, records[g].voltage, records[g].displacement,
        {.initial_state = PiFitOptions::InitialState::periodic});
    ASSERT_TRUE(with_validation.report.validation);
    raw += fmt::format("{}: NRMSE {:.2f} % without zeroing at the first sample\n", records[g].name,
                       with_validation.report.validation->nrmse_percent);
  }
  std::string each;
  for (const Record& r : records) {
    each += fmt::format(
        "{}: PI fitted to it alone NRMSE {:.2f} %, odd-symmetry floor {:.2f} %, closure gap "
        "{:.1f} nm = {:.2f} %\n",
        r.name, fit_record(r).report.fit.nrmse_percent, odd_symmetry_floor(r),
        std::abs(r.displacement.back() - r.displacement.front()), closure_gap(r));
  }
  std::string thresholds;
  for (double r : fit.model.params().thresholds)
    thresholds += fmt::format("{}{:.1f}", thresholds.empty() ? "" : ", ", r);
  std::string weights;
  for (double p : fit.model.params().weights)
    weights += fmt::format("{}{:.4g}", weights.empty() ? "" : ", ", p);
  fmt::print(
      "PI fitted on {} (periodic initial state), {} operators\nthresholds [V]: {}\n"
      "weights [nm/V]: {}\noffset [nm]: {:.2f}\n\n{}\n{}\n{}\n{}",
      f.name, fit.model.size(), thresholds, weights, fit.model.params().offset, table, bounds, raw,
      each);
}

TEST(PiOnMeasuredPiezoLoops, TheLargestLoopIsNotAPiLoop) {
  const auto records = load_all();
  const Record& r = records[4];
  ASSERT_EQ(r.name, "19kv");
  // The switching part of the 1900 V loop: the displacement rises again while the voltage still
  // falls to its minimum.
  const auto lowest = std::min_element(r.displacement.begin(), r.displacement.end());
  const auto lowest_at = static_cast<std::size_t>(lowest - r.displacement.begin());
  EXPECT_LT(lowest_at + 10, r.bottom);
  EXPECT_GT(r.displacement[r.bottom] - *lowest, 100.0);
  EXPECT_GT(odd_symmetry_floor(r), 10.0);

  const PiFit fit = fit_record(r);
  EXPECT_GE(fit.report.fit.nrmse_percent, 0.95 * odd_symmetry_floor(r));
  std::string table =
      "| record | part | RMSE [nm] | NRMSE | max error [nm] |\n|---|---|---|---|---|\n";
  table += row(r.name, "fit", fit.report.fit);
  for (std::size_t g = 0; g < 4; ++g)
    table += row(records[g].name, "validation", predict(fit.model, records[g]));
  fmt::print("For comparison, PI fitted on {} instead:\n{}", r.name, table);
}

}  // namespace
}  // namespace hyst
