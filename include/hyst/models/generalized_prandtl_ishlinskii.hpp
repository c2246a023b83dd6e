#pragma once
//! \file
//! Generalized Prandtl-Ishlinskii model (GPI): a weighted sum of generalized play operators that
//! share one ascending envelope gamma_l and one descending envelope gamma_r. It describes
//! saturating, asymmetric loops such as force vs coil current of magnetic shape memory alloy
//! (MSMA) actuators.
//!
//!     y[k]   = sum_{j=0..m} p_j z_j[k]
//!     z_j[k] = max( gamma_l(v[k]) - r_j , min( gamma_r(v[k]) + r_j , z_j[k-1] ) )
//!     tanh envelopes:  gamma_l(v) = a0 tanh(a1 v + a2) + a3,   gamma_r(v) = b0 tanh(b1 v + b2) +
//!     b3 exponential density:  r_j = alpha j,  p_j = rho exp(-tau r_j),  j = 0..m
//!
//! The envelopes are evaluated once per sample and shared by all m + 1 operators. Parameters:
//! - envelopes (envelopes.hpp; tanh, arctan or linear, a compile-time choice): strictly increasing,
//!   a0 a1 > 0, b0 b1 > 0, and ordered gamma_l <= gamma_r on the declared operating range
//!   [input_min, input_max] (checked on a grid of 2001 inputs at construction);
//! - density: either exponential (rho > 0, alpha > 0 [envelope units], tau finite [1/envelope
//!   units], m >= 0) or free thresholds 0 = r_0 < r_1 < ... and weights with p_0 > 0 and every
//!   partial sum p_0 + ... + p_j > 0 (monotone and invertible). The discrete sum has no dr factor:
//!   rho absorbs it and is dimensionless.
//! Units: input v [input units, e.g. coil current A]; envelopes, thresholds and states z_j in
//! "u-space" [output units / S], S = sum_j p_j; output y [output units, e.g. force N].
//!
//! Initial state [ASSUMED default of the reference]: at rest at the input i0 = initial_input with
//! every z_j = gamma_l(i0), as if the input had arrived there rising (admissible because
//! gamma_l(i0) - r_j <= gamma_l(i0) <= gamma_r(i0) + r_j). The inverse GPI starts from the state
//! consistent with it.
//!
//! Properties: rate independent; the output never moves against the input (all p_j > 0 or
//! positive partial sums, increasing envelopes); after the first step every z_j lies in
//! [gamma_l(v) - r_j, gamma_r(v) + r_j], so y saturates with the envelope ranges. With linear
//! envelopes gamma_l = gamma_r = v the model is the classical PrandtlIshlinskii (bit for bit).
//!
//! Pitfalls:
//! - Branch direction: gamma_l is the ASCENDING (loading, lower) branch, gamma_r the descending
//!   (upper) one; loops run counter-clockwise. Swapped envelopes are rejected.
//! - The parameters are not unique: (rho, tau, alpha, a0, a3, b0, b3) ->
//!   (c rho, c tau, alpha / c, a0 / c, a3 / c, b0 / c, b3 / c) leaves the output unchanged for any
//!   c > 0 (envelopes, thresholds and states scale by 1/c, weights by c). rescale_density()
//!   applies this map; compare fitted parameters only after fixing the scale (e.g. rho or S = 1).
//! - Outside the operating range the ordering is not checked; keep inputs inside it.
//! Sources: Al Janaideh, Rakheja & Su (2009), Smart Mater. Struct. 18:045001; (2011) IEEE/ASME
//! TMech 16(4):734-744; MSMA application: Minorowicz & Milecki (2022), Materials 15:4400, section
//! 4.1; reference generalized_pi.md.

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "hyst/core/assert.hpp"
#include "hyst/core/enum_names.hpp"
#include "hyst/models/envelopes.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/generalized_play.hpp"

namespace hyst {

//! How the thresholds r_j and weights p_j are given: "exponential" or "free".
enum class GpiDensity : unsigned char {
  exponential,  //!< r_j = alpha j, p_j = rho exp(-tau r_j), j = 0..m (the paper's form)
  free,         //!< thresholds and weights listed explicitly
};
constexpr EnumNames<GpiDensity, 2> enumerator_names(GpiDensity) {
  return {{
      {GpiDensity::exponential, "exponential"},
      {GpiDensity::free, "free"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
GpiDensity gpi_density_from_string(std::string_view text);

//! Which branch a state at rest was reached on; the inverse GPI's running direction.
enum class LoopBranch : unsigned char {
  ascending,   //!< arrived rising: z_j = gamma_l(v)
  descending,  //!< arrived falling: z_j = gamma_r(v)
};

//! Parameters of a GPI model: plain numbers and vectors, shared by every envelope kind so that
//! model files and bindings need one format. `envelope` must match the model's envelope type.
struct GpiParams {
  EnvelopeKind envelope = EnvelopeKind::tanh;
  std::vector<double> ascending{};   //!< gamma_l coefficients (tanh/arctan: a0..a3; linear: a0, a1)
  std::vector<double> descending{};  //!< gamma_r coefficients (tanh/arctan: b0..b3; linear: b0, b1)
  GpiDensity density = GpiDensity::exponential;
  double rho = 1.0;    //!< exponential density: rho > 0 [-]
  double tau = 0.0;    //!< exponential density: decay tau [1/envelope units], finite
  double alpha = 1.0;  //!< exponential density: threshold spacing alpha > 0 [envelope units]
  std::size_t m = 10;  //!< exponential density: operators j = 0..m (m + 1 of them)
  std::vector<double> thresholds{};  //!< free density: 0 = r_0 < r_1 < ... [envelope units]
  std::vector<double> weights{};     //!< free density: p_j, p_0 > 0, partial sums > 0 [-]
  //! Operating range of the input [input units]; the ordering gamma_l <= gamma_r is checked on it.
  double input_min = std::numeric_limits<double>::quiet_NaN();
  double input_max = std::numeric_limits<double>::quiet_NaN();
  //! i0 [input units], in the operating range: initial_state() is at rest there.
  double initial_input = 0.0;
};

//! The GPI forward computation as a template on the scalar type T: double for the model, a Ceres
//! Jet for automatic derivatives in the fitter. Coefficients, thresholds, weights and states are
//! arrays of T; inputs are data (double). step() and output() are inline (the model's hot loop);
//! the other functions are compiled once for T = double in generalized_prandtl_ishlinskii.cpp.
template <Envelope E, class T>
struct GpiKernel {
  //! r_j = alpha j and p_j = rho exp(-tau r_j) for j = 0..m (m + 1 entries each).
  static void exponential_density(const T& rho, const T& tau, const T& alpha, std::size_t m,
                                  T* thresholds, T* weights);
  //! At rest at input v0: every z_j = gamma_l(v0) (ascending) or gamma_r(v0) (descending).
  static void rest_state(const T* ascending, const T* descending, double v0, LoopBranch branch,
                         std::size_t n, T* state);
  //! y = sum_j p_j z_j.
  static T output(const T* weights, const T* state, std::size_t n) {
    if constexpr (std::is_same_v<T, double>) {
      // Eigen's vectorised dot product, the same as PrandtlIshlinskii's: linear envelopes then
      // reproduce the classical model bit for bit.
      const auto size = static_cast<Eigen::Index>(n);
      return Eigen::Map<const Eigen::VectorXd>(weights, size)
          .dot(Eigen::Map<const Eigen::VectorXd>(state, size));
    } else {
      T sum = weights[0] * state[0];
      for (std::size_t j = 1; j < n; ++j)
        sum += weights[j] * state[j];
      return sum;
    }
  }
  //! Runs `input` from `state` (advanced), writing y[k] to output[k].
  static void simulate(const T* ascending, const T* descending, const T* thresholds,
                       const T* weights, std::size_t n, T* state, std::span<const double> input,
                       T* output);

  //! One sample: both envelopes once, then every operator, then the weighted sum.
  static T step(const T* ascending, const T* descending, const T* __restrict thresholds,
                const T* weights, std::size_t n, T* __restrict state, double input) {
    const T up = E::value(ascending, input);
    const T down = E::value(descending, input);
    for (std::size_t j = 0; j < n; ++j)
      generalized_play_update(up, down, thresholds[j], state[j]);
    return output(weights, state, n);
  }
};

template <Envelope E, class T>
void GpiKernel<E, T>::exponential_density(const T& rho, const T& tau, const T& alpha, std::size_t m,
                                          T* thresholds, T* weights) {
  using std::exp;
  for (std::size_t j = 0; j <= m; ++j) {
    thresholds[j] = alpha * static_cast<double>(j);
    weights[j] = rho * exp(-tau * thresholds[j]);
  }
}

template <Envelope E, class T>
void GpiKernel<E, T>::rest_state(const T* ascending, const T* descending, double v0,
                                 LoopBranch branch, std::size_t n, T* state) {
  const T value =
      branch == LoopBranch::ascending ? E::value(ascending, v0) : E::value(descending, v0);
  for (std::size_t j = 0; j < n; ++j)
    state[j] = value;
}

template <Envelope E, class T>
void GpiKernel<E, T>::simulate(const T* ascending, const T* descending, const T* thresholds,
                               const T* weights, std::size_t n, T* state,
                               std::span<const double> input, T* output) {
  for (std::size_t k = 0; k < input.size(); ++k)
    output[k] = step(ascending, descending, thresholds, weights, n, state, input[k]);
}

//! The GPI model with envelope type E (TanhEnvelope by default; LinearEnvelope, ArctanEnvelope).
template <Envelope E = TanhEnvelope>
class GeneralizedPrandtlIshlinskii {
 public:
  using Params = GpiParams;
  using EnvelopeType = E;
  struct State {
    std::vector<double> play;  //!< z_j [envelope units], one per operator
  };

  //! Validates the parameters; throws hyst::Error naming the first one that breaks a rule, with
  //! Error::field() set (e.g. "GPI density rho = -0.1 must be > 0", field "rho").
  explicit GeneralizedPrandtlIshlinskii(Params params);

  const Params& params() const { return params_; }
  //! Number of operators, m + 1.
  std::size_t size() const { return thresholds_.size(); }
  //! r_j [envelope units] (computed from alpha for the exponential density).
  const std::vector<double>& thresholds() const { return thresholds_; }
  //! p_j [-] (computed from rho, tau for the exponential density).
  const std::vector<double>& weights() const { return weights_; }
  //! S = sum_j p_j: the output of a state with every z_j = 1.
  double weight_sum() const;

  //! gamma_l(v) and gamma_r(v) [envelope units].
  double ascending(double input) const { return E::value(params_.ascending.data(), input); }
  double descending(double input) const { return E::value(params_.descending.data(), input); }
  //! The classical PI with the same thresholds and weights (no offset): the GPI with identity
  //! envelopes, and the operator whose inverse the inverse GPI uses.
  PrandtlIshlinskii classical() const;

  //! At rest at params().initial_input, arrived rising: every z_j = gamma_l(i0).
  State initial_state() const;
  //! At rest at `input`: every z_j = gamma_l(input) (ascending) or gamma_r(input) (descending).
  //! Throws hyst::Error for a non-finite input.
  State state_at_rest(double input, LoopBranch branch = LoopBranch::ascending) const;
  //! A given state; throws hyst::Error if its size is wrong, a value is not finite, or no input
  //! history reaches it (|z_j - z_{j-1}| > r_j - r_{j-1}, the same rule as for the classical PI).
  State make_state(std::vector<double> play) const;

  //! Output of the model in a given state, without advancing it.
  double output(const State& state) const;

  //! Advances one sample: both envelopes once, every operator, the weighted sum. No allocation,
  //! no virtual call. Precondition: `state` comes from this model and `input` is finite.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    HYST_ASSERT(state.play.size() == thresholds_.size(), "state of another model");
    return GpiKernel<E, double>::step(params_.ascending.data(), params_.descending.data(),
                                      thresholds_.data(), weights_.data(), thresholds_.size(),
                                      state.play.data(), input);
  }

 private:
  Params params_;
  std::vector<double> thresholds_;
  std::vector<double> weights_;
};

//! The model that gives the same output for every input (the exact scaling symmetry of the file
//! comment): envelope output coefficients and thresholds divided by `factor`, weights multiplied
//! by it (exponential: rho * factor, tau * factor, alpha / factor). Throws hyst::Error unless
//! factor is finite and > 0. States map by z / factor.
GpiParams rescale_density(const GpiParams& params, double factor);

extern template struct GpiKernel<LinearEnvelope, double>;
extern template struct GpiKernel<TanhEnvelope, double>;
extern template struct GpiKernel<ArctanEnvelope, double>;
extern template class GeneralizedPrandtlIshlinskii<LinearEnvelope>;
extern template class GeneralizedPrandtlIshlinskii<TanhEnvelope>;
extern template class GeneralizedPrandtlIshlinskii<ArctanEnvelope>;

}  // namespace hyst
