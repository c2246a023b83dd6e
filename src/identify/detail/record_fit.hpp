#pragma once
// Fit of a rate-independent scalar model (Bouc-Wen, Duhem, backlash-like) to one input/output
// record: the residuals of a free-run simulation from the first sample, optionally with the last
// part of the record held out for validation. The kernel gives, for any scalar type T,
//   template <class T> bool valid(const T* q) const;            // parameter combination admissible
//   template <class T> T initial(const T* q, double v0, double y0) const;  // internal state
//   template <class T> T advance(const T* q, T state, double v_prev, double v) const;
//   template <class T> T output(const T* q, const T& state, double v) const;

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <span>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"
#include "multistart_fit.hpp"

namespace hyst::detail {

template <class Kernel>
class RecordError {
 public:
  RecordError(Kernel kernel, std::span<const double> input, std::span<const double> output,
              double y_scale)
      : kernel_(kernel), input_(input), output_(output), y_scale_(y_scale) {}
  std::size_t residuals() const { return output_.size(); }

  template <class T>
  bool operator()(const T* q, T* residuals) const {
    if (!kernel_.valid(q)) return false;
    T state = kernel_.initial(q, input_.front(), output_.front());
    for (std::size_t k = 0; k < input_.size(); ++k) {
      if (k > 0) state = kernel_.advance(q, state, input_[k - 1], input_[k]);
      residuals[k] = (kernel_.output(q, state, input_[k]) - output_[k]) / y_scale_;
    }
    return true;
  }
  // The same simulation in double over any record (for the metrics).
  std::vector<double> simulate(const double* q, std::span<const double> input, double y0) const {
    std::vector<double> y(input.size());
    double state = kernel_.initial(q, input.front(), y0);
    for (std::size_t k = 0; k < input.size(); ++k) {
      if (k > 0) state = kernel_.advance(q, state, input[k - 1], input[k]);
      y[k] = kernel_.output(q, state, input[k]);
    }
    return y;
  }

 private:
  Kernel kernel_;
  std::span<const double> input_;
  std::span<const double> output_;
  double y_scale_;
};

struct RecordFitOutcome {
  FitReport report;
  std::size_t best_start = 0;
};

// Validates the record, fits on its first part and fills the report (model name and method are
// the caller's). `q` receives the fitted parameters.
template <std::size_t N, class Kernel>
RecordFitOutcome fit_record(const Kernel& kernel, std::span<const double> input,
                            std::span<const double> output, double validate_fraction,
                            const std::vector<std::array<double, N>>& starts,
                            const MultistartOptions<N>& options, std::string_view what,
                            std::array<double, N>& q) {
  const auto clock_start = std::chrono::steady_clock::now();
  require_same_size(input.size(), "input", output.size(), "output");
  require_finite(input, "input");
  require_finite(output, "output");
  if (!(validate_fraction >= 0.0 && validate_fraction < 1.0)) {
    throw Error(fmt::format("validate_fraction = {} must be in [0, 1)", validate_fraction),
                "validate_fraction");
  }
  const auto n_fit = static_cast<std::size_t>(
      std::round(static_cast<double>(input.size()) * (1.0 - validate_fraction)));
  if (n_fit < 2 * N) {
    throw Error(fmt::format("{} fit needs at least {} samples in the fit part, got {}", what, 2 * N,
                            n_fit));
  }
  double sum = 0.0;
  for (std::size_t k = 0; k < n_fit; ++k)
    sum += output[k] * output[k];
  const double y_scale = std::sqrt(sum / static_cast<double>(n_fit));
  if (!(y_scale > 0.0)) throw Error(fmt::format("{} fit: the output is zero", what), "output");
  const RecordError<Kernel> functor(kernel, input.first(n_fit), output.first(n_fit), y_scale);
  const auto result = multistart_fit(functor, starts, options, what);
  q = result.q;
  FitReport report = report_of(result, y_scale, N - options.fixed.size(), "", "");
  const auto simulated = functor.simulate(q.data(), input, output.front());
  report.fit = error_metrics(output.first(n_fit), std::span(simulated).first(n_fit));
  if (n_fit < input.size()) {
    report.validation = error_metrics(output.subspan(n_fit), std::span(simulated).subspan(n_fit));
  }
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return {report, result.best_start};
}

// Span and range of a record, for data-derived starts and bounds.
struct RecordScale {
  double input_span = 1.0;
  double output_span = 1.0;
  double slope = 1.0;  // output span / input span
};

inline RecordScale record_scale(std::span<const double> input, std::span<const double> output) {
  require_not_empty(input.size(), "input");
  require_not_empty(output.size(), "output");
  const auto [vlo, vhi] = std::minmax_element(input.begin(), input.end());
  const auto [ylo, yhi] = std::minmax_element(output.begin(), output.end());
  RecordScale s;
  s.input_span = *vhi - *vlo;
  s.output_span = *yhi - *ylo;
  if (!(s.input_span > 0.0)) throw Error("the input is constant", "input");
  if (!(s.output_span > 0.0)) throw Error("the output is constant", "output");
  s.slope = s.output_span / s.input_span;
  return s;
}

}  // namespace hyst::detail
