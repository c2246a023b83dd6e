#include "hyst/registry/model_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

namespace fs = std::filesystem;

class ModelFileTest : public testing::Test {
 protected:
  void SetUp() override {
    folder_ =
        fs::temp_directory_path() /
        ("hyst_model_file_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const std::string& text) {
    io::write_file_atomically(folder_ / name, text);
    return folder_ / name;
  }

  fs::path folder_;
};

nlohmann::json pi_document() {
  return nlohmann::json::parse(R"({"model": "pi", "version": 1,
      "params": {"thresholds": [0, 0.3, 0.7, 1.0], "weights": [0.8, 0.5, 0.3, 0.2],
                 "offset": 0.1}})");
}

std::string load_error(const nlohmann::json& document) {
  try {
    model_from_json(document, "m.json");
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

// The registry walk: every registered model is built from its example parameters, simulated,
// written to JSON and read back, and the copy continues with bit-identical output.
TEST(ModelRegistry, EveryModelRoundTripsThroughItsModelFile) {
  const auto input = test::random_walk(3000, 17, 2.0, 0.1);
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    SCOPED_TRACE(entry.name);
    EXPECT_FALSE(entry.description.empty());
    EXPECT_FALSE(entry.parameters.empty());
    auto model = entry.create(entry.example_params, nullptr);
    ASSERT_EQ(model->name(), entry.name);
    std::vector<double> first(input.size() / 2);
    model->simulate(std::span(input).first(first.size()), first);

    const auto document = model_to_json(*model);
    auto copy = model_from_json(nlohmann::json::parse(document.dump()), "memory");
    EXPECT_EQ(copy->params(), model->params());
    EXPECT_EQ(copy->state(), model->state());
    std::vector<double> rest(input.size() - first.size());
    std::vector<double> rest_copy(rest.size());
    model->simulate(std::span(input).subspan(first.size()), rest);
    copy->simulate(std::span(input).subspan(first.size()), rest_copy);
    EXPECT_EQ(rest, rest_copy);
  }
}

// A run on a copy of the state (simulate_from_state) gives what a run of a copy of the model
// gives, bit for bit, from the model's current state, and leaves the model as it was.
TEST(ModelRegistry, EveryModelRunsFromItsStateWithoutChangingIt) {
  const auto input = test::random_walk(2000, 23, 2.0, 0.1);
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    SCOPED_TRACE(entry.name);
    auto model = entry.create(entry.example_params, nullptr);
    std::vector<double> warm(500);
    model->simulate(std::span(input).first(warm.size()), warm);  // a state other than the start
    const auto state = model->state();
    std::vector<double> from_state(input.size()), from_copy(input.size());
    model->simulate_from_state(input, from_state);
    model->clone()->simulate(input, from_copy);
    EXPECT_EQ(from_state, from_copy);
    EXPECT_EQ(model->state(), state);
  }
  // The same checks as simulate(): a NaN input is named.
  const auto pi = ModelRegistry::builtin().find("pi").create(
      ModelRegistry::builtin().find("pi").example_params, nullptr);
  std::vector<double> bad{0.0, std::nan(""), 0.0}, out(3);
  EXPECT_THROW(pi->simulate_from_state(bad, out), Error);
}

TEST(ModelRegistry, UnknownNamesListTheKnownOnes) {
  EXPECT_HYST_ERROR(ModelRegistry::builtin().find("prandtl"), "unknown model 'prandtl' (known: pi");
  EXPECT_NE(ModelRegistry::builtin().find_if_known("pi"), nullptr);
}

TEST_F(ModelFileTest, SaveAndLoadKeepParametersStateAndInfo) {
  auto model = model_from_json(pi_document(), "memory");
  std::vector<double> y(500);
  model->simulate(test::random_walk(500, 3), y);
  const auto path = folder_ / "m.json";
  save_model(path, *model, {{"note", "written by a test"}});
  const auto loaded = load_model(path);
  EXPECT_EQ(loaded->params(), model->params());
  EXPECT_EQ(loaded->state(), model->state());
  std::ifstream file(path);
  const auto document = nlohmann::json::parse(file);
  EXPECT_EQ(document.at("info").at("note"), "written by a test");
  EXPECT_EQ(document.at("version"), kModelFileVersion);
}

TEST_F(ModelFileTest, ErrorsNameTheFileAndTheField) {
  EXPECT_HYST_ERROR(load_model(folder_ / "missing.json"), "missing.json");
  EXPECT_HYST_ERROR(load_model(write("bad.json", "{\"model\": \"pi\",\n  \"version\": }")),
                    "bad.json: not valid JSON: parse error at line 2, column 14");
}

TEST(ModelFile, ValidationErrorsNameTheField) {
  auto document = pi_document();
  document["params"]["thresholds"][3] = -0.2;
  EXPECT_EQ(load_error(document),
            "m.json: params.thresholds[3]: PI threshold r[3] = -0.2 must be > r[2] = 0.7");

  document = pi_document();
  document["params"]["weights"][2] = "x";
  EXPECT_EQ(load_error(document), "m.json: params.weights[2]: expected a number, got string \"x\"");

  document = pi_document();
  document["params"]["wieghts"] = {1.0};
  EXPECT_EQ(load_error(document),
            "m.json: params.wieghts: unknown field (known: thresholds, weights, offset)");

  document = pi_document();
  document["extra"] = 1;
  EXPECT_NE(load_error(document).find("m.json: extra: unknown field"), std::string::npos);

  document = pi_document();
  document["model"] = "nope";
  EXPECT_NE(load_error(document).find("m.json: unknown model 'nope'"), std::string::npos);

  document = pi_document();
  document["version"] = 2;
  EXPECT_EQ(load_error(document),
            "m.json: version: 2 is not supported (this library reads version 1)");

  document = pi_document();
  document.erase("params");
  EXPECT_EQ(load_error(document), "m.json: params: missing field");

  document = pi_document();
  document["params"].erase("weights");
  EXPECT_EQ(load_error(document), "m.json: params.weights: missing field");

  document = pi_document();
  document["state"] = {{"play", {0.0, 0.0, 1.0, 0.0}}};
  EXPECT_NE(load_error(document).find("m.json: state.play: PI state w[2] = 1 and w[1] = 0"),
            std::string::npos);

  document = pi_document();
  document["state"] = {{"play", {0.0, 0.0}}};
  EXPECT_NE(load_error(document).find("m.json: state.play: PI state w has 2 values"),
            std::string::npos);

  EXPECT_EQ(load_error(nlohmann::json::array()), "m.json: expected a JSON object, got an array");
}

TEST(ModelFile, InverseStartsConsistentWithTheStoredState) {
  auto model = model_from_json(pi_document(), "memory");
  std::vector<double> history(300);
  model->simulate(test::random_walk(300, 5), history);
  const auto targets = test::pi_check_signal();
  auto inverse = model->inverse({});
  std::vector<double> inputs(targets.size());
  EXPECT_TRUE(inverse->invert(targets, inputs).ok());
  std::vector<double> output(inputs.size());
  model->simulate(inputs, output);
  for (std::size_t k = 0; k < targets.size(); ++k)
    ASSERT_NEAR(output[k], targets[k], 1e-12) << k;
}

TEST(ModelFile, ModelsWithoutInverseSayWhy) {
  auto document = pi_document();
  document["params"]["weights"][0] = -0.1;
  auto model = model_from_json(document, "memory");
  EXPECT_FALSE(model->has_inverse());
  EXPECT_HYST_ERROR(model->inverse({}), "PI weight p[0] = -0.1 must be > 0");
}

// y[k] = v[k] + 2 y[k-1] (no network, unit scales): from rest with v = 1 the output is
// 2^(k+1) - 1, first beyond the bound of 1000 output scales at k = 9 (1023).
TEST(ModelFile, RunawaySimulationIsAnErrorWithItsSample) {
  const nlohmann::json params = {{"input_lags", 0},
                                 {"output_lags", 1},
                                 {"play_thresholds", nlohmann::json::array()},
                                 {"hidden_sizes", {1}},
                                 {"weights", {0, 0, 0, 0, 0, 1, 2}}};
  auto model = ModelRegistry::builtin().find("narx").create(params, nullptr);
  const std::vector<double> input(9, 1.0);
  std::vector<double> output(input.size());
  model->simulate(input, output);
  EXPECT_EQ(output.back(), 511.0);
  model->reset();
  const std::vector<double> longer(12, 1.0);
  output.resize(longer.size());
  EXPECT_HYST_ERROR(model->simulate(longer, output),
                    "the simulation ran away at sample 9 (input 1): the output 1023 is beyond "
                    "+-1000 (1000 output scales");
  // Run long enough to overflow (2^1025 is inf): the first sample beyond the bound is named,
  // not the overflow a thousand samples later.
  model->reset();
  const std::vector<double> overflowing(1100, 1.0);
  output.resize(overflowing.size());
  EXPECT_HYST_ERROR(model->simulate(overflowing, output), "the simulation ran away at sample 9");
}

}  // namespace
}  // namespace hyst
