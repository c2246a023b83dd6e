#pragma once
//! \file
//! The type-erased face of a model: what the command line, model files and Python use to choose
//! a model at run time. It holds one concrete, non-virtual model together with its state; the
//! virtual call happens once per batch (simulate), never per sample.

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hyst/core/inverse_status.hpp"

namespace hyst {

//! Limits of the input an inverse may return (the actuator's admissible input range).
struct InverseLimits {
  double input_min = -std::numeric_limits<double>::infinity();
  double input_max = std::numeric_limits<double>::infinity();
};

//! An inverse model with its state, started consistently with the model it was made from.
class DynamicInverse {
 public:
  virtual ~DynamicInverse() = default;
  //! Inputs that make the model produce `targets`; advances the state. Saturation is reported,
  //! not thrown; hyst::Error for mismatched lengths or non-finite targets.
  virtual InverseReport invert(std::span<const double> targets, std::span<double> inputs) = 0;
  //! The inverse's own state as JSON (e.g. for `hyst info`).
  virtual nlohmann::json state() const = 0;
  //! An independent copy, state included.
  virtual std::unique_ptr<DynamicInverse> clone() const = 0;
};

//! How a model's output depends on time. Rate-independent models ignore time by design: their
//! output depends on the sequence of inputs alone, so a record's sample spacing does not change
//! it. The others carry their sample time in seconds in the model file.
enum class TimeDependence {
  none,        //!< rate independent: any sample spacing gives the same output
  continuous,  //!< continuous-time dynamics (lags, ODEs) discretised at the model's sample time,
               //!< re-discretised for any other one (at_sample_time())
  discrete,    //!< identified in samples (NARX): valid at its own sample time only
};

class DynamicModel {
 public:
  virtual ~DynamicModel() = default;

  //! Registry name, e.g. "pi".
  virtual std::string_view name() const = 0;
  virtual std::unique_ptr<DynamicModel> clone() const = 0;

  //! Parameters and state in the model-file form (see model_file.hpp).
  virtual nlohmann::json params() const = 0;
  virtual nlohmann::json state() const = 0;
  //! Replaces the state; throws hyst::Error naming the field ("state.play[2]: ...").
  virtual void set_state(const nlohmann::json& state) = 0;
  //! Back to the model's default initial state.
  virtual void reset() = 0;

  //! Runs the model over `input` from the current state (advanced); hyst::Error for mismatched
  //! lengths, non-finite input samples or outputs that overflow (not finite).
  virtual void simulate(std::span<const double> input, std::span<double> output) = 0;
  //! The same run on a copy of the state alone, the model unchanged: no copy of the parameters
  //! (a Preisach model's relay weights, a NARX network), so a caller that wants every run to
  //! start afresh pays only for the state.
  virtual void simulate_from_state(std::span<const double> input,
                                   std::span<double> output) const = 0;

  //! How the output depends on time; TimeDependence::none unless the model has a sample time.
  virtual TimeDependence time_dependence() const = 0;
  //! The sample time [s] the model is discretised at; none for a rate-independent model and for
  //! a discrete model fitted without a time axis.
  virtual std::optional<double> sample_time() const = 0;
  //! The same model, in the same state, at the sample time `seconds` > 0: a rate-independent
  //! model as it is; a continuous-time one re-discretised (exactly where an exact form exists,
  //! e.g. the lags' decays exp(-Ts / tau), else by its own integrator at the new step); a
  //! discrete one only at its own sample time (within 0.1 %), else hyst::Error naming both.
  virtual std::unique_ptr<DynamicModel> at_sample_time(double seconds) const = 0;

  //! Number of free parameters (for comparing models).
  virtual std::size_t parameter_count() const = 0;
  //! A few lines describing the model and its parameters, for people.
  virtual std::string describe() const = 0;

  //! True if inverse() is available for this model and parameter set.
  virtual bool has_inverse() const = 0;
  //! The inverse, started in the state consistent with this model's current state; throws
  //! hyst::Error when the model has none or its parameters admit none.
  virtual std::unique_ptr<DynamicInverse> inverse(const InverseLimits& limits) const = 0;
};

}  // namespace hyst
