// The reference predictors of the yardstick against analytic expectations: the mean and the held
// value by hand, a cubic recovered exactly by the degree-3 polynomial, a known linear system
// recovered exactly by the ARX least squares and continued exactly in free run.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/test_signals.hpp"
#include "hyst/identify/reference_predictors.hpp"

namespace hyst {
namespace {

TEST(ReferencePredictors, MeanAndHoldByHand) {
  const std::vector<double> fit_output{1.0, 2.0, 6.0};
  EXPECT_EQ(predict_mean(fit_output, 2), (std::vector<double>{3.0, 3.0}));
  EXPECT_EQ(predict_hold(fit_output, 3), (std::vector<double>{6.0, 6.0, 6.0}));
  EXPECT_HYST_ERROR(predict_mean({}, 2), "fit_output");
}

TEST(ReferencePredictors, PolynomialRecoversACubic) {
  const auto cubic = [](double v) { return 0.5 - 2.0 * v + 0.25 * v * v + 0.75 * v * v * v; };
  const auto fit_input = test::random_walk(200, 3);
  std::vector<double> fit_output;
  for (const double v : fit_input)
    fit_output.push_back(cubic(v));
  const std::vector<double> held_input{-1.5, -0.2, 0.0, 0.9, 2.5};  // 2.5: beyond the fit range
  const auto predicted = predict_polynomial(fit_input, fit_output, held_input, 3);
  ASSERT_EQ(predicted.size(), held_input.size());
  for (std::size_t k = 0; k < held_input.size(); ++k)
    EXPECT_NEAR(predicted[k], cubic(held_input[k]), 1e-9) << held_input[k];
  EXPECT_HYST_ERROR(
      predict_polynomial(std::vector<double>{1, 2, 3}, std::vector<double>{1, 2, 3}, held_input, 3),
      "fewer than its 4 coefficients");
  EXPECT_HYST_ERROR(
      predict_polynomial(std::vector<double>(5, 1.0), std::vector<double>(5, 1.0), held_input, 3),
      "input is constant");
}

TEST(ReferencePredictors, ArxRecoversAKnownLinearSystem) {
  // y[k] = 1.2 y[k-1] - 0.5 y[k-2] + 0.8 v[k] - 0.3 v[k-1] + 0.1 (poles 0.6 +- 0.37i: stable).
  const auto v = test::random_walk(600, 11);
  std::vector<double> y(v.size(), 0.0);
  for (std::size_t k = 2; k < v.size(); ++k)
    y[k] = 1.2 * y[k - 1] - 0.5 * y[k - 2] + 0.8 * v[k] - 0.3 * v[k - 1] + 0.1;
  const std::size_t n_fit = 450;
  const std::span<const double> input(v), output(y);
  const auto arx = fit_arx(input.first(n_fit), output.first(n_fit), 2, 2);
  ASSERT_EQ(arx.a.size(), 2u);
  ASSERT_EQ(arx.b.size(), 2u);
  EXPECT_NEAR(arx.a[0], 1.2, 1e-9);
  EXPECT_NEAR(arx.a[1], -0.5, 1e-9);
  EXPECT_NEAR(arx.b[0], 0.8, 1e-9);
  EXPECT_NEAR(arx.b[1], -0.3, 1e-9);
  EXPECT_NEAR(arx.offset, 0.1, 1e-9);
  // Free run from the fit part's end continues the system exactly.
  const auto predicted =
      simulate_arx(arx, input.first(n_fit), output.first(n_fit), input.subspan(n_fit));
  ASSERT_EQ(predicted.size(), v.size() - n_fit);
  for (std::size_t k = 0; k < predicted.size(); ++k)
    EXPECT_NEAR(predicted[k], y[n_fit + k], 1e-8) << k;
  EXPECT_HYST_ERROR(fit_arx(input.first(6), output.first(6), 2, 2), "fewer equations");
  EXPECT_HYST_ERROR(fit_arx(input.first(50), output.first(50), 0, 2), "orders must be >= 1");
}

TEST(ReferencePredictors, EveryReferenceIsScoredOnTheHeldOutPart) {
  // The output holds its last fitted value over the held-out part: "last value held" is exact,
  // the mean of the fit part (0, 1, 2, 3 -> 1.5) is off by 1.5 everywhere.
  const std::vector<double> input{0, 1, 2, 3, 3, 3};
  const std::vector<double> output{0, 1, 2, 3, 3, 4};
  const DataSplit split{0, 4, 4, 6};
  const auto scores = reference_predictions(input, output, split);
  ASSERT_EQ(scores.size(), 4u);
  EXPECT_EQ(scores[0].name, "mean");
  ASSERT_TRUE(scores[0].validation);
  // errors 1.5 and 2.5: RMSE sqrt(4.25), measured range 1 -> NRMSE 100 sqrt(4.25) %.
  EXPECT_NEAR(scores[0].validation->nrmse_percent, 100.0 * std::sqrt(4.25), 1e-12);
  EXPECT_EQ(scores[1].name, "last value held");
  // errors 0 and 1: RMSE sqrt(0.5), range 1.
  EXPECT_NEAR(scores[1].validation->nrmse_percent, 100.0 * std::sqrt(0.5), 1e-12);
  EXPECT_EQ(scores[2].name, "polynomial y(v), degree 3");
  EXPECT_EQ(scores[3].name, "ARX(2,2)");
  EXPECT_FALSE(scores[3].validation);  // 4 fit samples: too few equations
  EXPECT_NE(scores[3].error.find("fewer equations"), std::string::npos) << scores[3].error;
  // The cubic through the 4 fit points is y = v, which predicts 3 and 3: it ties with the held
  // value, and the first of equal scores is the best.
  EXPECT_NEAR(scores[2].validation->nrmse_percent, scores[1].validation->nrmse_percent, 1e-9);
  EXPECT_EQ(best_reference(scores)->name, "last value held");
  ReferenceOptions no_time;
  no_time.time_series = false;
  EXPECT_EQ(reference_predictions(input, output, split, no_time).size(), 3u);
  EXPECT_HYST_ERROR(reference_predictions(input, output, DataSplit{0, 6, 6, 6}),
                    "needs a fit part and a held-out part");
}

}  // namespace
}  // namespace hyst
