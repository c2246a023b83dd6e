#pragma once
//! \file
//! Identification of a Prandtl-Ishlinskii model from one measured input/output record: the weights
//! for fixed thresholds, by non-negative least squares.
//!
//! For fixed thresholds r_j and a known initial state, the play outputs w_j[k] follow from the
//! input alone, and the model output is linear in the weights p_j and the offset y_off:
//!
//!     y[k] = y_off + sum_{j=0..n} p_j w_j[k],    w_j[k] = max(v[k] - r_j, min(v[k] + r_j,
//!     w_j[k-1]))
//!
//!     min_{p, y_off} sum_k (y_meas[k] - y[k])^2   subject to   p_0 >= eps,  p_j >= 0 (j >= 1)
//!
//! p_j >= 0 with p_0 > 0 is the usual sufficient condition for a monotone, invertible model (every
//! partial sum S_j = p_0 + ... + p_j > 0, see InversePrandtlIshlinskii). The bound p_0 >= eps is
//! handled by the substitution p_0 = eps + q, q >= 0; the free offset by centring every column and
//! the output (the best offset for any weights is mean(y_meas - sum_j p_j w_j)), after which the
//! problem is a plain NNLS (nnls.hpp) of size samples x operators.
//!
//! Thresholds (when not given): r_j = j (v_max - v_min) / (2 n_op), j = 0..n_op-1, with v_max and
//! v_min the extremes of the fitted input. A play of half-width r only moves on a branch when the
//! input travels more than 2r along it; the longest branch of the record spans v_max - v_min, so a
//! threshold >= (v_max - v_min)/2 would give a column that is constant after the first reversal
//! (no information, and collinear with the offset). Uniform spacing below that limit gives every
//! play the same resolution in amplitude; the largest one, r = (n_op - 1)/(2 n_op) (v_max - v_min),
//! still moves over the last 1/n_op of the largest branch.
//!
//! Initial state: `virgin` starts every play at 0 (the record starts from a demagnetised /
//! depolarised state at v = 0). `periodic` is for a record that is one period of a periodic
//! excitation in steady state: the plays start from the state reached after running the whole input
//! once. This is the exact periodic steady state, not an approximation: one period maps a play's
//! start value w through a composition of clamps, which is itself a clamp and therefore idempotent,
//! so a second period ends where the first did. Getting this wrong (virgin for a steady-state
//! record) makes the fit explain a first-loading curve that was never measured.
//!
//! Common mistakes: thresholds in output instead of input units; a record that does not reach the
//! amplitudes the model will be used at (thresholds above half the fitted range are never
//! identified); expecting a classical PI model to fit asymmetric or saturating loops - its loops
//! are odd-symmetric about their centre, so the fit error of such data does not shrink with more
//! operators.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace hyst {

struct PiFitOptions {
  enum class InitialState {
    virgin,    //!< every play output starts at 0
    periodic,  //!< the record is one period in steady state (see the file comment)
  };

  //! Number of play operators n_op (thresholds r_0 = 0 ... r_{n_op-1}) when `thresholds` is empty;
  //! >= 1.
  std::size_t operators = 10;
  //! Thresholds r_j [input units]: r_0 = 0, strictly increasing, finite. Empty = uniform spacing
  //! j (v_max - v_min) / (2 operators) over the fitted input (see the file comment).
  std::vector<double> thresholds{};
  //! Fit a free (unconstrained) offset y_off [output units]; false = y_off = 0.
  bool fit_offset = true;
  //! Lower bound on the linear weight, relative to the scale of the data: p_0 >= eps with
  //! eps = min_linear_weight * (y_max - y_min) / (v_max - v_min) over the fitted part [-].
  //! It keeps p_0 > 0 so that the fitted model is invertible; > 0 and finite.
  double min_linear_weight = 1e-9;
  InitialState initial_state = InitialState::virgin;
  //! Fraction of the record, at its end, held out for validation (data_split.hpp); [0, 1). The
  //! validation part is predicted by continuing the simulation from the state reached at the end
  //! of the fit part. Must be 0 when a separate validation record is given.
  double validate_fraction = 0.0;
};

//! "virgin" or "periodic".
constexpr EnumNames<PiFitOptions::InitialState, 2> enumerator_names(PiFitOptions::InitialState) {
  return {{
      {PiFitOptions::InitialState::virgin, "virgin"},
      {PiFitOptions::InitialState::periodic, "periodic"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
PiFitOptions::InitialState pi_initial_state_from_string(std::string_view text);

//! Uniform thresholds r_j = j (v_max - v_min) / (2 operators), j = 0..operators-1, over the range
//! of `input`. Throws hyst::Error unless operators >= 1 and the input is finite and not constant.
std::vector<double> pi_default_thresholds(std::span<const double> input, std::size_t operators);

//! The periodic steady state of `model` for a record that is one period of its input: the play
//! states after running `input` once from the virgin state (exact, see the file comment). Throws
//! hyst::Error for an empty or non-finite input.
PrandtlIshlinskii::State pi_periodic_state(const PrandtlIshlinskii& model,
                                           std::span<const double> input);

//! A fitted PI model with the initial state the fit assumed and the report.
struct PiFit {
  PrandtlIshlinskii model;
  //! The play states at the first sample of the fitted record (all 0 for `virgin`).
  PrandtlIshlinskii::State initial_state;
  FitReport report;  //!< model "pi", method "nnls (Lawson-Hanson)"
};

//! Fits the weights (and offset) of a PI model to one record, optionally holding out its last
//! part for validation. Throws hyst::Error for invalid data or options: lengths differ, a sample
//! is not finite (named with its index), fewer than operators + 2 samples in the fit part,
//! thresholds not 0 = r_0 < r_1 < ..., a constant input or output. A fit that does not converge is
//! not an error: see report.termination.
PiFit fit_prandtl_ishlinskii(std::span<const double> input, std::span<const double> output,
                             const PiFitOptions& options = {});

//! Same, validated on a separate held-out record (e.g. another amplitude), which starts from its
//! own initial state of the chosen kind (virgin, or the periodic state of the validation input);
//! fills report.validation. options.validate_fraction must be 0.
PiFit fit_prandtl_ishlinskii(std::span<const double> input, std::span<const double> output,
                             std::span<const double> validation_input,
                             std::span<const double> validation_output,
                             const PiFitOptions& options = {});

}  // namespace hyst
