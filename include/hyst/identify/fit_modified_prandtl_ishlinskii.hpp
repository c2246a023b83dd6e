#pragma once
//! \file
//! Identification of a modified Prandtl-Ishlinskii model (PI followed by a dead-zone
//! superposition) by constrained linear least squares, in Kuhnen's equation-error form.
//!
//! y = y_off + S(Gamma[v]) is bilinear in the PI weights p and the dead-zone weights g, but the
//! equivalent relation through the inverse dead-zone map S' = S^{-1} is linear in both:
//!
//!     S'(y[k] - y_off) = q + sum_j p_j w_j[k],      S'(z) = sum_i g'_i S_{d'_i}(z),   g'_0 = 1
//!
//! (w_j: play outputs of the measured input; thresholds r_j and d'_i fixed; g'_0 = 1 fixes the
//! scale shared by Gamma and S). The constraints that make the model invertible are linear:
//! p_0 >= eps_p, p_j >= 0, and every outward partial sum of g' (a slope of S') >= eps_g. With the
//! partial sums as unknowns (g'_i = T_i - T_{i-1}, T_0 = 1) all constraints become simple bounds,
//! the free PI offset q is removed by centring, and the problem is one NNLS. The forward dead-zone
//! map is then S = S'^{-1} (DeadZoneSuperposition::inverse()), so the fitted model is monotone
//! and analytically invertible by construction. The residual minimised is in Gamma units (the
//! equation error); the report gives the output error of the simulated model.
//!
//! Defaults: thresholds as fit_prandtl_ishlinskii (uniform up to half the input range); y_off =
//! mid-range of the measured output; dead-zone thresholds d'_i = +-i h/(l+1), i = 1..l, h = the
//! distance from y_off to the output's max (min) - they are in output units relative to y_off.
//! Initial state: every play at 0 (virgin), or, for a record that is one period in steady state,
//! the periodic state of the PI part (the plays after running the input once; exact, see
//! fit_prandtl_ishlinskii.hpp).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hyst/identify/fit_prandtl_ishlinskii.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/modified_prandtl_ishlinskii.hpp"

namespace hyst {

struct ModifiedPiFitOptions {
  std::size_t operators = 10;        //!< play operators when thresholds is empty, >= 1
  std::vector<double> thresholds{};  //!< r_j [input units], 0 = r_0 < r_1 < ...; empty = uniform
  std::size_t dead_zones = 3;        //!< l dead zones per side when dead_zone_thresholds is empty
  //! d'_i of the inverse map S' [output units, relative to y_off], increasing, containing 0.
  std::vector<double> dead_zone_thresholds{};
  std::optional<double> output_offset = std::nullopt;  //!< y_off; not set = mid-range of output
  double min_weight = 1e-6;  //!< relative lower bound of p_0 and of the slopes of S', > 0
  //! virgin (plays at 0) or periodic (the record is one period in steady state).
  PiFitOptions::InitialState initial_state = PiFitOptions::InitialState::virgin;
  //! Set output_min/output_max (modified_prandtl_ishlinskii.hpp) to the fit record's output range
  //! [y_lo, y_hi] widened by output_margin (y_hi - y_lo) on each side; false = no limits.
  bool clamp_output = true;
  double output_margin = 0.0;      //!< >= 0, fraction of the fit record's output range
  double validate_fraction = 0.0;  //!< held out at the end of the record, [0, 1)
};

struct ModifiedPiFit {
  ModifiedPrandtlIshlinskii model;
  //! The play states at the first sample of the record (all 0 for virgin).
  ModifiedPrandtlIshlinskii::State initial_state;
  FitReport report;  //!< model "modified_pi", method "constrained least squares (NNLS) ..."
};

//! Throws hyst::Error for invalid data or options.
ModifiedPiFit fit_modified_prandtl_ishlinskii(std::span<const double> input,
                                              std::span<const double> output,
                                              const ModifiedPiFitOptions& options = {});

}  // namespace hyst
