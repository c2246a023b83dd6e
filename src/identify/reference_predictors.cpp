#include "hyst/identify/reference_predictors.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

struct Scaling {
  double centre = 0.0;
  double scale = 1.0;  // 1 for constant data, so that nothing divides by zero
};

Scaling scaling_of(std::span<const double> values) {
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  const double half_range = 0.5 * (*highest - *lowest);
  return {0.5 * (*highest + *lowest), half_range > 0.0 ? half_range : 1.0};
}

Eigen::VectorXd least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  return a.colPivHouseholderQr().solve(b);
}

ReferenceScore scored(std::string name, std::span<const double> measured,
                      std::vector<double> predicted) {
  ReferenceScore score;
  score.name = std::move(name);
  score.validation = error_metrics(measured, predicted);  // throws for a diverged free run
  score.predicted = std::move(predicted);
  return score;
}

}  // namespace

std::vector<double> predict_mean(std::span<const double> fit_output, std::size_t samples) {
  require_not_empty(fit_output.size(), "fit_output");
  const double sum = std::accumulate(fit_output.begin(), fit_output.end(), 0.0);
  return std::vector<double>(samples, sum / static_cast<double>(fit_output.size()));
}

std::vector<double> predict_hold(std::span<const double> fit_output, std::size_t samples) {
  require_not_empty(fit_output.size(), "fit_output");
  return std::vector<double>(samples, fit_output.back());
}

std::vector<double> predict_polynomial(std::span<const double> fit_input,
                                       std::span<const double> fit_output,
                                       std::span<const double> held_input, std::size_t degree) {
  require_same_size(fit_input.size(), "fit_input", fit_output.size(), "fit_output");
  const std::size_t coefficients = degree + 1;
  if (fit_input.size() < coefficients) {
    throw Error(
        fmt::format("polynomial of degree {}: {} fit samples, fewer than its {} "
                    "coefficients",
                    degree, fit_input.size(), coefficients));
  }
  const auto [lowest, highest] = std::minmax_element(fit_input.begin(), fit_input.end());
  if (!(*highest > *lowest)) throw Error("polynomial y(v): the fit part's input is constant");
  // Powers of the input mapped onto [-1, 1]: a well-conditioned Vandermonde matrix.
  const Scaling v = scaling_of(fit_input);
  const auto rows = static_cast<Eigen::Index>(fit_input.size());
  Eigen::MatrixXd a(rows, static_cast<Eigen::Index>(coefficients));
  Eigen::VectorXd b(rows);
  for (Eigen::Index k = 0; k < rows; ++k) {
    const double t = (fit_input[static_cast<std::size_t>(k)] - v.centre) / v.scale;
    double power = 1.0;
    for (Eigen::Index j = 0; j < a.cols(); ++j, power *= t)
      a(k, j) = power;
    b(k) = fit_output[static_cast<std::size_t>(k)];
  }
  const Eigen::VectorXd c = least_squares(a, b);
  std::vector<double> predicted(held_input.size());
  for (std::size_t k = 0; k < held_input.size(); ++k) {
    const double t = (held_input[k] - v.centre) / v.scale;
    double y = 0.0;
    for (Eigen::Index j = c.size(); j-- > 0;)
      y = y * t + c(j);
    predicted[k] = y;
  }
  return predicted;
}

ArxCoefficients fit_arx(std::span<const double> fit_input, std::span<const double> fit_output,
                        std::size_t na, std::size_t nb) {
  require_same_size(fit_input.size(), "fit_input", fit_output.size(), "fit_output");
  if (na == 0 || nb == 0) {
    throw Error(fmt::format("ARX({},{}): both orders must be >= 1", na, nb), "arx orders");
  }
  const std::size_t first = std::max(na, nb - 1);  // first sample with a full history
  const std::size_t coefficients = na + nb + 1;
  if (fit_input.size() < first + coefficients) {
    throw Error(
        fmt::format("ARX({},{}): {} fit samples give fewer equations than its {} "
                    "coefficients",
                    na, nb, fit_input.size(), coefficients));
  }
  const Scaling v = scaling_of(fit_input);
  const Scaling y = scaling_of(fit_output);
  const auto rows = static_cast<Eigen::Index>(fit_input.size() - first);
  Eigen::MatrixXd a(rows, static_cast<Eigen::Index>(coefficients));
  Eigen::VectorXd b(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const std::size_t k = first + static_cast<std::size_t>(r);
    Eigen::Index column = 0;
    for (std::size_t i = 1; i <= na; ++i)
      a(r, column++) = (fit_output[k - i] - y.centre) / y.scale;
    for (std::size_t j = 0; j < nb; ++j)
      a(r, column++) = (fit_input[k - j] - v.centre) / v.scale;
    a(r, column) = 1.0;
    b(r) = (fit_output[k] - y.centre) / y.scale;
  }
  const Eigen::VectorXd c = least_squares(a, b);
  // Back to the data's units: y = sum a_i y[k-i] + sum (sy/sv) b_j v[k-j] + offset.
  ArxCoefficients arx;
  double offset = y.centre + y.scale * c(static_cast<Eigen::Index>(na + nb));
  for (std::size_t i = 0; i < na; ++i) {
    arx.a.push_back(c(static_cast<Eigen::Index>(i)));
    offset -= arx.a.back() * y.centre;
  }
  for (std::size_t j = 0; j < nb; ++j) {
    arx.b.push_back(c(static_cast<Eigen::Index>(na + j)) * y.scale / v.scale);
    offset -= arx.b.back() * v.centre;
  }
  arx.offset = offset;
  return arx;
}

std::vector<double> simulate_arx(const ArxCoefficients& arx, std::span<const double> fit_input,
                                 std::span<const double> fit_output,
                                 std::span<const double> held_input) {
  require_same_size(fit_input.size(), "fit_input", fit_output.size(), "fit_output");
  const std::size_t na = arx.a.size();
  const std::size_t nb = arx.b.size();
  if (fit_input.size() < std::max(na, nb)) {
    throw Error(fmt::format("ARX({},{}): a fit part of {} samples is shorter than the history", na,
                            nb, fit_input.size()));
  }
  // The record as one sequence: the fit part's tail, then the free-run part.
  const std::size_t history = std::max(na, nb);
  std::vector<double> v(fit_input.end() - static_cast<std::ptrdiff_t>(history), fit_input.end());
  std::vector<double> y(fit_output.end() - static_cast<std::ptrdiff_t>(history), fit_output.end());
  v.insert(v.end(), held_input.begin(), held_input.end());
  y.resize(v.size());
  for (std::size_t k = history; k < v.size(); ++k) {
    double next = arx.offset;
    for (std::size_t i = 1; i <= na; ++i)
      next += arx.a[i - 1] * y[k - i];
    for (std::size_t j = 0; j < nb; ++j)
      next += arx.b[j] * v[k - j];
    y[k] = next;
  }
  return {y.begin() + static_cast<std::ptrdiff_t>(history), y.end()};
}

std::vector<ReferenceScore> reference_predictions(std::span<const double> input,
                                                  std::span<const double> output,
                                                  const DataSplit& split,
                                                  const ReferenceOptions& options) {
  require_same_size(input.size(), "input", output.size(), "output");
  if (!split.has_validation() || split.fit_size() == 0 || split.validation_end > input.size() ||
      split.fit_end > split.validation_begin) {
    throw Error(
        fmt::format("reference predictors: the split (fit {}..{}, held out {}..{}) needs "
                    "a fit part and a held-out part within the {} samples",
                    split.fit_begin, split.fit_end, split.validation_begin, split.validation_end,
                    input.size()));
  }
  return reference_predictions_on_record(
      input.subspan(split.fit_begin, split.fit_size()),
      output.subspan(split.fit_begin, split.fit_size()),
      input.subspan(split.validation_begin, split.validation_size()),
      output.subspan(split.validation_begin, split.validation_size()), options);
}

std::vector<ReferenceScore> reference_predictions_on_record(std::span<const double> fit_input,
                                                            std::span<const double> fit_output,
                                                            std::span<const double> held_input,
                                                            std::span<const double> held_output,
                                                            const ReferenceOptions& options) {
  require_same_size(fit_input.size(), "fit input", fit_output.size(), "fit output");
  require_same_size(held_input.size(), "held-out input", held_output.size(), "held-out output");
  if (fit_input.empty() || held_input.empty()) {
    throw Error(
        fmt::format("reference predictors: {} fit and {} held-out samples; both must be "
                    "> 0",
                    fit_input.size(), held_input.size()));
  }
  const std::size_t held = held_input.size();
  std::vector<ReferenceScore> scores;
  const auto add = [&](std::string name, const auto& predict) {
    try {
      auto predicted = predict();
      if (options.align_first_sample) {
        const double shift = held_output.front() - predicted.front();
        for (double& value : predicted)
          value += shift;
      }
      scores.push_back(scored(name, held_output, std::move(predicted)));
    } catch (const std::exception& error) {
      scores.push_back({std::move(name), std::nullopt, error.what(), {}});
    }
  };
  add("mean", [&] { return predict_mean(fit_output, held); });
  add("last value held", [&] { return predict_hold(fit_output, held); });
  add(fmt::format("polynomial y(v), degree {}", options.polynomial_degree), [&] {
    return predict_polynomial(fit_input, fit_output, held_input, options.polynomial_degree);
  });
  if (options.time_series) {
    add(fmt::format("ARX({},{})", options.arx_outputs, options.arx_inputs), [&] {
      const auto arx = fit_arx(fit_input, fit_output, options.arx_outputs, options.arx_inputs);
      auto predicted = simulate_arx(arx, fit_input, fit_output, held_input);
      if (!std::all_of(predicted.begin(), predicted.end(),
                       [](double y) { return std::isfinite(y); })) {
        throw Error("the fitted ARX model diverges in free run");
      }
      return predicted;
    });
  }
  return scores;
}

const ReferenceScore* best_reference(const std::vector<ReferenceScore>& references) {
  const ReferenceScore* best = nullptr;
  for (const auto& reference : references) {
    if (!reference.validation) continue;
    if (best == nullptr || reference.validation->nrmse_percent < best->validation->nrmse_percent) {
      best = &reference;
    }
  }
  return best;
}

}  // namespace hyst
