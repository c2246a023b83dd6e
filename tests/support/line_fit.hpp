#pragma once
// Least-squares line through (x, y) and its largest residual, for tests of linearity.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace hyst::test {

//! Fits y = slope x + intercept; returns the largest |y - (slope x + intercept)|.
inline double line_fit_max_residual(const std::vector<double>& x, const std::vector<double>& y,
                                    double& slope, double& intercept) {
  const auto n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxy += (x[k] - mx) * (y[k] - my);
    sxx += (x[k] - mx) * (x[k] - mx);
  }
  slope = sxy / sxx;
  intercept = my - slope * mx;
  double worst = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    worst = std::max(worst, std::abs(y[k] - (slope * x[k] + intercept)));
  return worst;
}

}  // namespace hyst::test
