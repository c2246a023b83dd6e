// State-space model files: an exact round trip (matrices, state, info), the static gain without
// states, a file written by hand, and an error naming the field for each malformed part.

#include "hyst/registry/state_space_file.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/io/json_text.hpp"

namespace hyst::state_space_file_test {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using nlohmann::json;

// Values whose shortest decimal forms are long, tiny, huge or subnormal.
MatrixXd awkward_matrix(Eigen::Index rows, Eigen::Index cols, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss;
  MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      m(i, j) = gauss(random) / 3.0;
  m(0, 0) = 0.1 + 0.2;
  if (m.size() > 1) m(rows - 1, cols - 1) = std::numeric_limits<double>::denorm_min();
  return m;
}

StateSpace awkward_model() {
  MatrixXd a = awkward_matrix(3, 3, 1) * 0.3;
  a(1, 2) = std::nextafter(0.5, 1.0);
  MatrixXd d = awkward_matrix(2, 2, 4);
  d(0, 1) = -1.7976931348623157e308;
  return StateSpace({a, awkward_matrix(3, 2, 2), awkward_matrix(2, 3, 3), d, 1.0 / 6400.0});
}

void expect_same_model(const StateSpace& loaded, const StateSpace& expected) {
  EXPECT_EQ(loaded.params().a, expected.params().a);
  EXPECT_EQ(loaded.params().b, expected.params().b);
  EXPECT_EQ(loaded.params().c, expected.params().c);
  EXPECT_EQ(loaded.params().d, expected.params().d);
  EXPECT_EQ(loaded.sample_time(), expected.sample_time());
}

// The document of the two-state model of the model tests, with a state.
json two_state_document() {
  return json::parse(R"({
    "model": "state_space", "version": 1,
    "params": {"sample_time": 0.5,
               "a": [[0.5, 0.1], [0, 0.8]], "b": [[1, 0], [0.5, 1]],
               "c": [[1, 2], [0, -1]], "d": [[0.1, 0], [0, 0.2]]},
    "state": {"x": [1, -2]},
    "info": {"note": "by hand"}})");
}

class StateSpaceFileTest : public test::TempFolderTest {};

TEST_F(StateSpaceFileTest, RoundTripIsExact) {
  const auto model = awkward_model();
  const VectorXd x = (VectorXd(3) << 1.0 / 3.0, -0.0, 1e-310).finished();
  const json info = {{"fit", {{"rmse", 0.25}}}};
  const auto path = dir_ / "m.json";
  save_state_space(path, model, x, info);
  const auto loaded = load_state_space(path);
  expect_same_model(loaded.model, model);
  ASSERT_TRUE(loaded.state.has_value());
  EXPECT_EQ(*loaded.state, x);
  EXPECT_TRUE(std::signbit((*loaded.state)[1]));  // -0 stays -0
  EXPECT_EQ(loaded.info, info);
  EXPECT_EQ(entries(), std::vector<std::string>{"m.json"});  // no temporary file left
  const json document = io::parse_json_text(slurp(path), "m.json");
  EXPECT_EQ(document["model"], "state_space");
  EXPECT_EQ(document["version"], 1);
  EXPECT_EQ(document["params"]["a"].size(), 3u);  // rows
  EXPECT_EQ(document["params"]["b"][0].size(), 2u);
}

TEST_F(StateSpaceFileTest, WithoutStateOrInfo) {
  const auto model = awkward_model();
  const json document = state_space_to_json(model);
  EXPECT_FALSE(document.contains("state"));
  EXPECT_FALSE(document.contains("info"));
  const auto path = dir_ / "plain.json";
  save_state_space(path, model);
  const auto loaded = load_state_space(path);
  expect_same_model(loaded.model, model);
  EXPECT_FALSE(loaded.state.has_value());
  EXPECT_EQ(loaded.info, json::object());
}

TEST_F(StateSpaceFileTest, StaticGainWithoutStates) {
  // n = 0: "a": [] and "b": [] (no rows), "c": one empty row per output; D tells m.
  const MatrixXd d = (MatrixXd(2, 3) << 1.0, 2.0, 3.0, -4.0, 0.5, 0.0).finished();
  const StateSpace model({MatrixXd(0, 0), MatrixXd(0, 3), MatrixXd(2, 0), d, 0.01});
  const json document = state_space_to_json(model, VectorXd(0));
  EXPECT_EQ(document["params"]["a"], json::array());
  EXPECT_EQ(document["params"]["b"], json::array());
  EXPECT_EQ(document["params"]["c"], json::parse("[[], []]"));
  EXPECT_EQ(document["state"]["x"], json::array());
  const auto path = dir_ / "gain.json";
  save_state_space(path, model, VectorXd(0));
  const auto loaded = load_state_space(path);
  EXPECT_EQ(loaded.model.order(), 0u);
  EXPECT_EQ(loaded.model.inputs(), 3u);
  EXPECT_EQ(loaded.model.outputs(), 2u);
  EXPECT_EQ(loaded.model.params().d, d);
  EXPECT_EQ(loaded.state->size(), 0);
}

TEST(StateSpaceFileJson, ReadsADocumentWrittenByHand) {
  const auto file = state_space_from_json(two_state_document(), "m.json");
  EXPECT_EQ(file.model.order(), 2u);
  EXPECT_EQ(file.model.inputs(), 2u);
  EXPECT_EQ(file.model.outputs(), 2u);
  EXPECT_EQ(file.model.params().a(0, 1), 0.1);
  EXPECT_EQ(file.model.params().b(1, 0), 0.5);
  EXPECT_EQ(file.model.params().c(1, 1), -1.0);
  EXPECT_EQ(file.model.params().d(1, 1), 0.2);
  EXPECT_EQ(file.model.sample_time(), 0.5);
  EXPECT_EQ(*file.state, (VectorXd(2) << 1.0, -2.0).finished());
  EXPECT_EQ(file.info["note"], "by hand");
}

// The error of the two-state document changed by `change`.
std::string error_of(void (*change)(json&)) {
  json document = two_state_document();
  change(document);
  try {
    state_space_from_json(document, "m.json");
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(StateSpaceFileJson, NamesTheFieldOfEachMalformedPart) {
  const std::vector<std::pair<void (*)(json&), std::string>> cases{
      {[](json& d) { d = json::array(); }, "m.json: expected a JSON object, got an array"},
      {[](json& d) { d.erase("model"); }, "m.json: model: missing field"},
      {[](json& d) { d["model"] = "pi"; },
       "m.json: model: \"pi\" is not a state-space model file (expected \"state_space\")"},
      {[](json& d) { d["model"] = 3; }, "m.json: model: expected a string, got number 3"},
      {[](json& d) { d.erase("version"); }, "m.json: version: missing field"},
      {[](json& d) { d["version"] = 2; },
       "m.json: version: 2 is not supported (this library reads version 1)"},
      {[](json& d) { d.erase("params"); }, "m.json: params: missing field"},
      {[](json& d) { d["params"] = json::array(); },
       "m.json: params: expected an object, got an array"},
      {[](json& d) { d["extra"] = 1; }, "m.json: extra: unknown field (known: model, version,"},
      {[](json& d) { d["info"] = "x"; }, "m.json: info: expected an object, got string \"x\""},
      {[](json& d) { d["params"].erase("c"); }, "m.json: params.c: missing field"},
      {[](json& d) { d["params"].erase("sample_time"); },
       "m.json: params.sample_time: missing field"},
      {[](json& d) { d["params"]["sample_time"] = "1 ms"; },
       "m.json: params.sample_time: expected a number, got string \"1 ms\""},
      {[](json& d) { d["params"]["sample_time"] = 0; },
       "m.json: params.sample_time: state space: sample time Ts = 0 must be finite and > 0"},
      {[](json& d) { d["params"]["e"] = json::array(); },
       "m.json: params.e: unknown field (known: sample_time, a, b, c, d)"},
      {[](json& d) { d["params"]["d"] = 5; },
       "m.json: params.d: expected an array of rows, got number 5"},
      {[](json& d) { d["params"]["b"][0] = 3; },
       "m.json: params.b[0]: expected a row (an array of numbers), got number 3"},
      {[](json& d) { d["params"]["a"][1] = {1}; },
       "m.json: params.a[1]: 1 numbers, but row 0 has 2; every row must be as long"},
      {[](json& d) { d["params"]["b"][1][0] = "x"; },
       "m.json: params.b[1][0]: expected a number, got string \"x\""},
      {[](json& d) { d["params"]["c"][0][1] = nullptr; },
       "m.json: params.c[0][1]: expected a number, got null"},
      {[](json& d) {
         d["params"]["b"].push_back({1, 2});
       },
       "m.json: params.b: state space: B has 3 rows, A has 2"},
      {[](json& d) {
         d["params"]["c"] = {{1, 2, 3}, {4, 5, 6}};
       },
       "m.json: params.c: state space: C has 3 columns, A has 2"},
      {[](json& d) {
         d["params"]["d"] = {{1, 2}};
       },
       "m.json: params.d: state space: D has 1 rows, C has 2"},
      {[](json& d) {
         d["params"]["a"] = {{1, 2}};
       },
       "m.json: params.a: state space: A is 1 x 2; it must be square"},
      {[](json& d) {
         d["state"] = {{"x", {1, 2, 3}}};
       },
       "m.json: state.x: state space: the state x has 3 values; the model has 2 states"},
      {[](json& d) {
         d["state"] = {{"x", {true, 2}}};
       },
       "m.json: state.x[0]: expected a number, got boolean true"},
      {[](json& d) { d["state"] = json::object(); }, "m.json: state.x: missing field"},
      {[](json& d) { d["state"]["y"] = 1; }, "m.json: state.y: unknown field (known: x)"},
      {[](json& d) { d["params"]["a"] = json::array(); },
       "m.json: params.b: state space: B has 2 rows, A has 0"},
  };
  for (const auto& [change, expected] : cases) {
    const auto message = error_of(change);
    EXPECT_NE(message.find(expected), std::string::npos)
        << "message: \"" << message << "\"\nexpected to contain: \"" << expected << "\"";
  }
}

TEST(StateSpaceFileJson, StaticGainNeedsOneEmptyRowOfCPerOutput) {
  json document = json::parse(R"({"model": "state_space", "version": 1,
    "params": {"sample_time": 1, "a": [], "b": [], "c": [[], []], "d": [[1], [2]]}})");
  EXPECT_EQ(state_space_from_json(document, "g.json").model.outputs(), 2u);
  document["params"]["c"] = json::array();
  EXPECT_HYST_ERROR(state_space_from_json(document, "g.json"),
                    "g.json: params.d: state space: D has 2 rows, C has 0");
}

TEST_F(StateSpaceFileTest, FileErrorsNameTheFile) {
  EXPECT_HYST_ERROR(load_state_space(dir_ / "missing.json"), "missing.json");
  const auto path = dir_ / "broken.json";
  std::ofstream(path) << "{\"model\": \"state_space\",";
  EXPECT_HYST_ERROR(load_state_space(path), "broken.json: not valid JSON");
  std::ofstream(path) << two_state_document().dump().replace(0, 1, "{\"version\": 1, ");
  EXPECT_HYST_ERROR(load_state_space(path), "duplicate key 'version'");
  std::ofstream(path, std::ios::trunc) << R"({"model": "state_space", "version": 1})";
  EXPECT_HYST_ERROR(load_state_space(path), (path.string() + ": params: missing field"));
}

TEST_F(StateSpaceFileTest, RefusesToWriteAStateOfTheWrongSize) {
  const auto model = awkward_model();
  EXPECT_HYST_ERROR(save_state_space(dir_ / "m.json", model, VectorXd::Zero(2)),
                    "state space: the state x has 2 values; the model has 3 states");
  EXPECT_TRUE(entries().empty());
}

}  // namespace
}  // namespace hyst::state_space_file_test
