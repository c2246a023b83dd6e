#pragma once
//! \file
//! Identification of the Duhem (Coleman-Hodgdon) model (duhem.hpp) and of its special case, the
//! backlash-like model (backlash_like.hpp), from one input/output record with Ceres
//! (Levenberg-Marquardt, automatic derivatives; RK4 for Duhem, the exact solution for
//! backlash-like). The simulation starts at the first sample with the measured first output.
//!
//! Duhem: theta = (alpha, f_slope, f_sat, v_sat, r) with g_peak = r f_sat / v_sat, r in [-1, 1]
//! (so that f' >= g holds by construction) and g(0) >= 0 enforced. Backlash-like: theta =
//! (a, c, r) with B1 = r c, r in [-1, 0.999] (B1 < c). Bounds scale with the input span dv and
//! the output span dy; several starts from these scales.

#include <cstddef>
#include <span>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/backlash_like.hpp"
#include "hyst/models/duhem.hpp"

namespace hyst {

struct DuhemFitOptions {
  std::size_t substeps = 20;
  //! Cost evaluations of the global stage (NLopt CRS2-LM over the bounded box) before the
  //! local starts; its best point is one more start. 0: data-derived starts only.
  std::size_t global_evaluations = 300;
  std::size_t screening_iterations = 10;
  std::size_t max_iterations = 100;
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  double validate_fraction = 0.0;  //!< last part of the record held out, [0, 1)
};

struct DuhemFit {
  Duhem model;
  Duhem::State initial_state;  //!< first input, first measured output
  FitReport report;            //!< model "duhem"
};

struct BacklashLikeFit {
  BacklashLike model;
  BacklashLike::State initial_state;  //!< first input, first measured output
  FitReport report;                   //!< model "backlash_like"
};

//! Throws hyst::Error for invalid data (lengths, non-finite, constant, too few samples).
DuhemFit fit_duhem(std::span<const double> input, std::span<const double> output,
                   const DuhemFitOptions& options = {});
BacklashLikeFit fit_backlash_like(std::span<const double> input, std::span<const double> output,
                                  const DuhemFitOptions& options = {});

}  // namespace hyst
