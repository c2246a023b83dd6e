// The progress of a fit with several starts (FitRequest::progress): every fitter on the
// multistart driver tells each start and the refinement, in order, and ends with done == total;
// a fit without starts (PI: one NNLS) never calls it.

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

struct Told {
  std::size_t done;
  std::size_t total;
  std::string current;
};

std::vector<Told> fit_and_record(const std::string& model, const nlohmann::json& options) {
  std::vector<double> v(300);
  std::vector<double> y(300);
  for (std::size_t k = 0; k < v.size(); ++k) {
    v[k] = std::sin(0.05 * static_cast<double>(k));
    y[k] = v[k] + 0.2 * std::cos(0.05 * static_cast<double>(k));  // a loop
  }
  std::vector<Told> told;
  FitRequest request;
  request.input = v;
  request.output = y;
  request.options = options;
  request.progress = [&](const Progress& progress) {
    EXPECT_EQ(progress.task, "starts");
    told.push_back({progress.done, progress.total, std::string(progress.current)});
  };
  fit_model(ModelRegistry::builtin().find(model), request);
  return told;
}

class FitProgress : public testing::TestWithParam<std::string> {};

TEST_P(FitProgress, EveryStartIsToldInOrderAndTheLastReportIsComplete) {
  const nlohmann::json options =
      GetParam() == "gpi"    ? nlohmann::json{{"max_iterations", 50}}
      : GetParam() == "narx" ? nlohmann::json{{"max_iterations", 3}, {"starts", 2}}
                             : nlohmann::json{{"max_iterations", 10}, {"global_evaluations", 0}};
  const auto told = fit_and_record(GetParam(), options);
  ASSERT_GE(told.size(), 2u);
  const std::size_t total = told.front().total;
  for (std::size_t k = 0; k < told.size(); ++k) {
    EXPECT_EQ(told[k].total, total);
    if (k > 0) {
      EXPECT_GE(told[k].done, told[k - 1].done);
    }
  }
  EXPECT_EQ(told.front().done, 0u);
  EXPECT_FALSE(told.front().current.empty());
  EXPECT_EQ(told.back().done, total);
  EXPECT_TRUE(told.back().current.empty());
}

INSTANTIATE_TEST_SUITE_P(MultistartFitters, FitProgress,
                         testing::Values("gpi", "bouc_wen", "duhem", "narx"));

TEST(FitProgressOfOneSolve, IsNeverCalled) {
  EXPECT_TRUE(fit_and_record("pi", nlohmann::json::object()).empty());
}

}  // namespace
}  // namespace hyst
