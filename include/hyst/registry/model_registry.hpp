#pragma once
//! \file
//! The registry of models: for each model its name, a one-line description, its parameter
//! schema, construction from model-file JSON, and what else it can do: its fitter, its C export,
//! its use as an actuator's force, where it has them. Every model of the library is registered
//! here, so that the command line, model files, Python, the C export and the actuator all know it
//! by the same name; a model is wired in by its entry alone (docs/architecture.md).

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/core/progress.hpp"
#include "hyst/data/preprocessing.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/validation_rule.hpp"

namespace hyst {

struct CCode;           // hyst/export/c_code.hpp
struct CExportOptions;  // hyst/export/c_code.hpp
struct ActuatorForce;   // hyst/registry/actuator_force.hpp

//! One entry of a model's parameter schema.
struct ParameterInfo {
  std::string name;         //!< field name in model files, e.g. "thresholds"
  std::string type;         //!< "number", "array of numbers", ...
  std::string unit;         //!< e.g. "input units"
  std::string description;  //!< meaning and admissible range
  //! The value taken when the field is left out; empty when it must be given or when the
  //! description says what leaving it out means.
  std::string default_value;
};

//! What a fitter is given: one input/output record, how to validate, and model-specific options
//! as JSON (the same names as the fields of the model's C++ options struct).
//!
//! Validation is either the last `validate_fraction` of the record (contiguous, never shuffled;
//! predicted by continuing the simulation from the state at the end of the fit part) or a
//! separate held-out record (validation_input/validation_output), predicted by fit_model() under
//! `validation` (the fitter never sees it), never both.
struct FitRequest {
  std::span<const double> input;
  std::span<const double> output;
  double validate_fraction = 0.0;             //!< [0, 1)
  std::span<const double> validation_input;   //!< empty: no held-out record
  std::span<const double> validation_output;  //!< same length as validation_input
  nlohmann::json options = nlohmann::json::object();
  //! Preparation of the record (drift, cycles, resampling) applied by fit_model(). A separate
  //! validation record gets the drift removal only (data::prepare_validation()); a held-out
  //! fraction is the end of the prepared record.
  data::Preprocessing preprocessing;
  //! How a separate validation record is predicted (validation_rule.hpp).
  ValidationRule validation;
  //! Told as a fitter with several starts runs them (task "starts"); the others never call it.
  ProgressCallback progress{};
};

struct FitOutcome {
  std::unique_ptr<DynamicModel> model;  //!< in the initial state used for fitting
  FitReport report;
};

//! A closed interval of model inputs.
struct InputRange {
  double min = -1.0;
  double max = 1.0;
};

struct ModelEntry {
  std::string name;
  std::string description;  //!< one line
  std::vector<ParameterInfo> parameters;
  std::vector<ParameterInfo> fit_options;  //!< empty when the model has no fitter
  //! Builds the model from the "params" and (optional, may be null) "state" objects of a model
  //! file; hyst::Error messages name the field as "params.thresholds[3]: ...".
  std::function<std::unique_ptr<DynamicModel>(const nlohmann::json& params,
                                              const nlohmann::json* state)>
      create;
  //! Empty when the model has no fitter.
  std::function<FitOutcome(const FitRequest&)> fit;
  //! A fitter of several records together, one model for all (one actuator at several rates or
  //! amplitudes): `sample_times` has one per record, or is empty for the option sample_time on
  //! every record; a model without a sample time refuses them. Records as measured (no
  //! preprocessing, no held-out part: fit_model() is the one-record route for those). Empty when
  //! the model has no such fitter.
  std::function<FitOutcome(std::span<const FitRecord> records, std::span<const double> sample_times,
                           const nlohmann::json& options)>
      fit_records;
  //! The C code of a model made by `create` or `fit` (and of its inverse), in its current state,
  //! for options whose prefix is checked (generate_c() in export_c.hpp calls it); empty when the
  //! model has no C export.
  std::function<CCode(const DynamicModel&, const CExportOptions&)> c_code;
  //! How a model made by `create` becomes an actuator's hysteretic force; null when it cannot be
  //! one (hysteretic_force.hpp).
  std::shared_ptr<const ActuatorForce> actuator_force;
  //! A small valid parameter set (for `hyst models --example`, tests and documentation).
  nlohmann::json example_params;
  //! The units the model's parameters assume for its input and its output ("A/m" and "T" for
  //! Jiles-Atherton: H and B); empty for a model whose parameters are in input and output units
  //! (any). `hyst fit` refuses data whose file states other units (see 'hyst fit --help',
  //! --units-intended).
  std::string input_unit;
  std::string output_unit;
  //! Inputs for which the example model is meant: its hysteresis shows within them and nothing
  //! overflows. The conformance tests drive every model with inputs from this range.
  InputRange example_input_range;
  //! How closely the example model's inverse (where it has one) reproduces a reachable output,
  //! relative to the output range of a major loop over example_input_range.
  double example_inverse_tolerance = 1e-6;

  bool can_fit() const { return static_cast<bool>(fit); }
  bool can_fit_records() const { return static_cast<bool>(fit_records); }
  bool can_export_c() const { return static_cast<bool>(c_code); }
};

//! Throws hyst::Error when a fit of several records is given `count` of them, more than
//! io::limits::kMaxFitRecords; ModelEntry::fit_records checks it, and the command line and Python
//! before they read or copy the records.
void require_fit_record_count(std::size_t count);

//! Fits `entry`'s model: prepares request.input/output as request.preprocessing asks
//! (data::preprocess()) and a separate validation record by data::prepare_validation(), calls
//! entry.fit on the prepared records and lists the steps applied in the report's `preprocessing`
//! ("fit record: ...", "validation record: ...", or "fit and held-out validation part: ..." when
//! a fraction is held out; unprefixed without validation). Throws hyst::Error when the model has
//! no fitter.
FitOutcome fit_model(const ModelEntry& entry, const FitRequest& request);

//! True when the entry's fitter takes the option sample_time (its model depends on time).
bool fits_sample_time(const ModelEntry& entry);
//! `options` (a JSON object) with "sample_time" = `seconds` when the entry's fitter takes that
//! option and `options` does not already set it; unchanged otherwise or without `seconds`.
nlohmann::json with_sample_time(const ModelEntry& entry, nlohmann::json options,
                                std::optional<double> seconds);

class ModelRegistry {
 public:
  //! The registry with every built-in model.
  static const ModelRegistry& builtin();

  //! Throws hyst::Error "unknown model 'x' (known: pi, ...)".
  const ModelEntry& find(std::string_view name) const;
  const ModelEntry* find_if_known(std::string_view name) const;
  const std::vector<ModelEntry>& entries() const { return entries_; }
  //! Comma-separated names.
  std::string names() const;

  //! Adds an entry; throws hyst::Error if the name is taken.
  void add(ModelEntry entry);

 private:
  std::vector<ModelEntry> entries_;
};

}  // namespace hyst
