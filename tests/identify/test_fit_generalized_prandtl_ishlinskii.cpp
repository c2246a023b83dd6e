#include "hyst/identify/fit_generalized_prandtl_ishlinskii.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <ceres/jet.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <matio.h>

#include "../support/expect_error.hpp"
#include "../support/gpi_reference.hpp"
#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"

namespace hyst {
namespace {

using TanhGpi = GeneralizedPrandtlIshlinskii<TanhEnvelope>;

// Gaussian noise from a seeded mt19937_64 by Box-Muller (the same numbers on every platform).
std::vector<double> gaussian_noise(std::size_t samples, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1p-53; };
  std::vector<double> noise(samples);
  for (std::size_t k = 0; k < samples; k += 2) {
    const double radius = sigma * std::sqrt(-2 * std::log(uniform()));
    const double angle = 2 * std::numbers::pi * uniform();
    noise[k] = radius * std::cos(angle);
    if (k + 1 < samples) noise[k + 1] = radius * std::sin(angle);
  }
  return noise;
}

// A current record that excites every threshold: a seeded random walk over 0 .. 8 A starting at
// rest at 0 A (the fit's `rest` initial state).
std::vector<double> msma_excitation(std::size_t samples, std::uint64_t seed) {
  auto i = test::random_walk(samples, seed, 4.0, 0.08);
  for (double& x : i)
    x += 4.0;
  const double first = i.front();
  for (std::size_t k = 0; k < 40; ++k)  // ramp in from 0 A
    i.insert(i.begin(), first * static_cast<double>(39 - k) / 40.0);
  i.resize(samples);
  return i;
}

// Parameters of `fitted` moved to the gauge rho = rho_true (the exact scaling symmetry).
GpiParameterVector in_gauge_of(const GpiParams& fitted, double rho_true) {
  return gpi_vector_from_params(rescale_density(fitted, rho_true / fitted.rho));
}

// The ASSUMED MSMA set recovered from 6000 samples of its output with Gaussian noise
// sigma = 0.1 N (0.13 % of the 76 N range). Tolerances, after moving the fit to the true rho:
// envelope levels a0, a3, b0, b3 within 1 %, slopes a1, b1 within 0.5 %, shifts a2, b2 within
// 0.01 (0.0125 A of input), tau and alpha within 5 %; RMSE within 5 % of sigma. (Reached on this
// data: 0.35 %, 0.05 %, 0.001, 0.6 %.)
TEST(FitGeneralizedPrandtlIshlinskii, RecoversAKnownModelFromNoisyOutput) {
  const auto truth_params = test::msma_params();
  const TanhGpi truth(truth_params);
  const auto current = msma_excitation(6000, 31);
  auto state = truth.initial_state();
  auto force = simulate(truth, state, current);
  const auto noise = gaussian_noise(force.size(), 0.1, 32);
  for (std::size_t k = 0; k < force.size(); ++k)
    force[k] += noise[k];

  GpiFitOptions options;
  options.m = truth_params.m;
  const GpiFit fit = fit_generalized_prandtl_ishlinskii(current, force, options);
  SCOPED_TRACE(fit.report.full());
  std::printf("%s\n", fit.report.brief().c_str());
  EXPECT_EQ(fit.report.termination, Termination::converged);
  EXPECT_NEAR(fit.model.weight_sum(), 1.0, 1e-12);  // the reported gauge
  EXPECT_NEAR(fit.report.fit.rmse, 0.1, 0.005);

  const auto got = in_gauge_of(fit.model.params(), truth_params.rho);
  const auto want = gpi_vector_from_params(truth_params);
  const double relative[] = {0.01, 0.005, -1, 0.01, 0.01, 0.005, -1, 0.01, 1e-12, 0.05, 0.05};
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const auto name = to_string(static_cast<GpiParameter>(i));
    std::printf("  %-5s true %10.5f fitted %10.5f\n", std::string(name).c_str(), want[i], got[i]);
    const double tolerance = relative[i] < 0 ? 0.01 : relative[i] * std::abs(want[i]);
    EXPECT_NEAR(got[i], want[i], tolerance) << name;
  }
  ASSERT_EQ(fit.parameters.size(), kGpiParameterCount);
  for (const auto& p : fit.parameters) {
    EXPECT_LE(p.lower, p.value) << to_string(p.parameter);
    EXPECT_LE(p.value, p.upper) << to_string(p.parameter);
  }
  EXPECT_TRUE(fit.parameters[static_cast<std::size_t>(GpiParameter::rho)].fixed);
}

// The last quarter of the record is held out and predicted from the state the fit part ends in.
TEST(FitGeneralizedPrandtlIshlinskii, HoldsOutTheEndOfTheRecord) {
  const TanhGpi truth(test::msma_params());
  const auto current = msma_excitation(3000, 41);
  auto state = truth.initial_state();
  auto force = simulate(truth, state, current);
  const auto noise = gaussian_noise(force.size(), 0.05, 42);
  for (std::size_t k = 0; k < force.size(); ++k)
    force[k] += noise[k];
  GpiFitOptions options;
  options.validate_fraction = 0.25;
  const GpiFit fit = fit_generalized_prandtl_ishlinskii(current, force, options);
  SCOPED_TRACE(fit.report.full());
  EXPECT_EQ(fit.report.fit.samples, 2250u);
  ASSERT_TRUE(fit.report.validation.has_value());
  EXPECT_EQ(fit.report.validation->samples, 750u);
  EXPECT_NEAR(fit.report.fit.rmse, 0.05, 0.005);
  EXPECT_NEAR(fit.report.validation->rmse, 0.05, 0.01);
  EXPECT_LT(fit.report.final_cost, fit.report.initial_cost);
  EXPECT_EQ(fit.report.model, "gpi");
  EXPECT_EQ(fit.report.parameters, 10u);
}

// One period of a steady-state loop (no first-loading curve in the record): with `periodic` the
// fit reproduces it (noise free) to 0.1 % NRMSE; assuming rest instead leaves a visible error.
TEST(FitGeneralizedPrandtlIshlinskii, PeriodicInitialStateForASteadyStateLoop) {
  const TanhGpi truth(test::msma_params());
  std::vector<double> current(800);
  for (std::size_t k = 0; k < current.size(); ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(current.size());
    current[k] = 4.0 + 3.5 * std::sin(2 * std::numbers::pi * t) +
                 0.6 * std::sin(6 * std::numbers::pi * t);  // with internal loops
  }
  auto state = truth.state_at_rest(current.front());
  simulate(truth, state, current);  // one period: the steady state
  const auto force = simulate(truth, state, current);
  GpiFitOptions options;
  options.initial_state = GpiFitOptions::InitialState::periodic;
  const GpiFit periodic = fit_generalized_prandtl_ishlinskii(current, force, options);
  EXPECT_LT(periodic.report.fit.nrmse_percent, 0.1) << periodic.report.full();
  // The returned initial state reproduces the reported fit.
  auto start = periodic.initial_state;
  EXPECT_NEAR(error_metrics(force, simulate(periodic.model, start, current)).nrmse_percent,
              periodic.report.fit.nrmse_percent, 1e-12);
  options.initial_state = GpiFitOptions::InitialState::rest;
  const GpiFit rest = fit_generalized_prandtl_ishlinskii(current, force, options);
  EXPECT_GT(rest.report.fit.nrmse_percent, 2 * periodic.report.fit.nrmse_percent);
}

TEST(FitGeneralizedPrandtlIshlinskii, NamesRoundTrip) {
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const auto parameter = static_cast<GpiParameter>(i);
    EXPECT_EQ(gpi_parameter_from_string(to_string(parameter)), parameter);
  }
  EXPECT_EQ(to_string(GpiParameter::alpha), "alpha");
  EXPECT_EQ(gpi_initial_state_from_string("periodic"), GpiFitOptions::InitialState::periodic);
  EXPECT_EQ(to_string(GpiFitOptions::InitialState::rest), "rest");
  EXPECT_HYST_ERROR(gpi_parameter_from_string("beta"), "unknown GPI parameter 'beta'");
  EXPECT_HYST_ERROR(gpi_initial_state_from_string("virgin"),
                    "unknown GPI initial state 'virgin' (expected rest or periodic)");
  auto params = test::msma_params();
  EXPECT_EQ(gpi_params_from_vector(gpi_vector_from_params(params), 10, 0, 8, 0).ascending,
            params.ascending);
  params.envelope = EnvelopeKind::arctan;
  EXPECT_HYST_ERROR(gpi_vector_from_params(params), "needs tanh envelopes");
}

// The data-derived starting points sit at the loop: centre, half-range, width.
TEST(FitGeneralizedPrandtlIshlinskii, StartingPointsComeFromTheLoop) {
  const TanhGpi truth(test::msma_params());
  auto state = truth.initial_state();
  const auto current = test::msma_current();
  const auto force = simulate(truth, state, current);
  const auto starts = gpi_starting_points(current, force, 10);
  ASSERT_EQ(starts.size(), 4u);
  for (const auto& theta : starts) {
    EXPECT_NEAR(theta[3], 0.5 * (0.13 + 76.04), 0.01);  // a3 = output centre
    EXPECT_EQ(theta[3], theta[7]);
    EXPECT_GT(theta[6], theta[2]);  // b2 > a2: descending envelope at lower inputs
    double sum = 0;
    for (std::size_t j = 0; j <= 10; ++j)
      sum += theta[8] * std::exp(-theta[9] * theta[10] * static_cast<double>(j));
    EXPECT_NEAR(sum, 1.0, 1e-12);  // rho sets S = 1
  }
}

TEST(FitGeneralizedPrandtlIshlinskii, RejectsBadInput) {
  const auto current = msma_excitation(200, 5);
  const TanhGpi truth(test::msma_params());
  auto state = truth.initial_state();
  auto force = simulate(truth, state, current);
  const std::vector<double> short_output(force.begin(), force.end() - 1);
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, short_output),
                    "GPI fit input has 200 values but GPI fit output has 199");
  auto bad = force;
  bad[3] = NAN;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, bad),
                    "GPI fit output[3] = nan is not finite");
  const std::vector<double> flat(current.size(), 2.0);
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, flat),
                    "GPI fit: the output of the fit part is constant (all 200 samples = 2)");
  EXPECT_HYST_ERROR(
      fit_generalized_prandtl_ishlinskii(std::span(current).first(20), std::span(force).first(20)),
      "the fit part has 20 samples, fewer than 2 * 11 = 22");
  GpiFitOptions options;
  options.m = 0;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, force, options),
                    "GPI fit m = 0 must be in [1, 200]");
  options = {};
  options.lower[static_cast<std::size_t>(GpiParameter::a1)] = 5.0;
  options.upper[static_cast<std::size_t>(GpiParameter::a1)] = 1.0;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, force, options),
                    "GPI fit bounds of a1: lower = 5 must be < upper = 1");
  options = {};
  options.starts = {gpi_vector_from_params(test::msma_params())};
  options.starts[0][0] = -1.0;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, force, options),
                    "GPI fit start 0: a0 = -1 lies outside its bounds");
  options = {};
  options.validate_fraction = 0.2;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, force, current, force, options),
                    "GPI fit validate_fraction = 0.2 must be 0 when separate validation records");
  options.validate_fraction = 1.0;
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(current, force, options),
                    "GPI fit: validate_fraction = 1 must be in [0, 1)");
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(std::span<const GpiRecord>{}, {}),
                    "GPI fit: no record to fit");
  const std::vector<GpiRecord> records{{current, force}, {current, flat}};
  EXPECT_HYST_ERROR(fit_generalized_prandtl_ishlinskii(records, {}),
                    "GPI fit: the output of the fit part (record 1) is constant");
}

// Automatic derivatives through the model's memory agree with central finite differences of the
// double simulation (a generic point: no reversal sits exactly on a switching point).
TEST(FitGeneralizedPrandtlIshlinskii, JetDerivativesMatchFiniteDifferences) {
  using Jet = ceres::Jet<double, kGpiParameterCount>;
  const GpiParameterVector theta{38.0, 0.75, -3.1, 41.0, 39.0, 0.82, -2.7, 40.5, 0.15, 0.12, 0.9};
  const std::size_t m = 6, n = m + 1;
  const auto current = msma_excitation(400, 77);
  const auto simulate_theta = [&](const auto* t, auto* out) {
    using T = std::remove_cv_t<std::remove_pointer_t<decltype(t)>>;
    using K = GpiKernel<TanhEnvelope, T>;
    std::vector<T> r(n), p(n), z(n);
    K::exponential_density(t[8], t[9], t[10], m, r.data(), p.data());
    K::rest_state(t, t + 4, current.front(), LoopBranch::ascending, n, z.data());
    K::simulate(t, t + 4, r.data(), p.data(), n, z.data(), current, out);
  };
  std::array<Jet, kGpiParameterCount> jet_theta;
  for (std::size_t i = 0; i < kGpiParameterCount; ++i)
    jet_theta[i] = Jet(theta[i], static_cast<int>(i));
  std::vector<Jet> jet_out(current.size());
  simulate_theta(jet_theta.data(), jet_out.data());
  double worst = 0;
  for (std::size_t i = 0; i < kGpiParameterCount; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(theta[i]));
    auto plus = theta, minus = theta;
    plus[i] += h;
    minus[i] -= h;
    std::vector<double> y_plus(current.size()), y_minus(current.size()), y(current.size());
    simulate_theta(plus.data(), y_plus.data());
    simulate_theta(minus.data(), y_minus.data());
    simulate_theta(theta.data(), y.data());
    for (std::size_t k = 0; k < current.size(); ++k) {
      // The same template, to rounding (the double path uses a vectorised dot product).
      ASSERT_NEAR(jet_out[k].a, y[k], 1e-13 * (1 + std::abs(y[k])));
      const double numeric = (y_plus[k] - y_minus[k]) / (2 * h);
      const double error = std::abs(jet_out[k].v[static_cast<Eigen::Index>(i)] - numeric);
      worst = std::max(worst, error / (1 + std::abs(numeric)));
    }
  }
  EXPECT_LE(worst, 1e-5);
}

// Columns of a real N x M double matrix in a MAT file (hyst::io reads vectors only).
std::vector<std::vector<double>> read_mat_columns(const std::filesystem::path& path,
                                                  const char* variable) {
  mat_t* file = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (file == nullptr) throw Error(fmt::format("cannot open {}", path.string()));
  matvar_t* var = Mat_VarRead(file, variable);
  if (var == nullptr || var->rank != 2 || var->class_type != MAT_C_DOUBLE || var->isComplex) {
    if (var != nullptr) Mat_VarFree(var);
    Mat_Close(file);
    throw Error(fmt::format("{}: no real double matrix '{}'", path.string(), variable));
  }
  const auto* data = static_cast<const double*>(var->data);
  std::vector<std::vector<double>> columns(var->dims[1]);
  for (std::size_t c = 0; c < var->dims[1]; ++c)
    columns[c].assign(data + c * var->dims[0], data + (c + 1) * var->dims[0]);
  Mat_VarFree(var);
  Mat_Close(file);
  return columns;
}

struct LoopFamily {
  std::string material;
  std::vector<std::vector<double>> h;  // [A/m], one closed loop per column, growing amplitude
  std::vector<std::vector<double>> b;  // [T]
};

LoopFamily read_bh_loops(const std::string& material) {
  const std::filesystem::path folder =
      std::filesystem::path(HYST_SHARED_DATA_DIR) / "bh_loops_jamodel";
  return {material, read_mat_columns(folder / ("H_" + material + ".mat"), "HmeasT"),
          read_mat_columns(folder / ("B_" + material + ".mat"), "BmeasT")};
}

// NRMSE of a model on a closed loop record, started in the loop's periodic steady state.
double gpi_loop_nrmse(const TanhGpi& model, const std::vector<double>& h,
                      const std::vector<double>& b) {
  auto state = model.state_at_rest(h.front());
  for (double v : h)
    model.step(state, v);
  return error_metrics(b, simulate(model, state, h)).nrmse_percent;
}

double pi_loop_nrmse(const PrandtlIshlinskii& model, const std::vector<double>& h,
                     const std::vector<double>& b) {
  auto state = pi_periodic_state(model, h);
  return error_metrics(b, simulate(model, state, h)).nrmse_percent;
}

std::string parameter_line(const GpiFit& fit) {
  std::string line;
  for (const auto& p : fit.parameters) {
    line += fmt::format("{}{} = {:.4g}{}", line.empty() ? "" : ", ", to_string(p.parameter),
                        p.value, p.at_bound ? " (at bound)" : "");
  }
  return line;
}

// Measured B(H) loops (bh_loops_jamodel, MIT; H [A/m] -> B [T], one closed loop per column).
// A: GPI (m = 10, 10 identifiable parameters) and classical PI (11 plays, 12 NNLS weights) fitted
//    to the same data, the largest loop in its periodic steady state; every smaller loop is held
//    out and predicted from its own periodic steady state.
// B: GPI fitted to the largest and the smallest loop together, the loops between held out.
// Prints the tables of docs/results.md; asserts the figures with some margin.
TEST(FitGeneralizedPrandtlIshlinskii, MeasuredBhLoops) {
  const std::filesystem::path folder =
      std::filesystem::path(HYST_SHARED_DATA_DIR) / "bh_loops_jamodel";
  if (!std::filesystem::exists(folder)) GTEST_SKIP() << "no " << folder;
  GpiFitOptions options;
  options.m = 10;
  options.initial_state = GpiFitOptions::InitialState::periodic;
  PiFitOptions pi_options;
  pi_options.operators = 11;
  pi_options.initial_state = PiFitOptions::InitialState::periodic;

  std::string table_a =
      "| material | loop, H amplitude | role | GPI NRMSE | PI NRMSE |\n|---|---|---|---:|---:|\n";
  std::string table_b = "| material | loop, H amplitude | role | GPI NRMSE |\n|---|---|---|---:|\n";
  std::string details;
  for (const std::string material : {"M130_27s", "MnZn_ferrite"}) {
    const LoopFamily loops = read_bh_loops(material);
    const std::size_t count = loops.h.size();
    ASSERT_GE(count, 3u);
    const auto& h_major = loops.h.back();
    const auto& b_major = loops.b.back();

    const GpiFit gpi = fit_generalized_prandtl_ishlinskii(h_major, b_major, loops.h[count - 2],
                                                          loops.b[count - 2], options);
    const PiFit pi = fit_prandtl_ishlinskii(h_major, b_major, loops.h[count - 2],
                                            loops.b[count - 2], pi_options);
    const std::vector<GpiRecord> pair{{h_major, b_major}, {loops.h.front(), loops.b.front()}};
    std::vector<GpiRecord> between;
    for (std::size_t c = 1; c + 1 < count; ++c)
      between.push_back({loops.h[c], loops.b[c]});
    const GpiFit gpi_pair = fit_generalized_prandtl_ishlinskii(pair, between, options);
    details += fmt::format("{} A: {}\n  {}\n{} B: {}\n  {}\n", material, gpi.report.brief(),
                           parameter_line(gpi), material, gpi_pair.report.brief(),
                           parameter_line(gpi_pair));

    for (std::size_t c = count; c-- > 0;) {
      const auto [lo, hi] = std::minmax_element(loops.h[c].begin(), loops.h[c].end());
      const auto loop = fmt::format("{} of {}, {:.0f} A/m", c + 1, count, 0.5 * (*hi - *lo));
      const double g = gpi_loop_nrmse(gpi.model, loops.h[c], loops.b[c]);
      const double p = pi_loop_nrmse(pi.model, loops.h[c], loops.b[c]);
      const double g_pair = gpi_loop_nrmse(gpi_pair.model, loops.h[c], loops.b[c]);
      table_a += fmt::format("| {} | {} | {} | {:.2f} % | {:.2f} % |\n", material, loop,
                             c + 1 == count ? "fit" : "held out", g, p);
      const bool fitted = c + 1 == count || c == 0;
      table_b += fmt::format("| {} | {} | {} | {:.2f} % |\n", material, loop,
                             fitted ? "fit" : "held out", g_pair);
      // GPI beats PI wherever the loop saturates (all but the smallest loop).
      if (c > 0) {
        EXPECT_LT(g, p) << material << " loop " << c + 1;
      }
      if (!fitted) {
        EXPECT_LT(g_pair, 12.0) << material << " loop " << c + 1;
      }
    }
    EXPECT_LT(gpi.report.fit.nrmse_percent, 5) << material;
    EXPECT_LT(gpi.report.validation->nrmse_percent, 10) << material;
    EXPECT_LT(gpi_pair.report.validation->nrmse_percent, 12) << material;
  }
  std::printf(
      "A: fitted to the largest loop\n%s\nB: GPI fitted to the largest and the smallest "
      "loop\n%s\n%s",
      table_a.c_str(), table_b.c_str(), details.c_str());
}

}  // namespace
}  // namespace hyst
