#include "hyst/identify/fit_maxwell_slip.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "weight_fit.hpp"

namespace hyst {
namespace {

std::vector<double> slip_grid(const MaxwellSlipFitOptions& options, double range) {
  if (!options.slip_displacements.empty()) {
    const auto& d = options.slip_displacements;
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!std::isfinite(d[i]) || !(d[i] > 0.0) || (i > 0 && !(d[i] > d[i - 1]))) {
        throw Error(fmt::format("Maxwell-slip fit slip displacement D[{}] = {} must be finite, "
                                "> 0 and > the one before",
                                i, d[i]),
                    fmt::format("slip_displacements[{}]", i));
      }
    }
    return d;
  }
  if (options.elements == 0) throw Error("Maxwell-slip fit elements = 0 must be >= 1", "elements");
  std::vector<double> d(options.elements);
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = static_cast<double>(i + 1) * range / (2.0 * static_cast<double>(options.elements + 1));
  }
  return d;
}

MaxwellSlip::Orientation orientation_of(double area) {
  return area < 0.0 ? MaxwellSlip::Orientation::counter_clockwise
                    : MaxwellSlip::Orientation::clockwise;
}

}  // namespace

double enclosed_area(std::span<const double> position, std::span<const double> force) {
  const std::size_t n = std::min(position.size(), force.size());
  double twice_area = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = k + 1 < n ? k + 1 : 0;  // the last term closes the loop
    twice_area += (force[k] + force[next]) * (position[next] - position[k]);
  }
  return 0.5 * twice_area;
}

MaxwellSlipFit fit_maxwell_slip(std::span<const double> position, std::span<const double> force,
                                const MaxwellSlipFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t count =
      options.slip_displacements.empty() ? options.elements : options.slip_displacements.size();
  const auto parts = detail::split_record(position, force, options.validate_fraction,
                                          "Maxwell-slip fit", count + 2);
  const auto slip = slip_grid(options, detail::range_of(parts.fit_input));
  const std::size_t n = slip.size();
  const double area = enclosed_area(parts.fit_input, parts.fit_output);
  const auto orientation = options.orientation.value_or(orientation_of(area));
  const double sign = orientation == MaxwellSlip::Orientation::clockwise ? 1.0 : -1.0;
  const auto m = static_cast<Eigen::Index>(parts.fit_input.size());
  const auto columns = static_cast<Eigen::Index>(n + (options.fit_linear_stiffness ? 1 : 0));
  Eigen::MatrixXd A(m, columns);
  std::vector<double> delta(n, 0.0);
  double previous = parts.fit_input.front();
  for (Eigen::Index k = 0; k < m; ++k) {
    const double x = parts.fit_input[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < n; ++i) {
      delta[i] = std::clamp(delta[i] + x - previous, -slip[i], slip[i]);
      A(k, static_cast<Eigen::Index>(i)) = sign * delta[i];
    }
    if (options.fit_linear_stiffness) A(k, static_cast<Eigen::Index>(n)) = x;
    previous = x;
  }
  const Eigen::Map<const Eigen::VectorXd> y(parts.fit_output.data(), m);
  const auto solution = detail::nnls_with_offset(std::move(A), y, options.fit_offset);

  MaxwellSlip::Params params;
  params.orientation = orientation;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = solution.x[static_cast<Eigen::Index>(i)];
    if (k > 0.0) {
      params.stiffness.push_back(k);
      params.break_away.push_back(k * slip[i]);
    }
  }
  if (params.stiffness.empty()) {
    throw Error(
        fmt::format("Maxwell-slip fit: every element stiffness came out 0 for a {} loop ({}; the "
                    "record encloses the signed area {:.6g}, > 0 clockwise, < 0 "
                    "counter-clockwise): the data show no hysteresis the elements can explain "
                    "in that orientation; try the other orientation or other slip displacements",
                    orientation_name(orientation),
                    options.orientation ? "given" : "detected from the enclosed area", area),
        "orientation");
  }
  params.linear_stiffness = options.fit_linear_stiffness ? solution.x[columns - 1] : 0.0;
  params.offset = solution.offset;
  MaxwellSlipFit result{MaxwellSlip(std::move(params)), {}, {}};
  result.initial_state = result.model.state_at_rest(parts.fit_input.front());
  result.report = detail::weight_fit_report(
      "maxwell_slip",
      fmt::format("nnls (Lawson-Hanson) on element stiffnesses, {} loop",
                  orientation_name(orientation)),
      solution, static_cast<std::size_t>(columns) + (options.fit_offset ? 1 : 0), result.model,
      result.initial_state, parts, start);
  return result;
}

}  // namespace hyst
