#pragma once
//! \file
//! Identification of a generalized Prandtl-Ishlinskii model (tanh envelopes, exponential density)
//! from measured input/output records, by nonlinear least squares with Ceres Solver.
//!
//!     theta = (a0, a1, a2, a3, b0, b1, b2, b3, rho, tau, alpha),   m fixed (chosen by the user)
//!     min_theta  sum_records sum_k ( y_meas[k] - GPI_theta[v_meas][k] )^2
//!                + sum_g ( w max(0, gamma_l(v_g) - gamma_r(v_g)) )^2         (ordering penalty)
//!     subject to bounds on every parameter (a0, a1, b0, b1, alpha > 0, tau >= 0 by default)
//!
//! Method: Levenberg-Marquardt (Ceres trust region, dense QR) with derivatives by automatic
//! differentiation: the GPI forward simulation is one template on the scalar type (GpiKernel in
//! generalized_prandtl_ishlinskii.hpp), run here with ceres::Jet, so the Jacobian is exact and
//! propagates through the operators' memory. max/min are not differentiable where two arguments
//! tie (a reversal exactly at a play's switching point): the Jet then carries the derivative of
//! the branch taken, a valid one-sided derivative. The cost is piecewise smooth and LM handles it;
//! this is documented behaviour, not a bug. The ordering penalty (w = 10 sqrt(N) on 64 inputs of
//! the operating range) keeps gamma_l <= gamma_r; a residual violation after the fit is removed by
//! raising b3 by it, so the returned model always passes the model's own check.
//!
//! Starting points (several, all derived from the data): output centre and half-range give
//! a3 = b3 and a0 = b0 (in units of S = sum_j p_j, which the starts set to 1); the input span gives
//! a1 = b1 (4/span: saturating, or 2/span: mild); the loop centre v_c and the loop width w (the
//! distance between the rising and the falling crossings of the output centre) give
//! a2 = -a1 (v_c + s w/2) and b2 = -a1 (v_c - s w/2) with s = 1 (all the width from the envelopes)
//! or s = 1/2 (half of it from the thresholds: alpha m = half the vertical loop height). Every
//! start runs `screening_iterations`; the best one continues up to `max_iterations`.
//!
//! Scale gauge: the output is unchanged under (rho, tau, alpha, a0, a3, b0, b3) ->
//! (c rho, c tau, alpha/c, a0/c, a3/c, b0/c, b3/c) (see generalized_prandtl_ishlinskii.hpp), so
//! only 10 of the 11 parameters are identifiable. The fit holds rho at its start value (the
//! symmetry makes that no restriction) and returns the parameters rescaled to S = sum_j p_j = 1:
//! the envelopes are then in output units. rescale_density() moves them to any other scale (e.g.
//! a given rho). Compare parameter sets only in the same gauge.
//!
//! Initial state: `rest` = the record starts at rest at its first input, arrived rising (every
//! z_j = gamma_l(v[0]), the model's default); `periodic` = the record is one period of a periodic
//! excitation in steady state: the simulation runs the input once before the residuals are
//! taken (exact, as for the classical PI: one period is a composition of clamps, hence idempotent).
//!
//! Data: quasi-static (rate effects are not modelled), finite, non-constant input and output,
//! at least 2 * 11 samples in the fit part. Common mistakes: fitting GPI to butterfly
//! (non-monotone) loops, which no GPI can produce; choosing `rest` for a steady-state loop record
//! (the fit then explains a first-loading curve that was never measured); comparing raw rho, a0,
//! ... between fits without fixing the gauge; fitting a single major loop and expecting minor loops
//! to follow - one saturated loop does not identify the thresholds (on measured B(H) loops both
//! fits drove alpha to a bound); fit a major and a minor loop together (the GpiRecord overload),
//! see docs/results.md. Sources: Al Janaideh, Rakheja & Su (2009), Smart
//! Mater. Struct. 18:045001; reference generalized_pi.md section 5; Ceres Solver (Agarwal, Mierle
//! et al.), http://ceres-solver.org.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"
#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/generalized_prandtl_ishlinskii.hpp"

namespace hyst {

//! The fitted parameters, in the order of the parameter vector theta.
enum class GpiParameter : unsigned char { a0, a1, a2, a3, b0, b1, b2, b3, rho, tau, alpha };
inline constexpr std::size_t kGpiParameterCount = 11;
//! "a0", ..., "b3", "rho", "tau", "alpha".
std::string_view to_string(GpiParameter parameter);
//! The inverse of to_string(); throws hyst::Error for other text.
GpiParameter gpi_parameter_from_string(std::string_view text);

//! theta = (a0, a1, a2, a3, b0, b1, b2, b3, rho, tau, alpha).
using GpiParameterVector = std::array<double, kGpiParameterCount>;

//! The tanh / exponential-density GpiParams of a parameter vector (not validated here).
GpiParams gpi_params_from_vector(const GpiParameterVector& theta, std::size_t m, double input_min,
                                 double input_max, double initial_input);
//! The parameter vector of tanh / exponential-density params; throws hyst::Error otherwise.
GpiParameterVector gpi_vector_from_params(const GpiParams& params);

struct GpiFitOptions {
  enum class InitialState {
    rest,      //!< at rest at the first input sample, arrived rising (z_j = gamma_l(v[0]))
    periodic,  //!< the record is one period in steady state (see the file comment)
  };

  //! Operators j = 0..m (m + 1 of them); 1 <= m <= 200.
  std::size_t m = 10;
  InitialState initial_state = InitialState::rest;
  //! Fraction of the record, at its end, held out for validation (data_split.hpp); [0, 1).
  //! Must be 0 when a separate validation record is given.
  double validate_fraction = 0.0;
  //! Starting points; empty = the data-derived starts of the file comment. rho of a given start
  //! sets the gauge during the iteration.
  std::vector<GpiParameterVector> starts;
  //! Bound overrides by parameter (indexed by GpiParameter); unset = the defaults, which scale
  //! with the data (see default_gpi_bounds()). rho's bounds are ignored (gauge).
  std::array<std::optional<double>, kGpiParameterCount> lower{};
  std::array<std::optional<double>, kGpiParameterCount> upper{};
  //! Levenberg-Marquardt iterations of each start in the screening stage (>= 1).
  std::size_t screening_iterations = 15;
  //! Levenberg-Marquardt iterations of the best start after screening (>= 0).
  std::size_t max_iterations = 3000;
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  //! Ceres' relative cost-decrease tolerance (> 0): stop when |d cost| / cost < it.
  double function_tolerance = 1e-9;
  //! Operating range for the ordering check of the fitted model [input units]; unset = the range
  //! of all inputs (fit and validation), widened by 1 % of the span on each side.
  std::optional<double> input_min;
  std::optional<double> input_max;
};

//! "rest" or "periodic".
constexpr EnumNames<GpiFitOptions::InitialState, 2> enumerator_names(GpiFitOptions::InitialState) {
  return {{
      {GpiFitOptions::InitialState::rest, "rest"},
      {GpiFitOptions::InitialState::periodic, "periodic"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
GpiFitOptions::InitialState gpi_initial_state_from_string(std::string_view text);

//! One fitted parameter with the bounds it was fitted within (both in the reported gauge
//! sum_j p_j = 1).
struct GpiFitParameter {
  GpiParameter parameter = GpiParameter::a0;
  double value = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  bool fixed = false;     //!< not iterated (rho: the scale gauge)
  bool at_bound = false;  //!< within 1e-6 (relative to the bound interval) of a bound
};

//! Default bounds for data with input span dv and output span dy (the iteration gauge has S ~ 1,
//! so envelope quantities are in output units): a0, b0 in [1e-3 dy, 10 dy]; a1, b1 in
//! [0.01/dv, 200/dv]; a2, b2 within +-(200/dv (max|v| + 2 dv) + 10); a3, b3 within
//! +-(max|y| + 10 dy); tau in [0, 300/dy]; alpha in [1e-6 dy/m, 2 dy/m] (tau alpha m <= 600 keeps
//! every weight a normal number). rho: unused (gauge). Returns {lower, upper}.
std::array<GpiParameterVector, 2> default_gpi_bounds(double input_min, double input_max,
                                                     double output_min, double output_max,
                                                     std::size_t m);

//! The data-derived starting points of the file comment (rho such that sum_j p_j = 1).
std::vector<GpiParameterVector> gpi_starting_points(std::span<const double> input,
                                                    std::span<const double> output, std::size_t m);

//! A fitted GPI model with the initial state the fit assumed, the report and the parameters.
struct GpiFit {
  GeneralizedPrandtlIshlinskii<TanhEnvelope> model;
  //! The model state at the first sample of the fitted record (rest or periodic).
  GeneralizedPrandtlIshlinskii<TanhEnvelope>::State initial_state;
  FitReport report;  //!< model "gpi", method "levenberg-marquardt (ceres, autodiff)"
  std::vector<GpiFitParameter> parameters;  //!< all 11, in GpiParameter order
  std::size_t starts = 0;                   //!< starting points tried
  std::size_t best_start = 0;               //!< index of the one that was refined
};

//! Fits the GPI to one record, optionally holding out its last part for validation. Throws
//! hyst::Error for invalid data or options (lengths differ, a non-finite sample named with its
//! index, too few samples, constant input or output, m out of range, a bound with lower >= upper,
//! a start outside the bounds). A fit that does not converge is not an error: see
//! report.termination.
GpiFit fit_generalized_prandtl_ishlinskii(std::span<const double> input,
                                          std::span<const double> output,
                                          const GpiFitOptions& options = {});

//! Same, validated on a separate record (e.g. a smaller loop), which starts from its own initial
//! state of the chosen kind; fills report.validation. options.validate_fraction must be 0.
GpiFit fit_generalized_prandtl_ishlinskii(std::span<const double> input,
                                          std::span<const double> output,
                                          std::span<const double> validation_input,
                                          std::span<const double> validation_output,
                                          const GpiFitOptions& options = {});

//! One input/output record, e.g. one measured loop (the record type of every fitter).
using GpiRecord = FitRecord;

//! Fits one model to several records at once (e.g. a major loop and a minor loop, which together
//! identify the threshold distribution a major loop alone leaves open), each record starting from
//! its own initial state of the chosen kind; validated on the `validation` records (may be empty),
//! each also from its own initial state. report.fit and report.validation are over the
//! concatenated records; GpiFit::initial_state is the first record's. options.validate_fraction
//! must be 0 unless there is exactly one record and no validation record.
GpiFit fit_generalized_prandtl_ishlinskii(std::span<const GpiRecord> records,
                                          std::span<const GpiRecord> validation,
                                          const GpiFitOptions& options = {});

}  // namespace hyst
