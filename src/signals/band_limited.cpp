#include "hyst/signals/band_limited.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include <unsupported/Eigen/FFT>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void check_factor(std::size_t factor) {
  if (factor < 1 || factor > 1000) {
    throw Error(fmt::format("upsampling factor = {} must be in [1, 1000]", factor), "factor");
  }
}

double bessel_i0(double x) {
  // Power series; converges quickly for the window's arguments (x <= 10).
  double sum = 1.0;
  double term = 1.0;
  for (int k = 1; k < 60; ++k) {
    term *= (x / (2.0 * k)) * (x / (2.0 * k));
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return sum;
}

}  // namespace

std::vector<double> upsample_periodic(std::span<const double> one_period, std::size_t factor) {
  check_factor(factor);
  require_not_empty(one_period.size(), "input");
  require_finite(one_period, "input");
  const std::size_t n = one_period.size();
  const std::size_t fine = n * factor;
  Eigen::FFT<double> fft;
  std::vector<double> x(one_period.begin(), one_period.end());
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, x);
  std::vector<std::complex<double>> padded(fine, {0.0, 0.0});
  const std::size_t half = n / 2;
  for (std::size_t i = 0; i <= half; ++i)
    padded[i] = spectrum[i];
  for (std::size_t i = 1; i <= (n - 1) / 2; ++i)
    padded[fine - i] = spectrum[n - i];
  if (n % 2 == 0 && factor > 1) {
    // The Nyquist bin of the coarse grid stands for a cosine: half on each side.
    padded[half] = 0.5 * spectrum[half];
    padded[fine - half] = 0.5 * spectrum[half];
  }
  std::vector<double> result;
  fft.inv(result, padded);
  for (double& value : result)
    value *= static_cast<double>(factor);
  return result;
}

std::vector<double> upsample_band_limited(std::span<const double> input, std::size_t factor,
                                          std::size_t half_width) {
  check_factor(factor);
  if (half_width < 1 || half_width > 1000) {
    throw Error(fmt::format("interpolation half-width = {} must be in [1, 1000]", half_width),
                "half_width");
  }
  require_not_empty(input.size(), "input");
  require_finite(input, "input");
  constexpr double kKaiserBeta = 10.0;
  const double window_norm = bessel_i0(kKaiserBeta);
  const auto width = static_cast<std::ptrdiff_t>(half_width);
  // kernels[p][j]: weight of input sample k + j - width + 1 for fine sample k * factor + p.
  std::vector<std::vector<double>> kernels(factor, std::vector<double>(2 * half_width));
  for (std::size_t p = 0; p < factor; ++p) {
    const double frac = static_cast<double>(p) / static_cast<double>(factor);
    double sum = 0.0;
    for (std::ptrdiff_t j = 0; j < 2 * width; ++j) {
      const double t = frac - static_cast<double>(j - width + 1);  // distance to the sample
      const double u = t / static_cast<double>(width);
      double weight = 0.0;
      if (std::abs(u) < 1.0) {
        const double sinc =
            t == 0.0 ? 1.0 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t);
        weight = sinc * bessel_i0(kKaiserBeta * std::sqrt(1.0 - u * u)) / window_norm;
      }
      kernels[p][static_cast<std::size_t>(j)] = weight;
      sum += weight;
    }
    for (double& w : kernels[p])
      w /= sum;
  }
  const auto n = static_cast<std::ptrdiff_t>(input.size());
  std::vector<double> result(input.size() * factor);
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    for (std::size_t p = 0; p < factor; ++p) {
      const auto& kernel = kernels[p];
      double value = 0.0;
      for (std::ptrdiff_t j = 0; j < 2 * width; ++j) {
        const std::ptrdiff_t index = k + j - width + 1;
        if (index >= 0 && index < n) {
          value += kernel[static_cast<std::size_t>(j)] * input[static_cast<std::size_t>(index)];
        }
      }
      result[static_cast<std::size_t>(k) * factor + p] = value;
    }
  }
  return result;
}

}  // namespace hyst
