#pragma once
// The relay grid of the butterfly strain fits (with and without creep): the grid with unit weights
// on the fitted inputs' range, and every record's relay states s_r[k] = +-1 from its start, the
// columns of the polarisation's weights.

#include <cstddef>
#include <span>
#include <string_view>

#include <Eigen/Core>

#include "hyst/identify/fit_butterfly_strain.hpp"
#include "hyst/models/preisach.hpp"
#include "weight_fit.hpp"

namespace hyst::detail {

// One record as the fit sees it: its whole input (for the periodic start), the compared part of
// it and the measured output of that part.
struct ButterflyRecordView {
  std::span<const double> whole_input;
  std::span<const double> input;
  std::span<const double> output;
};

// The relay grid with unit weights on the records' input range (or the options' lower and
// upper), `levels` levels or, when 0, as many as the records' samples allow (at most 16). Throws
// hyst::Error for an empty range.
Preisach::Params butterfly_unit_grid(std::span<const ButterflyRecordView> records,
                                     const ButterflyFitOptions& options);

// The Preisach initial state of a fit start (periodic starts from negative saturation and runs
// the whole input first).
PreisachInitialState butterfly_preisach_start(ButterflyFitStart start);

// Every record's relay states s_r[k] = +-1, stacked, with the inputs and outputs.
struct ButterflyRelayDesign {
  Eigen::MatrixXd relays;
  Eigen::VectorXd input;
  Eigen::VectorXd output;
};

ButterflyRelayDesign butterfly_relay_design(std::span<const ButterflyRecordView> records,
                                            const Preisach::Params& grid, ButterflyFitStart start);

// A record with measured polarisation split into fit and held-out parts, the strain's and the
// polarisation's (the same samples). Throws hyst::Error, messages starting with `who`, for a
// polarisation of another length and for what split_record() refuses.
struct PolarisationParts {
  RecordParts strain;
  RecordParts polarisation;
};
PolarisationParts split_with_polarisation(std::span<const double> input,
                                          std::span<const double> polarisation,
                                          std::span<const double> output, double validate_fraction,
                                          std::string_view who);

}  // namespace hyst::detail
