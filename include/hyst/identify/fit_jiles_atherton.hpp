#pragma once
//! \file
//! Identification of the Jiles-Atherton model (jiles_atherton.hpp) from measured B(H) loops by
//! nonlinear least squares with Ceres Solver.
//!
//!     theta = (M_s, a, k, c, alpha)
//!     min_theta sum_loops sum_k ( B_meas[k] - B_theta[H_meas][k] )^2,   theta within bounds
//!
//! Each loop is simulated in steady state: from the demagnetised state the field rises to the
//! loop's first sample, the loop is run once (warm-up), and the residuals are taken on the second
//! pass (a measured loop is one period of a periodic excitation). Integration: by default the
//! model's own (RK4 under error control, jiles_atherton.hpp); the start costs, the global stage
//! and the screening rank parameter sets with a 100 times larger step error, the refinement runs
//! at the model's. With max_field_step > 0: fixed RK4 steps of min(max_field_step, k / 20)
//! (dM/dH ~ 1/k: larger steps make RK4 unstable for small k), which the returned model keeps.
//!
//! Method: Levenberg-Marquardt (Ceres, dense QR) with automatic derivatives through the RK4
//! integration (forward mode: the simulation runs in inlined dual numbers, copied into Ceres' Jets;
//! the values are those of the double simulation; the step sizes follow from the values, so the
//! derivatives are those of the discrete map), parameters scaled by the first start. Starts
//! (from the data): M_s = 1.1 max(B/mu0 - H); k = the coercive field H_c (where B crosses 0); a in
//! {H_c, 3 H_c}; c in {0.2, 0.8}; alpha = 0 and alpha = a / M_s. Candidate steps with alpha M_s /
//! (3 a) >= 0.99 are rejected. Every start runs screening_iterations; the best refined_starts
//! continue, the lowest final cost wins. report.termination is Ceres' own verdict.

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/jiles_atherton.hpp"

namespace hyst {

//! One closed B(H) loop (one period), H [A/m] and B [T].
//! One closed B(H) loop (one period): input = H [A/m], output = B [T].
using BhLoop = FitRecord;

struct JilesAthertonFitOptions {
  JilesAthertonVariant variant = JilesAthertonVariant::original;
  std::vector<JilesAtherton::Params> starts;  //!< empty = the data-derived starts
  double max_field_step = 0.0;                //!< [A/m]; 0 = RK4 under error control
  //! Cost evaluations of the global stage (NLopt CRS2-LM over the bounded box) before the
  //! local starts; its best point is one more start. 0 (default, since every evaluation
  //! simulates every loop): the data-derived starts only.
  std::size_t global_evaluations = 0;
  std::size_t screening_iterations = 8;
  //! The best this many starts after screening continue up to max_iterations; the lowest final
  //! cost wins (the cost has several valleys, e.g. c near 0 and near 1 on the amorphous loop).
  std::size_t refined_starts = 3;
  std::size_t max_iterations = 2000;
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  double function_tolerance = 1e-9;
  //! true: every loop is one period in steady state (file comment); false: every record starts
  //! from the demagnetised state at H = 0 (e.g. a first-magnetisation record).
  bool periodic = true;
};

struct JilesAthertonFit {
  JilesAtherton model;
  FitReport report;  //!< model "jiles_atherton"; validation over the `validation` loops
  std::size_t starts = 0;
  std::size_t best_start = 0;
};

//! Fits one model to `loops` (usually the largest measured loop), predicts `validation` loops
//! (may be empty). Throws hyst::Error for invalid loops (lengths differ, fewer than 8 samples,
//! non-finite or constant data) or options.
JilesAthertonFit fit_jiles_atherton(std::span<const BhLoop> loops,
                                    std::span<const BhLoop> validation,
                                    const JilesAthertonFitOptions& options);

//! B along a loop: periodic = steady state (demagnetised, rise to the first sample, one warm-up
//! period), otherwise from the demagnetised state at H = 0.
std::vector<double> simulate_bh_loop(const JilesAtherton& model, std::span<const double> field,
                                     bool periodic = true);

//! The data-derived starts of the file comment.
std::vector<JilesAtherton::Params> jiles_atherton_starts(const BhLoop& loop,
                                                         JilesAthertonVariant variant);

}  // namespace hyst
