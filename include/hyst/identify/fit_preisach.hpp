#pragma once
//! \file
//! Identification of Preisach models: (a) the relay weights of the discrete grid from an
//! input/output record, (b) a tabulated Everett function from first-order reversal curves (FORC).
//! Both are linear least-squares problems with non-negativity constraints, solved by NNLS
//! (nnls.hpp), and both return the common FitReport.
//!
//! (a) Relay weights. With a known initial state the relay states s_ij[k] = +-1 follow from the
//! input alone (PreisachRelayGrid with unit weights), and the output is linear in the weights:
//!
//!     y[k] = y_off + sum_{i >= j} mu_ij s_ij[k]
//!     min_{mu >= 0, y_off}  sum_k (y_meas[k] - y[k])^2 + lambda^2 M sum_{(r,r') neighbours} (mu_r
//!     - mu_r')^2
//!
//! (M = samples in the fit part; neighbours = relays next to each other along alpha or beta on the
//! triangular grid, the diagonal ones - alpha = beta, the reversible part - only among themselves).
//! The free offset is removed by centring the columns and the output (the best
//! offset for any weights is the mean residual); the smoothness term (lambda >= 0, dimensionless:
//! weight of the squared neighbour differences relative to the mean squared residual) is appended
//! as extra rows lambda sqrt(M) (mu_r - mu_r') = 0. Then the problem is a plain NNLS of size
//! (M + neighbours) x N(N+1)/2.
//!
//! (b) Everett function from FORCs. A curve starts at saturation (positive, as magnetometers do:
//! saturate, go down to the reversal field H_r, measure up; or negative), moves to its reversal
//! input v_r = input[0] and then along input[1...]. For the tabulated Everett function
//! (everett_table.hpp) on levels x_0 .. x_K the model output along any such history is linear in
//! the table, and the table is linear in the K(K+1)/2 non-negative cell weights w_ij
//! (E(x_a, x_c) = sum_{c <= j <= i <= a-1} w_ij; diagonal cells carry the reversible part). For a
//! curve from positive saturation this is the classical relation
//!
//!     y(v_r, v) = y_off + F0 - 2 E(upper, v_r) + 2 E(v, v_r),   so  E(v, v_r) = (y(v_r, v) -
//!     y(v_r, v_r)) / 2
//!
//! (Mayergoyz 1991; negative saturation mirrors it). Every measured point is one row; the cell
//! weights come from NNLS with the same offset and smoothness treatment as (a), which makes the
//! identified Everett function a valid Preisach model (mu >= 0, monotone output) even for noisy
//! data, where the textbook double difference of the FORCs amplifies the noise.
//!
//! Costs: (a) builds an M x N(N+1)/2 matrix and NNLS takes O(R^3) per active-set change (R =
//! relays), practical up to N ~ 30; (b) likewise with R = K(K+1)/2 cells, K ~ 30.
//! Common mistakes: an input that never reverses inside a cell pair leaves those relays
//! unidentifiable (their columns coincide: the weights split arbitrarily, the output does not);
//! excite the whole range with reversals of many amplitudes. A wrong initial state (a record that
//! does not start at the assumed saturation) biases every weight. FORCs of magnetometers start at
//! positive saturation, the reference's FORCs (preisach.md sec. 7) at negative.
//! Sources: preisach.md sec. 7; Mayergoyz (1991) ch. 1; Tan & Baras (2004); Lawson & Hanson (1974).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/preisach.hpp"

namespace hyst {

//! Options of fit_preisach_weights().
struct PreisachWeightFitOptions {
  std::size_t levels = 21;  //!< N threshold levels (N(N+1)/2 relays), >= 1
  //! Input range of the grid [input units]; not set = min and max of the fitted input.
  std::optional<double> lower = std::nullopt;
  std::optional<double> upper = std::nullopt;
  PreisachGridLayout layout = PreisachGridLayout::cell_centred;
  //! The state the record starts from (also the fitted model's initial state).
  PreisachInitialState initial_state = PreisachInitialState::negative_saturation;
  double smoothness = 0.0;  //!< lambda >= 0 (file comment)
  bool fit_offset = true;   //!< fit y_off; false = y_off = 0
  //! Fraction of the record, at its end, held out for validation (data_split.hpp), [0, 1); it is
  //! predicted by continuing the simulation from the state at the end of the fit part.
  double validate_fraction = 0.0;
};

//! A fitted relay-grid model and its report (model "preisach", method "nnls (Lawson-Hanson) on
//! relay weights").
struct PreisachWeightFit {
  Preisach model;
  FitReport report;
};

//! Fits the relay weights (and offset) to one record. Throws hyst::Error for invalid data or
//! options (lengths differ, a sample not finite, fewer samples than relays + 2 in the fit part,
//! constant input or output, lower >= upper, negative smoothness). A fit that does not converge
//! is not an error: see report.termination.
PreisachWeightFit fit_preisach_weights(std::span<const double> input,
                                       std::span<const double> output,
                                       const PreisachWeightFitOptions& options = {});

//! One first-order reversal curve, viewed: input[0] is the reversal input v_r, reached from
//! saturation; the curve then follows input[1...] (usually monotonically away from v_r). At least
//! 1 sample, output of the same length; oversampling 1 and skip 0.
using ReversalCurve = FitRecord;

//! Options of fit_preisach_forcs().
struct PreisachForcFitOptions {
  std::size_t intervals = 24;  //!< K: uniform levels x_0 .. x_K over [lower, upper], K >= 1
  //! Range of the table [input units]; not set = min and max of the fitted curves' inputs. Set
  //! upper to the saturating field when the curves stop short of it (inputs above the table act
  //! like saturation).
  std::optional<double> lower = std::nullopt;
  std::optional<double> upper = std::nullopt;
  //! positive_saturation (magnetometer FORCs: down to v_r, then up) or negative_saturation.
  PreisachInitialState saturation = PreisachInitialState::positive_saturation;
  double smoothness = 0.0;  //!< lambda >= 0 on neighbouring cell weights (as in (a))
  bool fit_offset = true;   //!< fit y_off; false = y_off = 0
  //! Indices of curves left out of the fit; report.validation is measured on them.
  std::vector<std::size_t> held_out = {};
};

//! A fitted tabulated Everett function and its report (model "tabulated_preisach", method
//! "nnls (Lawson-Hanson) on Everett cell weights from FORCs"). The model's initial_state is the
//! curves' saturation.
struct PreisachForcFit {
  TabulatedPreisach model;
  FitReport report;
};

//! Identifies the Everett function from reversal curves. Throws hyst::Error for invalid curves
//! (empty, lengths differ, not finite: "FORC 3 output[7] = nan is not finite") or options
//! (intervals = 0, held_out index out of range or holding out every curve, fewer points than
//! cells + 2, saturation = demagnetised).
PreisachForcFit fit_preisach_forcs(std::span<const ReversalCurve> curves,
                                   const PreisachForcFitOptions& options = {});

//! The model's output along a reversal curve: from `saturation` to input[0], then along input.
template <EverettFunction Everett>
std::vector<double> predict_reversal_curve(const BasicPreisach<Everett>& model,
                                           std::span<const double> input,
                                           PreisachInitialState saturation) {
  auto state = model.make_state(saturation);
  std::vector<double> output;
  output.reserve(input.size());
  for (double v : input)
    output.push_back(model.step(state, v));
  return output;
}

}  // namespace hyst
