#pragma once
//! \file
//! Identification of the Bouc-Wen model (bouc_wen.hpp) from one displacement/force record, in
//! its identifiable normalised parameters (rho, sigma, n, kx, kw), with Ceres
//! (Levenberg-Marquardt, automatic derivatives through the RK4 integration in the input).
//! Bounds: rho in [1e-3, 1e3] / input span, sigma in [0.5, 5] (the bounded class), n in [1, 5]
//! (held at 1 unless fit_n), kx in [0, 10 slope], kw in [0, 10 output span], slope = output span /
//! input span. Starts: rho in {2, 8} / input span x sigma in {0.6, 0.9}, kx = kw rho = slope / 2.
//! The simulation starts at the first sample with z = 0. Returns the model in standard form
//! (A = 1, from_normalised()).

#include <cstddef>
#include <span>

#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/bouc_wen.hpp"

namespace hyst {

struct BoucWenFitOptions {
  bool fit_n = false;  //!< also fit the exponent n (>= 1)
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

struct BoucWenFit {
  BoucWen model;
  BoucWen::State initial_state;  //!< at the first sample, z = 0
  FitReport report;              //!< model "bouc_wen"
};

//! Throws hyst::Error for invalid data (lengths, non-finite, constant, too few samples).
BoucWenFit fit_bouc_wen(std::span<const double> input, std::span<const double> output,
                        const BoucWenFitOptions& options = {});

}  // namespace hyst
