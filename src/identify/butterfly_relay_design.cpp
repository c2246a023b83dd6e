#include "butterfly_relay_design.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "detail/regressor_matrix.hpp"
#include "hyst/core/error.hpp"
#include "hyst/models/preisach_relay_grid.hpp"

namespace hyst::detail {
namespace {

constexpr std::string_view kFit = "butterfly strain fit";
constexpr std::size_t kDefaultLevels = 16;  // of the relay grid, when the record allows

// `levels`, or when 0 the most levels up to kDefaultLevels whose relays number at most half the
// `samples`, at least 2.
std::size_t butterfly_grid_levels(std::size_t levels, std::size_t samples) {
  if (levels > 0) return levels;
  std::size_t automatic = kDefaultLevels;
  while (automatic > 2 && 2 * preisach_relay_count(automatic) > samples)
    --automatic;
  return automatic;
}

}  // namespace

Preisach::Params butterfly_unit_grid(std::span<const ButterflyRecordView> records,
                                     const ButterflyFitOptions& options) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  std::size_t samples = 0;
  for (const auto& record : records) {
    samples += record.input.size();
    const auto [min, max] = std::minmax_element(record.input.begin(), record.input.end());
    lo = std::min(lo, *min);
    hi = std::max(hi, *max);
  }
  Preisach::Params params;
  params.everett.levels = butterfly_grid_levels(options.levels, samples);
  params.everett.lower = options.lower.value_or(lo);
  params.everett.upper = options.upper.value_or(hi);
  if (!(params.everett.lower < params.everett.upper)) {
    throw Error(fmt::format("{}: the input range [{}, {}] is empty (lower must be < upper; a "
                            "constant input cannot switch a polarisation)",
                            kFit, params.everett.lower, params.everett.upper),
                "upper");
  }
  params.everett.weights = uniform_relay_weights(params.everett.levels, 1.0);
  return params;
}

PreisachInitialState butterfly_preisach_start(ButterflyFitStart start) {
  if (start == ButterflyFitStart::positive_saturation) {
    return PreisachInitialState::positive_saturation;
  }
  return start == ButterflyFitStart::demagnetised ? PreisachInitialState::demagnetised
                                                  : PreisachInitialState::negative_saturation;
}

ButterflyRelayDesign butterfly_relay_design(std::span<const ButterflyRecordView> records,
                                            const Preisach::Params& grid, ButterflyFitStart start) {
  auto params = grid;
  params.initial_state = butterfly_preisach_start(start);
  const PreisachRelayGrid relays(params);
  Eigen::Index rows = 0;
  for (const auto& record : records)
    rows += static_cast<Eigen::Index>(record.input.size());
  const auto columns = static_cast<Eigen::Index>(relays.relay_count());
  ButterflyRelayDesign design{regressor_matrix(rows, columns, kFit), Eigen::VectorXd(rows),
                              Eigen::VectorXd(rows)};
  Eigen::Index row = 0;
  for (const auto& record : records) {
    auto state = relays.initial_state();
    if (start == ButterflyFitStart::periodic) {
      for (double v : record.whole_input)
        relays.step(state, v);
    }
    for (std::size_t k = 0; k < record.input.size(); ++k, ++row) {
      relays.step(state, record.input[k]);
      for (Eigen::Index r = 0; r < columns; ++r)
        design.relays(row, r) = state.relays[static_cast<std::size_t>(r)];
      design.input[row] = record.input[k];
      design.output[row] = record.output[k];
    }
  }
  return design;
}

PolarisationParts split_with_polarisation(std::span<const double> input,
                                          std::span<const double> polarisation,
                                          std::span<const double> output, double validate_fraction,
                                          std::string_view who) {
  if (polarisation.size() != input.size()) {
    throw Error(fmt::format("{}: {} polarisation samples for {} input samples", who,
                            polarisation.size(), input.size()),
                "polarisation");
  }
  return {split_record(input, output, validate_fraction, who, 2),
          split_record(input, polarisation, validate_fraction,
                       fmt::format("{} (polarisation)", who), 2)};
}

}  // namespace hyst::detail
