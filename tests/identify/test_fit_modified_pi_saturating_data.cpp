// The modified PI fit on a measured loop whose output saturates
// (../shared/data/bh_loops_jamodel, amorphous alloy B(H)): the equation-error fit flattens the
// inverse dead-zone map where B saturates, so the forward map is nearly vertical there. With the
// fitted output limits the prediction stays within the measured range instead of growing without
// bound (an unclamped fit predicted errors of about 5e4 T on this record).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_modified_prandtl_ishlinskii.hpp"
#include "hyst/io/mat_file.hpp"

namespace hyst {
namespace {

namespace fs = std::filesystem;

TEST(FitModifiedPiSaturatingData, PredictionStaysWithinTheMeasuredRange) {
  const fs::path dir = fs::path(HYST_SHARED_DATA_DIR) / "bh_loops_jamodel";
  if (!fs::exists(dir / "H_amorf.mat")) GTEST_SKIP() << dir << " not found";
  const auto h = io::read_mat_vector(dir / "H_amorf.mat", "HmeasT");
  const auto b = io::read_mat_vector(dir / "B_amorf.mat", "BmeasT");
  ASSERT_EQ(h.size(), b.size());
  // Fit on the first three quarters, predict the whole record from the fit's initial state.
  const std::size_t fitted = 3 * h.size() / 4;
  const auto fit =
      fit_modified_prandtl_ishlinskii(std::span(h).first(fitted), std::span(b).first(fitted));
  auto state = fit.initial_state;
  const auto predicted = simulate(fit.model, state, h);
  const auto [b_min, b_max] = std::minmax_element(b.begin(), b.end());
  double worst = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    ASSERT_TRUE(std::isfinite(predicted[k])) << "k = " << k;
    worst = std::max(worst, std::abs(predicted[k] - b[k]));
  }
  // The limits are the fit part's extremes, so no error can exceed the measured range.
  EXPECT_LE(worst, *b_max - *b_min);
}

}  // namespace
}  // namespace hyst
