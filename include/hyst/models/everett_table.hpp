#pragma once
//! \file
//! A tabulated Everett function with bilinear interpolation: the Preisach model as identified
//! from measured first-order reversal curves (fit_preisach.hpp) or any other table.
//!
//! Levels x_0 < x_1 < ... < x_K [input units] (not necessarily uniform) and the values
//!
//!     E_ac = E(x_a, x_c),   0 <= c < a <= K        [output units],   E(x_a, x_a) = 0,
//!
//! stored row by row at index a(a-1)/2 + c (K(K+1)/2 values). Between the levels:
//! - in a cell [x_i, x_{i+1}] x [x_j, x_{j+1}] with i > j: bilinear interpolation of its corners;
//! - in a diagonal cell (i = j), only its half alpha >= beta matters: linear interpolation on the
//!   triangle (x_i, x_i), (x_{i+1}, x_i), (x_{i+1}, x_{i+1}), i.e. E = E_{i+1,i} (s - t) with
//!   s, t the fractional positions of alpha and beta in the cell. This keeps E(u, u) = 0 (the
//!   output is continuous at reversals, which plain bilinear interpolation would break) and puts
//!   the cell's weight on the diagonal alpha = beta: a reversible part, linear in the input over
//!   one cell after each reversal.
//! Arguments are clamped to [x_0, x_K] (saturation outside it) and E = 0 for alpha <= beta.
//!
//! The table must describe a non-negative Preisach density: every cell weight
//!
//!     mu_ij = E_{i+1,j} - E_{i,j} - E_{i+1,j+1} + E_{i,j+1} >= 0   (i > j),   mu_ii = E_{i+1,i} >=
//!     0
//!
//! (with E_aa = 0), up to a rounding slack of 1e-10 max|E|. Then E grows with alpha and falls
//! with beta, the model output is monotone in the input and the bracketed inverse applies. The
//! total weight is F0 = E_K0. FORC relation (Mayergoyz 1991): a curve from negative saturation up
//! to alpha and down to beta gives E(alpha, beta) = (f_alpha - f_alpha,beta) / 2.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace hyst {

class TabulatedEverett {
 public:
  struct Params {
    std::vector<double> levels;  //!< x_0 < ... < x_K [input units], K >= 1, finite
    //! E(x_a, x_c) for c < a [output units], K(K+1)/2 values at index a(a-1)/2 + c
    std::vector<double> values;
  };

  //! Validates; throws hyst::Error naming the field, e.g. "tabulated Everett cell weight mu(3, 1)
  //! = E[4,1] - E[3,1] - E[4,2] + E[3,2] = -0.2 must be >= 0".
  explicit TabulatedEverett(Params params);

  const Params& params() const { return params_; }
  std::span<const double> levels() const { return params_.levels; }
  double lower() const { return params_.levels.front(); }
  double upper() const { return params_.levels.back(); }
  double total() const { return total_; }

  //! E(alpha, beta) interpolated as in the file comment; any arguments, +-inf included.
  double operator()(double alpha, double beta) const noexcept {
    const double* x = params_.levels.data();
    const double a = alpha < x[0] ? x[0] : (alpha > x[k_] ? x[k_] : alpha);
    const double b = beta < x[0] ? x[0] : (beta > x[k_] ? x[k_] : beta);
    if (!(a > b)) return 0.0;
    const std::size_t i = cell(a);
    const std::size_t j = cell(b);
    const double s = (a - x[i]) * inverse_width_[i];
    const double t = (b - x[j]) * inverse_width_[j];
    const double* row = &grid_[i * stride_];  // E(x_i, .); the next row is E(x_{i+1}, .)
    if (i == j) return row[stride_ + j] * (s - t);
    const double lower_row = (1 - t) * row[j] + t * row[j + 1];
    const double upper_row = (1 - t) * row[stride_ + j] + t * row[stride_ + j + 1];
    return (1 - s) * lower_row + s * upper_row;
  }
  double diagonal_tie(double) const noexcept { return 0.0; }

  //! The table entries that E(alpha, beta) interpolates, with their weights:
  //! E(alpha, beta) = sum_{n < size} weight[n] * E(x_{alpha_level[n]}, x_{beta_level[n]}) (entries
  //! with alpha_level <= beta_level, which are 0, are left out). E is linear in the table, so fits
  //! (fit_preisach.hpp) build their regressors from this.
  struct Stencil {
    std::array<std::size_t, 4> alpha_level{};
    std::array<std::size_t, 4> beta_level{};
    std::array<double, 4> weight{};
    std::size_t size = 0;
  };
  Stencil stencil(double alpha, double beta) const noexcept;

  //! preisach_midpoint_staircase(x_0, x_K, 64).
  std::vector<double> demagnetising_input() const;

  //! The cell index i with x_i <= u <= x_{i+1}, for x_0 <= u <= x_K: O(1) for uniform levels,
  //! a binary search otherwise.
  std::size_t cell(double u) const noexcept;

 private:
  Params params_;
  std::size_t k_ = 0;                  // K
  std::size_t stride_ = 0;             // K + 1
  std::vector<double> grid_;           // E(x_a, x_c) at a * stride_ + c, zero for c >= a
  std::vector<double> inverse_width_;  // 1 / (x_{i+1} - x_i)
  double total_ = 0.0;
  double inverse_spacing_ = 0.0;  // K / (x_K - x_0), for the first guess of cell()
};

//! Index of E(x_a, x_c), c < a, in TabulatedEverett::Params::values: a(a-1)/2 + c.
constexpr std::size_t everett_table_index(std::size_t a, std::size_t c) {
  return a * (a - 1) / 2 + c;
}

}  // namespace hyst
