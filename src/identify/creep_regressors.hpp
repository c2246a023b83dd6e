#pragma once
// Shared steps of the fits with Kuhnen's creep operator (PI with creep, modified PI with creep):
// the plays and creep lags of every record are fixed by its input once the thresholds and time
// constants are, so they are the columns of a linear fit. Records at different rates each run at
// their own sample time (the lags are discretised exactly for each).

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "hyst/core/simulate.hpp"
#include "hyst/identify/creep_law.hpp"
#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/models/prandtl_ishlinskii_creep.hpp"

namespace hyst::detail {

// What fixes the creep structure of a fit (the fields both creep fits' options share).
struct CreepStructureOptions {
  std::size_t operators = 0;
  std::span<const double> thresholds;  // empty: uniform (as the PI fit)
  std::size_t lags = 0;
  std::span<const double> time_constants;  // empty: log-spaced
  double sample_time = 1.0;
  std::span<const double> sample_times;  // one per record, or empty
  PiFitOptions::InitialState initial_state = PiFitOptions::InitialState::virgin;
  // logarithmic: default time constants lags_per_decade per decade up to longest_time_constant.
  CreepLaw creep_law = CreepLaw::free;
  std::size_t lags_per_decade = 2;
  double longest_time_constant = 1e5;
};

template <class Options>
CreepStructureOptions creep_structure_options(const Options& options) {
  CreepStructureOptions structure{options.operators,      options.thresholds,  options.lags,
                                  options.time_constants, options.sample_time, options.sample_times,
                                  options.initial_state};
  if constexpr (requires { options.creep_law; }) {
    structure.creep_law = options.creep_law;
    structure.lags_per_decade = options.lags_per_decade;
    structure.longest_time_constant = options.longest_time_constant;
  }
  return structure;
}

// Checks sample_time (> 0, finite); messages start with `who`.
void check_creep_sample_time(double sample_time, std::string_view who);

struct CreepRegressors {
  PrandtlIshlinskiiCreep structure;  // zero weights, at the first record's sample time
  std::vector<double> sample_times;  // of each record
  Eigen::MatrixXd columns;           // [w_j, z_ij] of every record's samples, records joined
  std::vector<double> inputs;        // every record's input, joined
  std::vector<double> outputs;       // every record's output, joined
};

// The thresholds (default: as the PI fit, over every record's input), the time constants
// (default: `lags` log-spaced from 10 Ts (the shortest) to the longest record's duration) and the
// columns of every record from its start state. Throws hyst::Error naming the option or the
// record, or when there are fewer samples than columns + 2.
CreepRegressors creep_regressors(std::span<const FitRecord> records,
                                 const CreepStructureOptions& options, std::string_view who);

// The rows of the logarithmic law's penalty (fit_prandtl_ishlinskii_creep.hpp) for the creep
// columns of `regressors` (the n play columns first, then one block of n per lag): row (i, j) is
// smoothing |w_j - mean w_j| (c_{i+1,j} - c_ij), zero on every other column of `columns` (the
// total column count, >= the creep columns). The creep blocks start at column
// `first_creep_column` of the fit (n when the plays come first, as in the regressors). Empty for
// fewer than two lags or smoothing 0.
Eigen::MatrixXd creep_law_penalty(const CreepRegressors& regressors, Eigen::Index columns,
                                  double smoothing, Eigen::Index first_creep_column);

// The leakage's columns: the charge sum Ts v (g >= 0: a conduction) and the time sum Ts twice
// (+ and -: NNLS bounds every unknown below and the offset current i0 has either sign), each
// record from its start, `rows` in all.
Eigen::MatrixXd leakage_columns(std::span<const FitRecord> records,
                                std::span<const double> sample_times, Eigen::Index rows);

// The state a record starts from: virgin, or the periodic steady state of its input.
template <class Model>
typename Model::State creep_start_state(const Model& model, std::span<const double> input,
                                        PiFitOptions::InitialState initial_state) {
  return initial_state == PiFitOptions::InitialState::periodic ? model.periodic_state(input)
                                                               : model.initial_state();
}

// Every record simulated at its sample time from its start state; outputs joined.
template <class Model>
std::vector<double> simulate_creep_records(const Model& model, std::span<const FitRecord> records,
                                           std::span<const double> sample_times,
                                           PiFitOptions::InitialState initial_state) {
  std::vector<double> predicted;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto discretised = model.at_sample_time(sample_times[r]);
    auto state = creep_start_state(discretised, records[r].input, initial_state);
    const auto y = simulate(discretised, state, records[r].input);
    predicted.insert(predicted.end(), y.begin(), y.end());
  }
  return predicted;
}

}  // namespace hyst::detail
