// The properties every registered model must have, checked for each one through the registry
// with its example parameters and example input range only (one test per property and model,
// named after the model):
//   - simulate (and an inverse's invert) allocates nothing once warmed up;
//   - the output is bit-identical on every run, after reset and in any chunking;
//   - a state copied mid-run (clone, or state JSON text into a fresh model) continues
//     bit-identically;
//   - a model file saved mid-run loads with the same parameters and state and continues
//     bit-identically;
//   - where the model has an inverse, re-simulating its inputs reproduces reachable outputs;
//   - random inputs inside the input range give finite outputs within a stated bound;
//   - a NaN in any numeric parameter gives a hyst::Error naming that parameter.
//
// DynamicModel::simulate is one virtual call per batch around the concrete model's non-virtual
// step() loop (ModelAdapter: hyst::simulate, then a finiteness scan), so counting allocations over
// a batch counts those of step().

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../support/allocation_counter.hpp"
#include "hyst/core/error.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/signals/generators.hpp"

namespace hyst {
namespace {

bool bit_identical(std::span<const double> a, std::span<const double> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A seeded random walk over the middle 90 % of the entry's input range, with steps of up to 2.5 %
// of the range: reversals at every scale, so nested minor loops.
std::vector<double> random_input(const ModelEntry& entry, std::size_t samples, std::uint64_t seed) {
  const auto [min, max] = entry.example_input_range;
  const double centre = 0.5 * (min + max);
  const double half = 0.5 * (max - min);
  return signals::generate(signals::TimeGrid{samples, 1.0},
                           signals::RandomWalk{.max_step = 0.05 * half,
                                               .lower = centre - 0.9 * half,
                                               .upper = centre + 0.9 * half,
                                               .start = centre,
                                               .seed = seed});
}

// Two slow periods of a triangle over the whole input range, from its centre: the major loop.
std::vector<double> major_loop_input(const ModelEntry& entry) {
  const auto [min, max] = entry.example_input_range;
  constexpr std::size_t kSamplesPerPeriod = 1000;
  return signals::generate(signals::TimeGrid{2 * kSamplesPerPeriod, 1.0},
                           signals::Triangle{.amplitude = 0.5 * (max - min),
                                             .frequency = 1.0 / kSamplesPerPeriod,
                                             .offset = 0.5 * (min + max)});
}

std::vector<double> run(DynamicModel& model, std::span<const double> input) {
  std::vector<double> output(input.size());
  model.simulate(input, output);
  return output;
}

struct OutputRange {
  double min = 0.0;
  double max = 0.0;
  double span() const { return max - min; }
};

// The outputs of the example model, from its initial state, over the major loop.
OutputRange major_loop_output(const ModelEntry& entry) {
  const auto output = run(*entry.create(entry.example_params, nullptr), major_loop_input(entry));
  const auto [min, max] = std::minmax_element(output.begin(), output.end());
  return {*min, *max};
}

// True if `message` names `field` as a parameter of a model file: "params.<field>" not followed
// by more of a name ("params.a" is not named by "params.alpha = nan").
bool names_parameter(const std::string& message, const std::string& field) {
  const std::string path = "params." + field;
  for (auto at = message.find(path); at != std::string::npos; at = message.find(path, at + 1)) {
    const auto end = at + path.size();
    if (end == message.size()) return true;
    const auto next = static_cast<unsigned char>(message[end]);
    if (!std::isalnum(next) && next != '_') return true;
  }
  return false;
}

TEST(ConformanceSupport, AllocationCounterSeesAllocations) {
  const long before = test::allocation_count();
  // A direct call: the compiler may elide a new-expression, never a call of operator new.
  void* block = ::operator new(64);
  ::operator delete(block);
  EXPECT_EQ(test::allocation_count() - before, 1);
}

TEST(ConformanceSupport, ParameterNamesAreMatchedWhole) {
  EXPECT_TRUE(names_parameter("params.a = nan is not finite", "a"));
  EXPECT_TRUE(names_parameter("m.json: params.weights[0]: ...", "weights[0]"));
  EXPECT_TRUE(names_parameter("bad params.a", "a"));
  EXPECT_FALSE(names_parameter("params.alpha = nan is not finite", "a"));
  EXPECT_FALSE(names_parameter("a = nan is not finite", "a"));
}

class Conformance : public testing::TestWithParam<std::string> {
 protected:
  const ModelEntry& entry() const { return ModelRegistry::builtin().find(GetParam()); }
  std::unique_ptr<DynamicModel> make() const {
    return entry().create(entry().example_params, nullptr);
  }
  InverseLimits input_limits() const {
    return {entry().example_input_range.min, entry().example_input_range.max};
  }
};

TEST_P(Conformance, SimulateAndInvertAllocateNothingAfterWarmUp) {
  constexpr std::size_t kWarmUp = 100;
  const auto input = random_input(entry(), 20'000, 11);
  auto model = make();
  const auto targets = run(*model->clone(), input);
  auto inverse = model->has_inverse() ? model->inverse(input_limits()) : nullptr;

  std::vector<double> output(input.size());
  const std::span<const double> in(input);
  const std::span<double> out(output);
  model->simulate(in.first(kWarmUp), out.first(kWarmUp));
  long before = test::allocation_count();
  model->simulate(in.subspan(kWarmUp), out.subspan(kWarmUp));
  EXPECT_EQ(test::allocation_count() - before, 0) << "simulate allocated";
  EXPECT_TRUE(bit_identical(output, targets));

  if (!inverse) return;
  const std::span<const double> wanted(targets);
  std::vector<double> inputs(targets.size());
  const std::span<double> found(inputs);
  inverse->invert(wanted.first(kWarmUp), found.first(kWarmUp));
  before = test::allocation_count();
  inverse->invert(wanted.subspan(kWarmUp), found.subspan(kWarmUp));
  EXPECT_EQ(test::allocation_count() - before, 0) << "invert allocated";
}

TEST_P(Conformance, OutputIsBitIdenticalOnEveryRunAfterResetAndInAnyChunking) {
  const auto input = random_input(entry(), 20'000, 1013);
  const auto batch = run(*make(), input);

  auto by_sample = make();
  std::vector<double> sampled(input.size());
  for (std::size_t k = 0; k < input.size(); ++k)
    by_sample->simulate(std::span(input).subspan(k, 1), std::span(sampled).subspan(k, 1));
  EXPECT_TRUE(bit_identical(batch, sampled)) << "one sample at a time";

  // Chunks of 1, 2, 3, ... 97 samples, then again from 1.
  auto chunked = make();
  std::vector<double> in_chunks(input.size());
  std::size_t chunk = 1;
  for (std::size_t k = 0; k < input.size(); k += chunk, chunk = chunk % 97 + 1) {
    const std::size_t n = std::min(chunk, input.size() - k);
    chunked->simulate(std::span(input).subspan(k, n), std::span(in_chunks).subspan(k, n));
  }
  EXPECT_TRUE(bit_identical(batch, in_chunks)) << "uneven chunks";

  auto model = make();
  EXPECT_TRUE(bit_identical(batch, run(*model, input))) << "second run";
  const auto initial_state = make()->state();
  EXPECT_NE(model->state(), initial_state) << "the input must move the state";
  model->reset();
  EXPECT_EQ(model->state(), initial_state);
  EXPECT_TRUE(bit_identical(batch, run(*model, input))) << "after reset";
}

TEST_P(Conformance, StateCopiedMidRunContinuesBitIdentically) {
  const auto input = random_input(entry(), 4000, 23);
  const std::span<const double> first_half = std::span(input).first(2000);
  const std::span<const double> second_half = std::span(input).subspan(2000);
  auto model = make();
  run(*model, first_half);

  auto cloned = model->clone();
  // Through the text of the state, as a model file or Python would carry it.
  auto restored = make();
  restored->set_state(nlohmann::json::parse(model->state().dump()));
  EXPECT_EQ(restored->state(), model->state());

  const auto expected = run(*model, second_half);
  EXPECT_TRUE(bit_identical(expected, run(*cloned, second_half))) << "clone()";
  EXPECT_TRUE(bit_identical(expected, run(*restored, second_half))) << "state() -> set_state()";
}

TEST_P(Conformance, ModelFileSavedMidRunLoadsAndContinuesBitIdentically) {
  const auto input = random_input(entry(), 4000, 31);
  auto model = make();
  run(*model, std::span(input).first(2000));

  const auto path = std::filesystem::temp_directory_path() /
                    fmt::format("hyst-conformance-{}-{}.json", GetParam(), ::getpid());
  save_model(path, *model, {{"note", "conformance test"}});
  const auto loaded = load_model(path);
  std::filesystem::remove(path);

  EXPECT_EQ(loaded->name(), model->name());
  EXPECT_EQ(loaded->params(), model->params());
  EXPECT_EQ(loaded->state(), model->state());
  const auto rest = std::span(input).subspan(2000);
  EXPECT_TRUE(bit_identical(run(*model, rest), run(*loaded, rest)));
}

// Targets are the model's own outputs for a random input, so every one is reachable from the
// state the inverse starts in; the inverse's inputs, simulated from that state, must give them
// back within example_inverse_tolerance of the major loop's output range.
TEST_P(Conformance, InverseInputsReproduceReachableOutputs) {
  auto model = make();
  if (!model->has_inverse()) GTEST_SKIP() << GetParam() << " has no inverse";
  const auto input = random_input(entry(), 5000, 47);
  const auto targets = run(*model->clone(), input);

  auto inverse = model->inverse(input_limits());
  std::vector<double> inputs(targets.size());
  const auto report = inverse->invert(targets, inputs);
  EXPECT_TRUE(report.ok()) << report.saturated_samples << " samples saturated, the first at "
                           << report.first_saturated;

  const auto reproduced = run(*model, inputs);
  const double tolerance = entry().example_inverse_tolerance * major_loop_output(entry()).span();
  double worst = 0.0;
  std::size_t worst_at = 0;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const double error = std::abs(reproduced[k] - targets[k]);
    if (error > worst) worst = error, worst_at = k;
  }
  EXPECT_LE(worst, tolerance) << "at sample " << worst_at << ": target " << targets[worst_at]
                              << ", reproduced " << reproduced[worst_at];
}

// Bound: the major loop's output range widened by its own span on either side. Hysteresis
// models stay on or inside their major loop; the margin admits the overshoot of the dynamic
// models (oscillator, NARX) without admitting a run-away.
TEST_P(Conformance, RandomInputsGiveFiniteOutputsNearTheMajorLoop) {
  const auto loop = major_loop_output(entry());
  ASSERT_GT(loop.span(), 0.0) << "the major loop must move the output";
  const double lower = loop.min - loop.span();
  const double upper = loop.max + loop.span();
  for (const std::uint64_t seed : {101U, 202U, 303U}) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const auto output = run(*make(), random_input(entry(), 5000, seed));
    const auto [min, max] = std::minmax_element(output.begin(), output.end());
    EXPECT_TRUE(
        std::all_of(output.begin(), output.end(), [](double y) { return std::isfinite(y); }));
    EXPECT_GE(*min, lower) << "major loop output range [" << loop.min << ", " << loop.max << "]";
    EXPECT_LE(*max, upper) << "major loop output range [" << loop.min << ", " << loop.max << "]";
  }
}

TEST_P(Conformance, NanParameterGivesAnErrorNamingIt) {
  const auto& example = entry().example_params;
  std::size_t checked = 0;
  for (const auto& [key, value] : example.items()) {
    nlohmann::json params = example;
    std::string field = key;
    if (value.is_number()) {
      params[key] = std::numeric_limits<double>::quiet_NaN();
    } else if (value.is_array() && !value.empty() && value[0].is_number()) {
      params[key][0] = std::numeric_limits<double>::quiet_NaN();
      field += "[0]";
    } else {
      continue;
    }
    ++checked;
    SCOPED_TRACE(field);
    try {
      entry().create(params, nullptr);
      ADD_FAILURE() << "NaN accepted";
    } catch (const Error& error) {
      EXPECT_TRUE(names_parameter(error.what(), field)) << "message: " << error.what();
    }
  }
  EXPECT_GT(checked, 0U) << "the example has no numeric parameter";
}

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const auto& entry : ModelRegistry::builtin().entries())
    names.push_back(entry.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(EveryModel, Conformance, testing::ValuesIn(model_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace hyst
