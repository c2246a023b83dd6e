#include "hyst/identify/fit_krasnoselskii_pokrovskii.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "weight_fit.hpp"

namespace hyst {

KpFit fit_krasnoselskii_pokrovskii(std::span<const double> input, std::span<const double> output,
                                   const KpFitOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (options.levels == 0) throw Error("KP fit levels = 0 must be >= 1", "levels");
  if (options.levels > 4096) {  // before N(N+1)/2, which overflows for huge N
    throw Error(fmt::format("KP fit levels = {} must be in 1 .. 4096", options.levels), "levels");
  }
  const std::size_t kernels = options.levels * (options.levels + 1) / 2;
  const auto parts =
      detail::split_record(input, output, options.validate_fraction, "KP fit", kernels + 1);
  const auto [lowest, highest] =
      std::minmax_element(parts.fit_input.begin(), parts.fit_input.end());
  // A probe model with unit weights validates the grid options and produces the columns.
  KrasnoselskiiPokrovskii::Params params{.levels = options.levels,
                                         .lower = options.lower.value_or(*lowest),
                                         .upper = options.upper.value_or(*highest),
                                         .weights = std::vector<double>(kernels, 1.0),
                                         .ramp_cells = options.ramp_cells,
                                         .offset = 0.0};
  const KrasnoselskiiPokrovskii probe(params);
  auto state = probe.initial_state();
  const auto m = static_cast<Eigen::Index>(parts.fit_input.size());
  Eigen::MatrixXd A = detail::regressor_matrix(m, static_cast<Eigen::Index>(kernels), "KP fit");
  for (Eigen::Index k = 0; k < m; ++k) {
    probe.step(state, parts.fit_input[static_cast<std::size_t>(k)]);
    A.row(k) = Eigen::Map<const Eigen::RowVectorXd>(state.kernels.data(),
                                                    static_cast<Eigen::Index>(kernels));
  }
  const Eigen::Map<const Eigen::VectorXd> y(parts.fit_output.data(), m);
  const auto solution = detail::nnls_with_offset(std::move(A), y, options.fit_offset);
  params.weights.assign(solution.x.data(), solution.x.data() + solution.x.size());
  params.offset = solution.offset;
  KpFit result{KrasnoselskiiPokrovskii(std::move(params)), {}};
  result.report =
      detail::weight_fit_report("kp", "nnls (Lawson-Hanson) on kernel weights", solution,
                                kernels + (options.fit_offset ? 1 : 0), result.model,
                                result.model.initial_state(), parts, start);
  return result;
}

}  // namespace hyst
