#pragma once
//! \file
//! The domain a model was fitted on, and whether another record stays in it. A fitted model
//! answers for inputs like the ones it saw; beyond them (a larger amplitude, an inverse asked for
//! an output the fit never measured) it extrapolates, and nothing in its answer says so. The fit
//! records the domain of its fit part (FitReport::domain, a model file's info.domain), and
//! `hyst simulate`, `hyst evaluate`, `hyst invert` and Python check every record against it.
//!
//! A sample leaves the domain when it lies beyond the fitted range by more than
//! kDomainMargin of the range's width (input samples for a model, targets for an inverse).
//! The longest hold (the most consecutive samples without a reversal of the input's direction)
//! and the largest input step per sample are recorded too; with the sample time they are a
//! duration and a rate, which check_timing() compares with another record's: rates beyond the
//! fitted ones, and holds longer than the largest time constant of a model with lags (creep),
//! whose behaviour beyond it no fit record has shown.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace hyst {

//! How far beyond a fitted range a sample may lie before it counts as outside the domain: 5 % of
//! the range's width (measurement noise and a slightly larger amplitude stay inside).
inline constexpr double kDomainMargin = 0.05;

struct FittedDomain {
  double input_min = 0.0;   //!< [input units]
  double input_max = 0.0;   //!< [input units]
  double output_min = 0.0;  //!< [output units]
  double output_max = 0.0;  //!< [output units]
  std::size_t samples = 0;  //!< of the fit part
  //! The largest |v[k] - v[k-1]| [input units per sample]; per second with sample_time.
  double largest_input_step = 0.0;
  //! The most consecutive samples without a reversal of the input's direction.
  std::size_t longest_hold_samples = 0;
  std::optional<double> sample_time;  //!< [s], when the fit knew it
  //! The largest time constant [s] of a model with lags (the creep models), else none.
  std::optional<double> largest_time_constant;

  //! The fit part's duration [s], samples x sample time, when the sample time is known.
  std::optional<double> duration() const;
  //! The largest |v[k] - v[k-1]| / Ts [input units / s], when the sample time is known.
  std::optional<double> largest_input_rate() const;
  //! The longest hold [s], when the sample time is known.
  std::optional<double> longest_hold() const;
};

//! The domain of a fit part. hyst::Error for records that differ in length or are empty.
FittedDomain fitted_domain(std::span<const double> input, std::span<const double> output,
                           std::optional<double> sample_time = {});

//! Samples of a record that leave one side of the domain, and the first of them (from 0).
struct DomainExcursion {
  //! "inputs above the fitted range [-1, 1] by more than 5 % of its width"
  std::string what;
  std::size_t samples = 0;
  std::size_t first = 0;
};

//! Every way a record leaves the domain; empty when it stays inside.
struct DomainCheck {
  std::vector<DomainExcursion> excursions;
  bool inside() const { return excursions.empty(); }
  //! Adds the excursions of `other` after these.
  void append(DomainCheck other);
  //! One sentence: "12 of 401 samples: inputs beyond the fitted input range [-1, 1] by more than
  //! 5 % of its width (first at sample 3); ...", for a warning line.
  std::string message(std::size_t record_samples) const;
};

//! The input samples of a record that a model fitted on `domain` extrapolates to.
DomainCheck check_inputs(const FittedDomain& domain, std::span<const double> input);

//! The rates and holds of a record sampled at `sample_time` [s] (none: at the model's own) that
//! the fit never saw: input rates above the fitted largest by more than kDomainMargin of it (per
//! second; per sample when the record has no sample time), and samples of a hold (time without
//! a reversal) that has lasted longer than both the longest fitted hold and the largest time
//! constant (by more than kDomainMargin). Nothing for a domain without a sample time (a
//! rate-independent model, for which neither matters).
//! `steps`, when not empty, are the record's own steps (one per sample, steps[k] = t[k] - t[k-1],
//! a non-uniform record) and take the place of `sample_time`.
DomainCheck check_timing(const FittedDomain& domain, std::span<const double> input,
                         std::optional<double> sample_time, std::span<const double> steps = {});

//! The inputs of a record (check_inputs()) and their rates and holds (check_timing()).
DomainCheck check_record_inputs(const FittedDomain& domain, std::span<const double> input,
                                std::optional<double> sample_time,
                                std::span<const double> steps = {});

//! The targets of an inverse that lie beyond every output the fit measured.
DomainCheck check_targets(const FittedDomain& domain, std::span<const double> targets);

//! The checks of several models on one record of `record_samples` samples as one text, the
//! models whose records leave their domains alike named together: "pi, kp: 12 of 401 samples:
//! inputs above ...; pi_creep: ..."; empty when every check is inside.
std::string models_domain_message(
    std::span<const std::pair<std::string, DomainCheck>> checks_by_model,
    std::size_t record_samples);

//! The domain of several fit records together, from the domain of each: the union of their
//! ranges, the largest rate and the longest hold of any of them, and their samples summed. When
//! every part has a sample time, the result is expressed at the smallest of them (steps, holds
//! and samples converted, so that its rate, longest hold and duration in seconds are those of the
//! parts); when any lacks one, it has none and counts per sample. hyst::Error without parts.
FittedDomain merged_domain(std::span<const FittedDomain> parts);

}  // namespace hyst
