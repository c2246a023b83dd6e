// Determinism beyond the conformance suite (which checks every registered model's runs, resets
// and chunkings): the concrete models' step() loop equals hyst::simulate() and the registry's
// batch; fits are reproducible (same data and options: the same parameters, bit for bit).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "../support/test_signals.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Inside every example model's input range, with reversals at many scales.
std::vector<double> test_input() {
  return test::random_walk(20000, 1013, 0.9, 0.05);
}

std::vector<double> in_one_batch(DynamicModel& model, const std::vector<double>& input) {
  std::vector<double> output(input.size());
  model.simulate(input, output);
  return output;
}

template <class Model>
std::vector<double> step_loop(const Model& model, const std::vector<double>& input) {
  auto state = model.initial_state();
  std::vector<double> output;
  for (const double v : input)
    output.push_back(model.step(state, v));
  return output;
}

TEST(Determinism, PrandtlIshlinskiiStepLoopEqualsSimulateAndTheRegistry) {
  const auto input = test_input();
  const PrandtlIshlinskii model(
      {.thresholds = {0.0, 0.3, 0.7, 1.0}, .weights = {0.8, 0.5, 0.3, 0.2}, .offset = 0.1});
  auto state = model.initial_state();
  const auto batch = simulate(model, state, input);
  EXPECT_TRUE(bit_identical(step_loop(model, input), batch));
  const auto dynamic = ModelRegistry::builtin().find("pi").create(
      {{"thresholds", {0.0, 0.3, 0.7, 1.0}}, {"weights", {0.8, 0.5, 0.3, 0.2}}, {"offset", 0.1}},
      nullptr);
  EXPECT_TRUE(bit_identical(in_one_batch(*dynamic, input), batch));
}

TEST(Determinism, PreisachStepLoopEqualsSimulateAndTheRegistry) {
  const auto input = test_input();
  std::vector<double> weights(preisach_relay_count(21));
  for (std::size_t k = 0; k < weights.size(); ++k)
    weights[k] = 1.0 + 0.5 * std::sin(0.37 * static_cast<double>(k));
  const Preisach model({.everett = {.levels = 21, .lower = -1, .upper = 1, .weights = weights}});
  auto state = model.initial_state();
  const auto batch = simulate(model, state, input);
  EXPECT_TRUE(bit_identical(step_loop(model, input), batch));
  const auto dynamic =
      ModelRegistry::builtin()
          .find("preisach")
          .create({{"levels", 21}, {"lower", -1.0}, {"upper", 1.0}, {"weights", weights}}, nullptr);
  EXPECT_TRUE(bit_identical(in_one_batch(*dynamic, input), batch));
}

// Every fitter, twice on the same data (the example model's response to a random walk): the
// same parameters and the same report, bit for bit. The fitters draw no random numbers; a fitter
// that does must take its seed from the options, which are the same here. One test per fitter, so
// that they run in parallel; iterative fitters stop after a few iterations (and screen their
// starts for two) on a short record, since reproducibility does not need convergence and the same
// code runs either way.
class FitDeterminism : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> fitter_names() {
  std::vector<std::string> names;
  for (const auto& entry : ModelRegistry::builtin().entries())
    if (entry.can_fit()) names.push_back(entry.name);
  return names;
}

TEST_P(FitDeterminism, TwoFitsGiveTheSameBits) {
  const auto& entry = ModelRegistry::builtin().find(GetParam());
  const auto input = test::random_walk(320, 29, 0.9, 0.08);
  const auto output = in_one_batch(*entry.create(entry.example_params, nullptr), input);
  FitRequest request;
  request.input = input;
  request.output = output;
  request.validate_fraction = 0.25;
  const auto has_option = [&](std::string_view name) {
    return std::any_of(entry.fit_options.begin(), entry.fit_options.end(),
                       [&](const auto& option) { return option.name == name; });
  };
  if (has_option("max_iterations")) request.options["max_iterations"] = 8;
  if (has_option("screening_iterations")) request.options["screening_iterations"] = 2;
  const auto first = entry.fit(request);
  const auto second = entry.fit(request);
  EXPECT_EQ(first.model->params(), second.model->params());
  EXPECT_EQ(first.model->state(), second.model->state());
  EXPECT_TRUE(bit_identical(in_one_batch(*first.model, input), in_one_batch(*second.model, input)));
  EXPECT_EQ(first.report.iterations, second.report.iterations);
  EXPECT_EQ(first.report.final_cost, second.report.final_cost);
  EXPECT_EQ(first.report.fit.rmse, second.report.fit.rmse);
}

INSTANTIATE_TEST_SUITE_P(EveryFitter, FitDeterminism, ::testing::ValuesIn(fitter_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace hyst
