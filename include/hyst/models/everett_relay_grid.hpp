#pragma once
//! \file
//! The Everett function of the discrete Preisach model: N threshold levels, one relay per pair
//! (alpha, beta) = (c_i, c_j) with i >= j, so N(N+1)/2 relays with weights mu_ij >= 0.
//!
//! Threshold levels c_0 < ... < c_{N-1} on the input range [lower, upper] [input units]:
//!
//!     cell_centred (default):  c_k = lower + (k + 1/2) (upper - lower) / N      k = 0..N-1
//!     endpoints:               c_k = lower +  k      (upper - lower) / (N - 1)
//!
//! (evaluated in this order of operations, as the reference checks do, so that e.g. the middle
//! level of N = 21 cells on [-1, 1] is exactly 0). With cell-centred levels an input equal to
//! `lower` or `upper` never ties with a threshold: v <= lower sets every relay to -1, v >= upper
//! every relay to +1. With endpoint levels the relay (c_0, c_0) switches up at v = lower (e.g. the
//! unweighted N = 21 model gives -229, not -231, at v = lower), which is why cell-centred is the
//! default. N = 21 gives the 231 relays of the seed paper; uniform weights mu_ij = 1 its
//! "unweighted" model (outputs -231 .. 231).
//!
//! Relay (i, j) is stored at index i(i+1)/2 + j (row i = switch-up level alpha = c_i, column
//! j <= i = switch-down level beta = c_j). Relay rule (relay.hpp): +1 if v >= alpha, else -1 if
//! v <= beta, else unchanged; the `>=` test comes first, so a diagonal relay (alpha = beta) is +1
//! at v = alpha.
//!
//! Everett function (exact for this grid, no interpolation):
//!
//!     E(u1, u2) = sum { mu_ij : c_i <= u1, c_j >= u2, i >= j }                [output units]
//!
//! tabulated at construction as T[a][c] = sum_{c <= j <= i <= a-1} mu_ij, a, c = 0..N, so that one
//! evaluation is two O(1) level look-ups (uniform levels) and one table read. The table has
//! (N+1)^2 entries (8 MB for N = 1001); N is limited to 4096.
//! Source: Preisach (1935); Mayergoyz (1991) ch. 1; Doong & Mayergoyz (1985) for the Everett form.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst {

//! Where the N threshold levels sit in [lower, upper] (see the file comment).
enum class PreisachGridLayout : unsigned char {
  cell_centred,  //!< centres of N equal cells: no ties at lower/upper (default)
  endpoints,     //!< N equally spaced levels including lower and upper (N >= 2)
};

//! "cell_centred", "endpoints".
constexpr EnumNames<PreisachGridLayout, 2> enumerator_names(PreisachGridLayout) {
  return {{
      {PreisachGridLayout::cell_centred, "cell_centred"},
      {PreisachGridLayout::endpoints, "endpoints"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
PreisachGridLayout preisach_grid_layout_from_string(std::string_view text);

//! N(N+1)/2, the number of relays of an N-level grid.
constexpr std::size_t preisach_relay_count(std::size_t levels) {
  return levels * (levels + 1) / 2;
}
//! Storage index of relay (i, j), i >= j: i(i+1)/2 + j.
constexpr std::size_t preisach_relay_index(std::size_t i, std::size_t j) {
  return i * (i + 1) / 2 + j;
}

//! The N threshold levels c_k [input units]. Throws hyst::Error unless 1 <= levels <= 4096
//! (>= 2 for endpoints) and lower < upper are finite.
std::vector<double> preisach_thresholds(std::size_t levels, double lower, double upper,
                                        PreisachGridLayout layout);

//! N(N+1)/2 equal weights (the seed paper's unweighted model with weight = 1).
std::vector<double> uniform_relay_weights(std::size_t levels, double weight);

class RelayGridEverett {
 public:
  struct Params {
    std::size_t levels = 21;  //!< N, number of threshold levels (1 .. 4096)
    double lower = -1.0;      //!< lower end of the input range [input units]
    double upper = 1.0;       //!< upper end, > lower [input units]
    //! mu_ij >= 0 [output units], N(N+1)/2 values, relay (i, j) at index i(i+1)/2 + j
    std::vector<double> weights;
    PreisachGridLayout layout = PreisachGridLayout::cell_centred;
  };

  //! Validates and tabulates; throws hyst::Error naming the field, e.g.
  //! "Preisach relay weight mu[12] (i = 4, j = 2) = -0.1 must be >= 0".
  explicit RelayGridEverett(Params params);

  const Params& params() const { return params_; }
  std::size_t levels() const { return params_.levels; }
  //! c_0 .. c_{N-1} [input units].
  std::span<const double> thresholds() const { return thresholds_; }
  //! Input range: at or below lower every relay is -1, at or above upper +1 (but see the
  //! endpoints layout at v = lower).
  double lower() const { return params_.lower; }
  double upper() const { return params_.upper; }
  //! F0 = sum of all weights [output units].
  double total() const { return table_[params_.levels * stride_]; }

  //! E(alpha, beta) as defined in the file comment; any arguments, +-inf included.
  double operator()(double alpha, double beta) const noexcept {
    return table_[count_at_or_below(alpha) * stride_ + count_below(beta)];
  }
  //! mu_kk if u equals a threshold c_k exactly, else 0: the diagonal relay that the `>=` rule keeps
  //! at +1 when a falling input stops exactly on it (see preisach.hpp).
  double diagonal_tie(double u) const noexcept {
    const std::size_t k = count_below(u);
    return k < params_.levels && thresholds_[k] == u ? diagonal_[k] : 0.0;
  }
  //! The alternating input that takes the grid from negative saturation to the demagnetised state
  //! (relay (i, j) at +1 iff i + j <= N - 2): maxima and minima between neighbouring thresholds,
  //! closing in from both ends.
  std::vector<double> demagnetising_input() const;

  //! #{k : c_k <= u}, O(1) for the uniform levels.
  std::size_t count_at_or_below(double u) const noexcept {
    const double* c = thresholds_.data();
    const std::size_t n = params_.levels;
    if (!(u >= c[0])) return 0;
    if (u >= c[n - 1]) return n;
    std::size_t k = guess(u);
    while (c[k + 1] <= u)
      ++k;
    while (c[k] > u)
      --k;
    return k + 1;  // c[k] <= u < c[k + 1]
  }
  //! #{k : c_k < u}, O(1) for the uniform levels.
  std::size_t count_below(double u) const noexcept {
    const double* c = thresholds_.data();
    const std::size_t n = params_.levels;
    if (!(u > c[0])) return 0;
    if (u > c[n - 1]) return n;
    std::size_t k = guess(u);
    while (c[k + 1] < u)
      ++k;
    while (c[k] >= u)
      --k;
    return k + 1;  // c[k] < u <= c[k + 1]
  }

 private:
  // Level index near u for c_0 < u < c_{N-1}, in [0, N-2]; the callers correct it by +-1.
  std::size_t guess(double u) const noexcept {
    const double g = (u - thresholds_[0]) * inverse_spacing_;
    const auto k = static_cast<std::size_t>(g > 0.0 ? g : 0.0);
    return k < params_.levels - 1 ? k : params_.levels - 2;
  }

  Params params_;
  std::vector<double> thresholds_;
  std::vector<double> diagonal_;  // mu_kk
  std::vector<double> table_;     // T[a][c] at a * stride_ + c
  std::size_t stride_ = 0;        // N + 1
  double inverse_spacing_ = 0.0;
};

}  // namespace hyst
