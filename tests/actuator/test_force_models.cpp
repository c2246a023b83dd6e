// The actuator force F = H[i] with the further models of the library: the inverse compensator
// makes the force linear in the virtual current for each of them (modified PI and Maxwell-slip:
// analytic inverses; KP and Ikuta SMA: the numerical inverse), configurations choose them by
// name, invalid or unsupported ones are rejected with their reason, and the closed loop with a
// numerical inverse does not allocate.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/line_fit.hpp"
#include "hyst/actuator/actuator_config.hpp"
#include "hyst/actuator/comparison.hpp"
#include "hyst/actuator/control_loop.hpp"
#include "hyst/actuator/force_compensator.hpp"
#include "hyst/control/references.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/registry/actuator_force.hpp"
#include "hyst/registry/model_registry.hpp"
#include "loop_allocations.hpp"

namespace hyst {
namespace {

const std::string kForceConfigDir = HYST_EXAMPLE_CONFIG_DIR;

// Virtual current i_d: three triangle loops between 1 and 9 A (current range 0..10 A).
std::vector<double> demand() {
  return control::triangle_reference(1.0, 9.0, 3, 50.0, 1e-3).values;
}

struct Compensated {
  std::vector<double> force;
  double worst = 0.0;  // max |F - k_F i_d|
  double slope = 0.0;
  double intercept = 0.0;
  double residual = 0.0;  // largest residual of the least-squares line
};

// F = H[H^-1[k_F i_d]] over demand().
template <class H>
Compensated compensate(const H& model, double gain) {
  const InverseCompensator<H> compensator(model, {gain, 0.0, 10.0});
  auto compensator_state = compensator.initial_state();
  auto model_state = model.initial_state();
  Compensated result;
  const auto d = demand();
  for (double i_d : d) {
    result.force.push_back(model.step(model_state, compensator.step(compensator_state, i_d)));
    result.worst = std::max(result.worst, std::abs(result.force.back() - gain * i_d));
  }
  result.residual = test::line_fit_max_residual(d, result.force, result.slope, result.intercept);
  return result;
}

void expect_linear(const Compensated& c, double gain, double bound) {
  EXPECT_LE(c.worst, bound);
  EXPECT_NEAR(c.slope, gain, 1e-6 * gain);
  // Points within `bound` of the line k_F i_d: the least-squares line lies within about 2 bound
  // of it over the data, so no residual exceeds 3 bound.
  EXPECT_LE(c.residual, 3.0 * bound);
}

TEST(ForceModels, ModifiedPiIsLinearisedByItsAnalyticInverse) {
  // Gamma = -3 + v + 0.5 (F_1 + F_2 + F_3) lies in [-3, 0] at v = 0 and >= 19 at v = 10;
  // S saturates beyond +-4 (outer weights -0.3). So k_F [1, 9] is reachable from every state.
  const ModifiedPrandtlIshlinskii model(
      {.pi = {.thresholds = {0, 1, 2, 3}, .weights = {1, 0.5, 0.5, 0.5}, .offset = -3.0},
       .dead_zone = {{-4.0, 0.0, 4.0}, {-0.3, 1.0, -0.3}},
       .offset = 0.0});
  const auto c = compensate(model, 1.0);
  expect_linear(c, 1.0, 1e-9);  // analytic: rounding only
}

TEST(ForceModels, MaxwellSlipIsLinearisedThroughItsPiForm) {
  // D = 0.5, 1; F(0) <= -2.5 + 0.5 + 2 = 0 and F(10) >= 20 - 2.5 - 2.5 = 15 from any state.
  const MaxwellSlip model(
      {.stiffness = {1.0, 2.0}, .break_away = {0.5, 2.0}, .linear_stiffness = 2.0, .offset = -2.5});
  const auto c = compensate(model, 1.0);
  expect_linear(c, 1.0, 1e-9);
  // Without the linear spring the force saturates: no inverse, a clear error.
  const MaxwellSlip saturating({.stiffness = {1.0, 2.0}, .break_away = {0.5, 2.0}});
  EXPECT_HYST_ERROR((InverseCompensator<MaxwellSlip>(saturating, {1.0, 0.0, 10.0})),
                    "needs linear_stiffness > 0 to be invertible");
}

TEST(ForceModels, KpIsLinearisedByTheNumericalInverse) {
  // 10 cells on [0, 10], unit weights (55 kernels), offset 55: F = 0 at 0 A and 110 at 10 A
  // from any state (saturation), so k_F = 11 is reachable over [1, 9] A.
  KrasnoselskiiPokrovskii::Params params;
  params.levels = 10;
  params.lower = 0.0;
  params.upper = 10.0;
  params.weights.assign(55, 1.0);
  params.offset = 55.0;
  const KrasnoselskiiPokrovskii model(params);
  const auto c = compensate(model, 11.0);
  // |F(u) - F*| <= L tolerance, L = sum mu 2/a = 110 N/A, tolerance 1e-12 of the range.
  const NumericalInverse<KrasnoselskiiPokrovskii> inverse(model, {0.0, 10.0});
  const double bound = 110.0 * inverse.input_tolerance() + 1e-12 * 110.0;
  expect_linear(c, 11.0, bound);
  EXPECT_LT(bound, 1e-8);
}

TEST(ForceModels, IkutaSmaIsLinearisedByTheNumericalInverse) {
  // Heating A_s = 3 .. A_f = 8 raises the force to y_A = 20 N (xi -> 0), cooling M_f = 1 ..
  // M_s = 4 lowers it to y_M = 0: every branch runs to 0 or 20 N, so k_F = 2 is reachable over
  // [1, 9] A from every state.
  const IkutaSma model({.martensite_finish = 1.0,
                        .martensite_start = 4.0,
                        .austenite_start = 3.0,
                        .austenite_finish = 8.0,
                        .output_austenite = 20.0,
                        .output_martensite = 0.0});
  const auto c = compensate(model, 2.0);
  // |dF/di| <= 20 N scale pi/(2 * 3 A) (the narrower window); the scale of a re-scaled branch
  // stays below 2 here (checked on the forward run).
  auto state = model.initial_state();
  double scale = 1.0;
  const InverseCompensator<IkutaSma> compensator(model, {2.0, 0.0, 10.0});
  auto inverse_state = compensator.initial_state();
  for (double i_d : demand()) {
    model.step(state, compensator.step(inverse_state, i_d));
    scale = std::max(scale, state.scale);
  }
  const double lipschitz = 20.0 * scale * std::numbers::pi / 6.0;
  const double bound = lipschitz * compensator.inverse().input_tolerance() + 1e-12 * 20.0;
  expect_linear(c, 2.0, bound);
}

TEST(ForceModels, BoucWenIsLinearisedByTheNumericalInverse) {
  // F = alpha_k k i + (1 - alpha_k) k z with |z| <= z0 = 1: k = 10, alpha_k = 0.5 give F within
  // 5 i +- 5 N, so over i in [0, 10] A the targets k_F i_d = 5 i_d for i_d in [1, 9] A are
  // reachable from every state (5 i_d - 5 >= 0 and 5 i_d + 5 <= 50).
  const BoucWen model({.a = 1.0, .beta = 0.5, .gamma = 0.5, .stiffness = 10.0, .alpha_k = 0.5});
  const auto c = compensate(model, 5.0);
  // |dF/di| <= alpha_k k + (1 - alpha_k) k A = 10 N/A (|dz/dx| <= A on the bounded class).
  const NumericalInverse<BoucWen> inverse(model, {0.0, 10.0});
  const double bound = 10.0 * inverse.input_tolerance() + 1e-12 * 50.0;
  expect_linear(c, 5.0, bound);
  // Without compensation the same demand shows the hysteresis: the force is not on the line.
  auto state = model.initial_state();
  double worst = 0.0;
  for (double i_d : demand())
    worst = std::max(worst, std::abs(model.step(state, i_d) - 10.0 * i_d));
  EXPECT_GT(worst, 1.0);
}

// The MSMA actuator file with another force model (0..8 A, about 0..76 N).
nlohmann::json msma_with(const nlohmann::json& hysteresis) {
  auto document = nlohmann::json::parse(io::read_file(kForceConfigDir + "/msma_assumed.json"));
  document["hysteresis"] = hysteresis;
  return document;
}

nlohmann::json kp_force() {
  return {{"model", "kp"},
          {"params",
           {{"levels", 20},
            {"lower", 0.0},
            {"upper", 8.0},
            {"weights", std::vector<double>(210, 38.0 / 210.0)},
            {"offset", 38.0}}}};
}

TEST(ForceModels, ChosenByNameTheClosedLoopSettles) {
  const std::vector<nlohmann::json> forces{
      kp_force(),
      {{"model", "modified_pi"},
       {"params",
        {{"thresholds", {0.0, 1.0, 2.0, 3.0}},
         {"weights", {9.0, 1.0, 1.0, 1.0}},
         {"pi_offset", -6.0},
         {"dead_zone_thresholds", {-40.0, 0.0, 50.0}},
         {"dead_zone_weights", {-0.2, 1.0, -0.2}}}}},
      {{"model", "maxwell_slip"},
       {"params",
        {{"stiffness", {2.0, 4.0}},
         {"break_away", {2.0, 8.0}},
         {"linear_stiffness", 10.0},
         {"offset", -10.0}}}},
      {{"model", "bouc_wen"},
       {"params", {{"beta", 0.5}, {"gamma", 0.5}, {"stiffness", 19.0}, {"alpha_k", 0.5}}}},
      {{"model", "ikuta_sma"},
       {"params",
        {{"martensite_finish", 1.0},
         {"martensite_start", 4.0},
         {"austenite_start", 3.0},
         {"austenite_finish", 7.0},
         {"output_austenite", 76.0},
         {"output_martensite", 0.0}}}}};
  for (const auto& force : forces) {
    const auto name = force["model"].get<std::string>();
    const auto config = actuator_config_from_json(msma_with(force), name + ".json");
    EXPECT_EQ(hysteresis_name(config.hysteresis), name);
    const auto step = control::step_reference(3e-4, 6e-4, 0.05, 0.3, config.plant.sample_time);
    const auto closed = simulate_loop(config, ControlStrategy::pid_feedforward, step.values);
    const double tail =
        std::accumulate(closed.measured.end() - 500, closed.measured.end(), 0.0) / 500.0;
    EXPECT_NEAR(tail, 6e-4, 1e-6) << name;
  }
}

TEST(ForceModels, UnsupportedOrNonInvertibleModelsAreRejected) {
  auto maxwell = msma_with(
      {{"model", "maxwell_slip"}, {"params", {{"stiffness", {2.0}}, {"break_away", {2.0}}}}});
  EXPECT_HYST_ERROR(actuator_config_from_json(maxwell, "m.json"),
                    "m.json: hysteresis.params.linear_stiffness: a Maxwell-slip force needs "
                    "linear_stiffness > 0 to be invertible");
  auto rate = msma_with({{"model", "rate_dependent_pi"},
                         {"params", {{"thresholds", {0.0, 1.0}}, {"weights", {1.0, 1.0}}}}});
  EXPECT_HYST_ERROR(actuator_config_from_json(rate, "r.json"),
                    "r.json: hysteresis.model: model 'rate_dependent_pi' cannot be an actuator "
                    "force: its output depends on the input rate");
  EXPECT_EQ(hysteresis_names(),
            "gpi, pi, preisach, modified_pi, kp, maxwell_slip, ikuta_sma, bouc_wen");
  auto unknown = msma_with({{"model", "bouc"}, {"params", nlohmann::json::object()}});
  EXPECT_HYST_ERROR(actuator_config_from_json(unknown, "u.json"), "unknown model 'bouc'");
  // A modified PI whose dead-zone partial sum 1 - 1.2 < 0 has no inverse: the file's field name.
  auto mpi = msma_with({{"model", "modified_pi"},
                        {"params",
                         {{"thresholds", {0.0}},
                          {"weights", {9.0}},
                          {"dead_zone_thresholds", {0.0, 5.0}},
                          {"dead_zone_weights", {1.0, -1.2}}}}});
  EXPECT_HYST_ERROR(actuator_config_from_json(mpi, "p.json"),
                    "p.json: hysteresis.params: dead-zone partial sum g[0] + ... + g[1] = ");
}

// The force models are the registry entries' (actuator_force): every alternative of AnyHysteresis
// is provided by exactly one entry, and an entry's example model becomes an alternative it lists,
// named after the entry.
TEST(ForceModels, EveryAlternativeComesFromOneEntry) {
  std::vector<int> providers(std::variant_size_v<AnyHysteresis>, 0);
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    if (!entry.actuator_force) continue;
    for (const auto index : entry.actuator_force->alternatives)
      ++providers.at(index);
    const auto model = entry.create(entry.example_params, nullptr);
    const auto force = entry.actuator_force->hysteresis(*model);
    EXPECT_NE(std::find(entry.actuator_force->alternatives.begin(),
                        entry.actuator_force->alternatives.end(), force.index()),
              entry.actuator_force->alternatives.end())
        << entry.name;
    EXPECT_EQ(hysteresis_name(force), entry.name);
  }
  for (std::size_t index = 0; index < providers.size(); ++index)
    EXPECT_EQ(providers[index], 1) << "alternative " << index;
}

TEST(NoAllocation, ClosedLoopStepWithTheNumericalInverse) {
  const auto config = actuator_config_from_json(msma_with(kp_force()), "kp.json");
  const auto& kp = std::get<KrasnoselskiiPokrovskii>(config.hysteresis);
  const ControlLoop<KrasnoselskiiPokrovskii> loop(
      Actuator<KrasnoselskiiPokrovskii>(kp, config.plant), kp, config.loop);
  test::expect_closed_loop_does_not_allocate(loop, 20000);
}

}  // namespace
}  // namespace hyst
