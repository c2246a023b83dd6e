#pragma once
//! \file
//! The yardstick of every ranking: simple predictors fitted on the same fit part and scored on
//! the same held-out part as the hysteresis models. A model that does not beat the best of them
//! has learnt nothing these do not already know.
//!
//! - mean: the mean of the fit part's output, held constant;
//! - last value held: the last output of the fit part, held constant (wins on records that end
//!   in a long hold);
//! - polynomial y(v): a static least-squares polynomial of the input (degree 3; no memory, so no
//!   hysteresis: what a model gains over it is what its memory explains);
//! - ARX(2,2): the linear model y[k] = a1 y[k-1] + a2 y[k-2] + b0 v[k] + b1 v[k-1] + c fitted by
//!   least squares (one-step equation error) on the fit part, then run in free run over the
//!   held-out part from the fit part's last two outputs. It treats the samples as a time series;
//!   it is left out where the record is not one (a record resampled on an input grid).
//!
//! All least-squares problems are solved with Eigen's column-pivoting QR on centred and scaled
//! data.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hyst/identify/data_split.hpp"
#include "hyst/identify/error_metrics.hpp"

namespace hyst {

//! One reference predictor scored on held-out samples.
struct ReferenceScore {
  std::string name;                        //!< "mean", "last value held", ...
  std::optional<ErrorMetrics> validation;  //!< empty when the predictor could not be made
  std::string error;                       //!< why not, when validation is empty
  std::vector<double> predicted;           //!< on the held-out part (empty when it failed)
};

struct ReferenceOptions {
  std::size_t polynomial_degree = 3;
  std::size_t arx_outputs = 2;  //!< past outputs y[k-1]..y[k-na]
  std::size_t arx_inputs = 2;   //!< inputs v[k]..v[k-nb+1]
  //! false: the samples are not in time order, or the held-out samples do not follow the fit
  //! samples in time (a separate record): no ARX.
  bool time_series = true;
  //! Shift every prediction to the measured first held-out sample, as the models' predictions
  //! of separately zeroed records are (validation_rule.hpp, "first-sample").
  bool align_first_sample = false;
};

//! Coefficients of a fitted ARX model (see the file comment) in the data's own units.
struct ArxCoefficients {
  std::vector<double> a;  //!< on y[k-1], y[k-2], ...
  std::vector<double> b;  //!< on v[k], v[k-1], ...
  double offset = 0.0;    //!< c
};

//! The mean of `fit_output`, `samples` times. Throws hyst::Error when fit_output is empty.
std::vector<double> predict_mean(std::span<const double> fit_output, std::size_t samples);
//! The last value of `fit_output`, `samples` times. Throws hyst::Error when fit_output is empty.
std::vector<double> predict_hold(std::span<const double> fit_output, std::size_t samples);
//! The least-squares polynomial y(v) of `degree` fitted on the fit part, evaluated at
//! `held_input`. Throws hyst::Error for lengths that differ, fewer samples than coefficients or a
//! constant fit input.
std::vector<double> predict_polynomial(std::span<const double> fit_input,
                                       std::span<const double> fit_output,
                                       std::span<const double> held_input, std::size_t degree);
//! The ARX model fitted by least squares on the fit part. Throws hyst::Error for lengths that
//! differ, na = 0 or nb = 0, or fewer equations than coefficients.
ArxCoefficients fit_arx(std::span<const double> fit_input, std::span<const double> fit_output,
                        std::size_t na, std::size_t nb);
//! Free run of `arx` over `held_input`, which continues the fit part: its first past outputs and
//! inputs are the last ones of `fit_output` and `fit_input`. Throws hyst::Error when the fit part
//! is shorter than the model's orders.
std::vector<double> simulate_arx(const ArxCoefficients& arx, std::span<const double> fit_input,
                                 std::span<const double> fit_output,
                                 std::span<const double> held_input);

//! Every reference predictor fitted on split's fit part of the record and scored on its held-out
//! part. A predictor that cannot be made (too few samples, a free run that diverges) gets a score
//! without metrics and the reason. Throws hyst::Error when the lengths differ or the split has no
//! held-out part or lies outside the record.
std::vector<ReferenceScore> reference_predictions(std::span<const double> input,
                                                  std::span<const double> output,
                                                  const DataSplit& split,
                                                  const ReferenceOptions& options = {});

//! The same on a held-out record that is given apart from the fit samples
//! (cross_record_compare.hpp: the fit records joined, one separate record held out). ARX (with
//! options.time_series) takes its first past values from the end of the fit samples, so it is meant
//! only for a held-out record that continues them in time. Throws hyst::Error when lengths differ
//! or a part is empty.
std::vector<ReferenceScore> reference_predictions_on_record(std::span<const double> fit_input,
                                                            std::span<const double> fit_output,
                                                            std::span<const double> held_input,
                                                            std::span<const double> held_output,
                                                            const ReferenceOptions& options = {});

//! The reference with the lowest held-out NRMSE, or null when none has metrics.
const ReferenceScore* best_reference(const std::vector<ReferenceScore>& references);

}  // namespace hyst
