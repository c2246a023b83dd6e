#pragma once
//! \file
//! Identification of the butterfly strain model (butterfly_strain.hpp), in two forms.
//!
//! **Direct form** (only voltage v and strain y measured; the polarisation is latent). For a
//! fixed relay grid the relay states s_r[k] = +-1 follow from the input alone (as in the Preisach
//! weight fit), so P[k] = sum_r mu_r s_r[k] and
//!
//!     min_{mu >= 0, y_off, d, q}  sum_k (y[k] - y_off - d v[k] - sum_n q_n P[k]^n)^2
//!                                 + (F0 - 1)^2 sigma_y^2 K         (F0 = sum_r mu_r)
//!
//! a bounded nonlinear least-squares problem (Levenberg-Marquardt, Ceres, analytic Jacobian
//! dy/dmu_r = (sum_n n q_n P^(n-1)) s_r). The last term fixes the scale of the latent P, which
//! the data cannot (P -> cP, q_n -> q_n / c^n gives the same strain); the result is rescaled to
//! F0 = 1 exactly. The start: for coercive voltages v_c on a grid of fractions of the input's
//! half range, a Gaussian density around (alpha, beta) = (v_c, -v_c) with width 0.15 of the half
//! range, the map fitted by linear least squares for each, the best one kept.
//!
//! **Two stages with measured polarisation** (records with v, P and y, e.g. an aixACCT
//! export's V+, P1 and D1): (1) the Preisach weights of P(v) by NNLS, (2) the map by linear least
//! squares on the model's polarisation, so that the chain v -> P -> y is the fitted model; the
//! map is also fitted on the measured polarisation and reported on its own, which checks the
//! strain-polarisation relation directly, with no hysteresis model in between. With
//! `fit_leakage`, stage 1 has one more non-negative unknown, the leakage conductance g of the
//! measured polarisation (P_meas = P + g Q, hyst/data/leakage.hpp), and the map on the measured
//! polarisation uses P_meas - g Q: a leakage charge is no polarisation and strains nothing.
//!
//! Records start in the stated state: `periodic` (default: each record is one period of a
//! periodic drive in steady state, ButterflyStrain::periodic_state() of its whole input - the
//! input only, so also when its end is held out) or a Preisach initial state.
//! Common mistakes: too few levels for a sharp switching (the coercive region needs relays of a
//! few percent of the range); records zeroed at their first sample (a usual displacement
//! convention) fitted together: their offsets differ, fit them separately or zero the
//! predictions the same way.

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "hyst/core/enum_names.hpp"
#include "hyst/core/progress.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/models/butterfly_strain.hpp"

namespace hyst {

//! Where each fitted record starts (see the file comment).
enum class ButterflyFitStart : unsigned char {
  periodic,
  negative_saturation,
  positive_saturation,
  demagnetised,
};

//! "periodic", "negative_saturation", "positive_saturation", "demagnetised".
constexpr EnumNames<ButterflyFitStart, 4> enumerator_names(ButterflyFitStart) {
  return {{
      {ButterflyFitStart::periodic, "periodic"},
      {ButterflyFitStart::negative_saturation, "negative_saturation"},
      {ButterflyFitStart::positive_saturation, "positive_saturation"},
      {ButterflyFitStart::demagnetised, "demagnetised"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
ButterflyFitStart butterfly_fit_start_from_string(std::string_view text);

struct ButterflyFitOptions {
  //! Threshold levels of the relay grid (1 .. 64); 0 = automatic: 16, or fewer for a short record
  //! (at most half as many relays as samples fitted).
  std::size_t levels = 0;
  //! Input range of the grid [input units]; not set = min and max of the fitted inputs.
  std::optional<double> lower = std::nullopt;
  std::optional<double> upper = std::nullopt;
  std::size_t degree = 2;      //!< N, degree of the polynomial in P (1 .. 8)
  bool fit_field_term = true;  //!< fit d; false = d = 0
  ButterflyFitStart start = ButterflyFitStart::periodic;
  std::size_t max_iterations = 300;  //!< Levenberg-Marquardt iterations (direct form), >= 1
  //! Told before each start of the fit and its refinement (task "starts"); may be empty.
  ProgressCallback progress{};
  double validate_fraction = 0.0;  //!< one record: held out at its end, [0, 1)
  //! Two stages: fit the leakage conductance g >= 0 of the measured polarisation with P(v)
  //! (hyst/data/leakage.hpp); the maps then see P without the leakage charge g Q.
  bool fit_leakage = false;
  double sample_time = 1.0;  //!< Ts > 0 [s] of the record, for the leakage charge
};

struct ButterflyFit {
  ButterflyStrain model;
  ButterflyStrain::State initial_state;  //!< the state the (first) record starts from
  FitReport report;                      //!< model "butterfly_strain"
};

//! Direct form, one record. Throws hyst::Error for invalid data or options.
ButterflyFit fit_butterfly_strain(std::span<const double> input, std::span<const double> output,
                                  const ButterflyFitOptions& options = {});

//! Direct form, several records of one sample fitted together (validate_fraction must be 0:
//! hold out a record instead). Throws hyst::Error naming the record ("records[1]").
ButterflyFit fit_butterfly_strain(std::span<const FitRecord> records,
                                  const ButterflyFitOptions& options = {});

//! The two-stage fit and its three reports.
struct ButterflyTwoStageFit {
  ButterflyFit fit;               //!< the chain v -> P -> y; its report is the strain's
  FitReport polarisation_report;  //!< stage 1: P(v), model "preisach"
  //! The map y(v, P) fitted on the measured polarisation, scored there (model
  //! "butterfly_strain_map", no hysteresis model involved).
  FitReport map_report;
  //! g [P units / (input units s)] with fit_leakage, else 0; the polarisation report is of
  //! Preisach(v) + g Q + offset against the measured P.
  double leakage_conductance = 0.0;
};

//! Two stages with measured polarisation (same length as input and output). Throws hyst::Error
//! for invalid data or options.
ButterflyTwoStageFit fit_butterfly_strain_with_polarisation(
    std::span<const double> input, std::span<const double> polarisation,
    std::span<const double> output, const ButterflyFitOptions& options = {});

}  // namespace hyst
