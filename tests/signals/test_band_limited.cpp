// Band-limited upsampling: exact for a periodic multisine (second algorithm: the analytic signal),
// accurate inside the record for a windowed sinc, input samples kept.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/signals/band_limited.hpp"

namespace hyst {
namespace {

double signal(double t) {  // t in input samples; period 256, content below 0.2 x Nyquist
  return std::sin(2 * std::numbers::pi * 3 * t / 256) +
         0.5 * std::cos(2 * std::numbers::pi * 20 * t / 256 + 0.3);
}

TEST(BandLimited, PeriodicUpsamplingIsExactForAMultisine) {
  std::vector<double> x(256);
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = signal(static_cast<double>(k));
  const auto fine = upsample_periodic(x, 7);
  ASSERT_EQ(fine.size(), 7 * x.size());
  for (std::size_t j = 0; j < fine.size(); ++j)
    EXPECT_NEAR(fine[j], signal(static_cast<double>(j) / 7.0), 1e-12);
}

TEST(BandLimited, WindowedSincIsAccurateAwayFromTheEnds) {
  std::vector<double> x(1024);
  for (std::size_t k = 0; k < x.size(); ++k)
    x[k] = signal(static_cast<double>(k));
  const auto fine = upsample_band_limited(x, 5, 64);
  for (std::size_t j = 5 * 100; j < 5 * 900; ++j)
    EXPECT_NEAR(fine[j], signal(static_cast<double>(j) / 5.0), 2e-4);
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_NEAR(fine[5 * k], x[k], 1e-12);
}

TEST(BandLimited, RejectsBadArguments) {
  const std::vector<double> x{1.0, 2.0};
  EXPECT_HYST_ERROR(upsample_periodic(x, 0), "upsampling factor = 0 must be in [1, 1000]");
  EXPECT_HYST_ERROR(upsample_band_limited(x, 2, 0), "half-width = 0");
  const std::vector<double> bad{1.0, NAN};
  EXPECT_HYST_ERROR(upsample_periodic(bad, 2), "input[1] = nan is not finite");
}

}  // namespace
}  // namespace hyst
