#pragma once
//! \file
//! Everett functions of continuous Preisach models with a factorised density: the Gaussian and
//! the Lorentzian.
//!
//!     mu(alpha, beta) = A f(alpha) g(beta)      on T0 = {lower <= beta <= alpha <= upper}, else 0
//!     f(alpha) = p((alpha - alpha_c) / w_alpha),   g(beta) = p((beta - beta_c) / w_beta)
//!     Gaussian:    p(x) = exp(-x^2 / 2),   P(x) = integral p = sqrt(pi/2) erf(x / sqrt 2)
//!     Lorentzian:  p(x) = 1 / (1 + x^2),   P(x) = integral p = atan(x)
//!
//! alpha_c is the switch-up field where the density peaks, beta_c the switch-down field
//! (typically alpha_c = +H_c, beta_c = -H_c for a coercive field H_c), w the widths (Gaussian
//! standard deviation, Lorentzian half width at half maximum) [input units]. The factorised
//! Lorentzian is the classical "factorized Lorentzian" Preisach distribution of magnetic
//! recording media (Bate 1962; Bertotti 1998, "Hysteresis in Magnetism", ch. 9). With equal
//! widths w_alpha = w_beta = w the Gaussian is also a product of Gaussians in the interaction
//! coordinate (alpha + beta)/2 and the coercive coordinate (alpha - beta)/2, both of standard
//! deviation w / sqrt 2, centred at (alpha_c + beta_c)/2 and (alpha_c - beta_c)/2 (the
//! Gaussian-in-(alpha+beta)/2-and-(alpha-beta) density of the reference, preisach.md sec. 7).
//!
//! The amplitude A is set so that the total weight F0 = E(upper, lower) equals `saturation`: the
//! output then spans [offset - F0, offset + F0] and saturates for inputs outside [lower, upper].
//!
//! Everett function, with F(x) = integral_lower^x f, G(x) = integral_lower^x g (closed forms with
//! P) and H(x) = integral_lower^x f(a) G(a) da, for lower <= beta <= alpha <= upper:
//!
//!     E(alpha, beta) = A integral_beta^alpha f(a) (G(a) - G(beta)) da
//!                    = A [ H(alpha) - H(beta) - G(beta) (F(alpha) - F(beta)) ]
//!
//! and arguments outside [lower, upper] are clamped to it (E = 0 for alpha <= beta). H has no
//! elementary form; it is tabulated on a uniform grid (at least 256 points per density width,
//! 2^10 .. 2^16 intervals) from 10-point Gauss-Legendre integrals and evaluated by cubic Hermite
//! interpolation with the exact derivative H' = f G. F and G are tabulated on the same nodes from
//! their closed forms (derivatives f, g), so that an evaluation costs two cell look-ups and five
//! cubic interpolations, no erf/atan call. E stays within ~1e-12 of F0 of a 2-D quadrature of
//! the density (tested).

#include <cstddef>
#include <string_view>
#include <vector>

namespace hyst {

//! p(x) = exp(-x^2/2), P(x) = sqrt(pi/2) erf(x/sqrt 2).
struct GaussianProfile {
  static constexpr std::string_view name = "Gaussian";
  static double density(double x) noexcept;
  static double integral(double x) noexcept;
};

//! p(x) = 1/(1 + x^2), P(x) = atan(x).
struct LorentzianProfile {
  static constexpr std::string_view name = "Lorentzian";
  static double density(double x) noexcept;
  static double integral(double x) noexcept;
};

template <class Profile>
class FactorisedEverett {
 public:
  struct Params {
    double lower = -1.0;        //!< lower end of the support, the negative saturation input
    double upper = 1.0;         //!< upper end, > lower [input units]
    double saturation = 1.0;    //!< F0 = total weight, > 0 [output units]
    double alpha_centre = 0.0;  //!< alpha_c, peak of f [input units], finite
    double alpha_width = 0.0;   //!< w_alpha > 0 [input units]
    double beta_centre = 0.0;   //!< beta_c, peak of g [input units], finite
    double beta_width = 0.0;    //!< w_beta > 0 [input units]
  };

  //! Validates and tabulates H; throws hyst::Error naming the field, e.g.
  //! "Gaussian Preisach alpha_width = 0 must be > 0".
  explicit FactorisedEverett(Params params);

  const Params& params() const { return params_; }
  double lower() const { return params_.lower; }
  double upper() const { return params_.upper; }
  double total() const { return params_.saturation; }
  //! A [output units / input units^2].
  double amplitude() const { return amplitude_; }
  //! mu(alpha, beta) [output units / input units^2], 0 outside T0.
  double density(double alpha, double beta) const noexcept;

  //! E(alpha, beta) (file comment); any arguments, +-inf included.
  double operator()(double alpha, double beta) const noexcept {
    const double a = clamp(alpha);
    const double b = clamp(beta);
    if (!(a > b)) return 0.0;
    const Interpolated at_a = interpolate(a);
    const Interpolated at_b = interpolate(b);
    return amplitude_ * (at_a.h - at_b.h - at_b.g * (at_a.f - at_b.f));
  }
  //! No relay sits exactly on a level: 0.
  double diagonal_tie(double) const noexcept { return 0.0; }
  //! preisach_midpoint_staircase(lower, upper, 64).
  std::vector<double> demagnetising_input() const;

 private:
  // H, F, G at one point by cubic Hermite interpolation on the node table.
  struct Interpolated {
    double h;
    double f;
    double g;
  };
  static constexpr std::size_t kNodeStride = 6;  // H, h H', F, h f, G, h g per node

  double clamp(double x) const noexcept {
    return x < params_.lower ? params_.lower : (x > params_.upper ? params_.upper : x);
  }
  // Closed forms of F and G (used to build the table).
  double big_f(double x) const noexcept {
    return params_.alpha_width *
           (Profile::integral((x - params_.alpha_centre) / params_.alpha_width) - f_at_lower_);
  }
  double big_g(double x) const noexcept {
    return params_.beta_width *
           (Profile::integral((x - params_.beta_centre) / params_.beta_width) - g_at_lower_);
  }
  // lower <= x <= upper.
  Interpolated interpolate(double x) const noexcept {
    const double s = (x - params_.lower) * inverse_step_;
    std::size_t m = static_cast<std::size_t>(s);
    if (m >= intervals_) m = intervals_ - 1;
    const double t = s - static_cast<double>(m);
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double w0 = 2 * t3 - 3 * t2 + 1;  // Hermite basis: value at m, slope at m,
    const double w1 = t3 - 2 * t2 + t;      // value at m + 1, slope at m + 1
    const double w2 = 3 * t2 - 2 * t3;
    const double w3 = t3 - t2;
    const double* n0 = &nodes_[kNodeStride * m];
    const double* n1 = n0 + kNodeStride;
    return {w0 * n0[0] + w1 * n0[1] + w2 * n1[0] + w3 * n1[1],
            w0 * n0[2] + w1 * n0[3] + w2 * n1[2] + w3 * n1[3],
            w0 * n0[4] + w1 * n0[5] + w2 * n1[4] + w3 * n1[5]};
  }

  Params params_;
  double f_at_lower_ = 0.0;  // P((lower - alpha_c) / w_alpha)
  double g_at_lower_ = 0.0;  // P((lower - beta_c) / w_beta)
  std::size_t intervals_ = 0;
  double inverse_step_ = 0.0;
  std::vector<double> nodes_;  // per node t_m, m = 0..intervals: H, h H', F, h f, G, h g
  double amplitude_ = 0.0;
};

using GaussianEverett = FactorisedEverett<GaussianProfile>;
using LorentzianEverett = FactorisedEverett<LorentzianProfile>;

extern template class FactorisedEverett<GaussianProfile>;
extern template class FactorisedEverett<LorentzianProfile>;

}  // namespace hyst
