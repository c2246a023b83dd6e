#pragma once
//! \file
//! Envelope functions of the generalized play operator and the generalized Prandtl-Ishlinskii
//! model (GPI): the ascending (loading) curve gamma_l and the descending (unloading) curve gamma_r.
//!
//!     linear:  gamma(v) = c0 v + c1                       c0 > 0           range (-inf, inf)
//!     tanh:    gamma(v) = c0 tanh(c1 v + c2) + c3         c0 c1 > 0        range (c3 - |c0|, c3 +
//!     |c0|) arctan:  gamma(v) = c0 atan(c1 v + c2) + c3         c0 c1 > 0        range (c3 - |c0|
//!     pi/2,
//!                                                                                 c3 + |c0| pi/2)
//!
//! The tanh envelope is the one of the GPI papers (gamma_l with a0..a3, gamma_r with b0..b3); the
//! linear one with c0 = 1, c1 = 0 turns the GPI into the classical PI model; the arctan one
//! saturates more slowly (algebraically instead of exponentially). Every envelope is strictly
//! increasing (the slope conditions above); values [output units of the model / the density],
//! input v [input units].
//!
//! Inverses (used by the inverse GPI):
//!
//!     linear:  v = (u - c1) / c0
//!     tanh:    v = (atanh((u - c3) / c0) - c2) / c1,   |u - c3| < |c0|
//!     arctan:  v = (tan((u - c3) / c0) - c2) / c1,      |u - c3| < |c0| pi/2
//!
//! A value u outside the open range of a saturating envelope has no preimage: inverse() then
//! clamps the atanh argument to +-(1 - 1e-12) (the tan argument to +-(1 - 1e-12) pi/2), returns the
//! large but finite input this gives and the status below_range / above_range (a NaN value gives
//! the lower end and below_range). It never throws.
//!
//! The envelope is a compile-time choice: each kind is a type with static functions, passed as a
//! template parameter to GeneralizedPlay, GeneralizedPrandtlIshlinskii and their inverse, so a
//! sample costs no virtual call. `value()` is a template on the scalar type, so that the fitter can
//! evaluate it with Ceres Jets (automatic derivatives). EnvelopeKind names the kinds at run time
//! (model files, CLI, Python).
//!
//! Pitfalls: the coefficients of gamma_l and gamma_r must keep gamma_l <= gamma_r on the operating
//! range (checked by check_envelope_ordering() at construction); swapping them gives a model that
//! has no memory and an inverse that is wrong by the whole loop width. The coefficients are in
//! output units divided by the density's sum S = sum_j p_j ("u-space"), not in output units.
//! Sources: Al Janaideh, Rakheja & Su (2009), Smart Mater. Struct. 18:045001; Al Janaideh, Rakheja
//! & Su (2011), IEEE/ASME TMech 16(4):734-744.

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <numbers>
#include <span>
#include <string_view>
#include <type_traits>

#include "hyst/core/enum_names.hpp"
#include "hyst/core/inverse_status.hpp"

namespace hyst {

//! The envelope kinds, named "linear", "tanh", "arctan" at run time.
enum class EnvelopeKind : unsigned char { linear, tanh, arctan };

//! "linear", "tanh" or "arctan".
constexpr EnumNames<EnvelopeKind, 3> enumerator_names(EnvelopeKind) {
  return {{
      {EnvelopeKind::linear, "linear"},
      {EnvelopeKind::tanh, "tanh"},
      {EnvelopeKind::arctan, "arctan"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text
//! ("unknown envelope 'cubic' (expected linear, tanh or arctan)").
EnvelopeKind envelope_kind_from_string(std::string_view text);

//! The open interval of values an envelope takes [its output units]; may be infinite.
struct EnvelopeRange {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool contains(double u) const { return u > lower && u < upper; }
};

//! Which envelope a set of coefficients belongs to, for error messages: the model ("GPI"), the
//! curve ("ascending") and the letter of its coefficients ('a' gives "a0", "a1", ...).
struct EnvelopeLabel {
  std::string_view model = "GPI";
  std::string_view curve = "ascending";  //!< also the Params field name
  char letter = 'a';
};

//! tanh(w) from one exponential: t = exp(-2|w|) in (0, 1], tanh(w) = sign(w) (1 - t) / (1 + t).
//! About twice as fast as glibc's tanh (the envelopes dominate the cost of a GPI step), never
//! overflows, absolute error below 4e-16 (relative accuracy is lost only where |tanh w| < 1e-3,
//! which the envelope's c3 offset absorbs anyway). With Ceres Jets its derivative is
//! 4t / (1 + t)^2 = sech^2(w), also without overflow; model and fitter share this formula.
template <class T>
inline T tanh_by_exp(const T& w) {
  using std::exp;
  if constexpr (std::is_floating_point_v<T>) {
    const T t = exp(-2 * std::abs(w));
    return std::copysign((1 - t) / (1 + t), w);
  } else {
    if (w < 0.0) {
      const T t = exp(2.0 * w);
      return (t - 1.0) / (t + 1.0);
    }
    const T t = exp(-2.0 * w);
    return (1.0 - t) / (1.0 + t);
  }
}

//! gamma(v) = c0 v + c1 with c0 > 0. Unbounded: the inverse never saturates.
struct LinearEnvelope {
  static constexpr EnvelopeKind kind = EnvelopeKind::linear;
  static constexpr std::size_t coefficient_count = 2;

  template <class T, class V>
  static T value(const T* c, const V& v) {
    return c[0] * v + c[1];
  }
  static InverseSample inverse(const double* c, double u) noexcept {
    return {(u - c[1]) / c[0], InverseStatus::ok};
  }
  static EnvelopeRange range(const double*) noexcept { return {}; }
  //! Multiplies the output by `factor` (> 0): the coefficients of factor * gamma.
  template <class T>
  static void scale_output(T* c, const T& factor) {
    c[0] *= factor;
    c[1] *= factor;
  }
  //! Throws hyst::Error unless there are 2 finite coefficients with c0 > 0.
  static void validate(std::span<const double> c, const EnvelopeLabel& label);
};

//! gamma(v) = c0 tanh(c1 v + c2) + c3 with c0 c1 > 0 (convention c0, c1 > 0).
struct TanhEnvelope {
  static constexpr EnvelopeKind kind = EnvelopeKind::tanh;
  static constexpr std::size_t coefficient_count = 4;
  //! The atanh argument is clamped to +-(1 - saturation_margin).
  static constexpr double saturation_margin = 1e-12;

  template <class T, class V>
  static T value(const T* c, const V& v) {
    return c[0] * tanh_by_exp(T(c[1] * v + c[2])) + c[3];
  }
  static InverseSample inverse(const double* c, double u) noexcept {
    constexpr double limit = 1.0 - saturation_margin;
    const double x = (u - c[3]) / c[0];
    if (x > -limit && x < limit) return {(std::atanh(x) - c[2]) / c[1], InverseStatus::ok};
    // Above the range (u > c3) the input goes to its upper end, whatever the common sign of c0, c1.
    const bool above = u > c[3];
    const double clamped = above == (c[0] > 0.0) ? limit : -limit;
    return {(std::atanh(clamped) - c[2]) / c[1],
            above ? InverseStatus::above_range : InverseStatus::below_range};
  }
  static EnvelopeRange range(const double* c) noexcept {
    return {c[3] - std::abs(c[0]), c[3] + std::abs(c[0])};
  }
  template <class T>
  static void scale_output(T* c, const T& factor) {
    c[0] *= factor;
    c[3] *= factor;
  }
  //! Throws hyst::Error unless there are 4 finite coefficients with c0 c1 > 0.
  static void validate(std::span<const double> c, const EnvelopeLabel& label);
};

//! gamma(v) = c0 atan(c1 v + c2) + c3 with c0 c1 > 0 (convention c0, c1 > 0).
struct ArctanEnvelope {
  static constexpr EnvelopeKind kind = EnvelopeKind::arctan;
  static constexpr std::size_t coefficient_count = 4;
  //! The tan argument is clamped to +-(1 - saturation_margin) pi/2.
  static constexpr double saturation_margin = 1e-12;

  template <class T, class V>
  static T value(const T* c, const V& v) {
    using std::atan;
    return c[0] * atan(c[1] * v + c[2]) + c[3];
  }
  static InverseSample inverse(const double* c, double u) noexcept {
    constexpr double limit = (1.0 - saturation_margin) * std::numbers::pi / 2;
    const double x = (u - c[3]) / c[0];
    if (x > -limit && x < limit) return {(std::tan(x) - c[2]) / c[1], InverseStatus::ok};
    const bool above = u > c[3];
    const double clamped = above == (c[0] > 0.0) ? limit : -limit;
    return {(std::tan(clamped) - c[2]) / c[1],
            above ? InverseStatus::above_range : InverseStatus::below_range};
  }
  static EnvelopeRange range(const double* c) noexcept {
    const double half = std::abs(c[0]) * std::numbers::pi / 2;
    return {c[3] - half, c[3] + half};
  }
  template <class T>
  static void scale_output(T* c, const T& factor) {
    c[0] *= factor;
    c[3] *= factor;
  }
  //! Throws hyst::Error unless there are 4 finite coefficients with c0 c1 > 0.
  static void validate(std::span<const double> c, const EnvelopeLabel& label);
};

//! What GeneralizedPlay and GeneralizedPrandtlIshlinskii need from an envelope type.
template <class E>
concept Envelope = requires(const double* c, double u, std::span<const double> coefficients,
                            const EnvelopeLabel& label) {
  { E::kind } -> std::convertible_to<EnvelopeKind>;
  { E::coefficient_count } -> std::convertible_to<std::size_t>;
  { E::value(c, u) } -> std::same_as<double>;
  { E::inverse(c, u) } -> std::same_as<InverseSample>;
  { E::range(c) } -> std::same_as<EnvelopeRange>;
  E::validate(coefficients, label);
};

//! Number of grid points check_envelope_ordering() evaluates (both ends included).
inline constexpr std::size_t kEnvelopeOrderingGrid = 2001;

//! Checks the ordering gamma_l(v) <= gamma_r(v) at kEnvelopeOrderingGrid equally spaced inputs of
//! the operating range [input_min, input_max] (a rounding slack of 1e-12 relative is allowed, so
//! equal envelopes pass). Throws hyst::Error naming the first input where it fails, with field
//! "descending". Also throws unless the range is finite with input_min < input_max (fields
//! "input_min", "input_max"). The coefficients must have been validated.
template <Envelope E>
void check_envelope_ordering(const double* ascending, const double* descending, double input_min,
                             double input_max, std::string_view model);

//! Calls `f(E{})` with the envelope type of `kind`: the bridge from a run-time name (model file,
//! CLI) to the compile-time choice.
template <class F>
decltype(auto) visit_envelope(EnvelopeKind kind, F&& f) {
  switch (kind) {
    case EnvelopeKind::linear:
      return f(LinearEnvelope{});
    case EnvelopeKind::arctan:
      return f(ArctanEnvelope{});
    case EnvelopeKind::tanh:
      break;
  }
  return f(TanhEnvelope{});
}

extern template void check_envelope_ordering<LinearEnvelope>(const double*, const double*, double,
                                                             double, std::string_view);
extern template void check_envelope_ordering<TanhEnvelope>(const double*, const double*, double,
                                                           double, std::string_view);
extern template void check_envelope_ordering<ArctanEnvelope>(const double*, const double*, double,
                                                             double, std::string_view);

}  // namespace hyst
