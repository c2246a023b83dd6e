#pragma once
// DynamicModel and DynamicInverse for any concrete model, given a codec that knows the model's
// JSON form:
//
//   struct Codec : CodecOf<Model, "name"> {  // Model, P (= Model::Params) and name
//     // The table of Model::Params (field_table.hpp), built once (parameter_table<Codec>()):
//     // the model file's "params" (read and written) and the entry's schema are derived from it.
//     static FieldTable<P> parameters();
//     static nlohmann::json state_to_json(const Model&, const typename Model::State&);
//     static typename Model::State state_from_json(const Model&, detail::JsonFields&);
//     static std::size_t parameter_count(const Model&);
//     static std::string describe(const Model&);
//     static bool has_inverse(const Model&);
//     static std::unique_ptr<DynamicInverse> make_inverse(const Model&,
//                                                         const typename Model::State&,
//                                                         const InverseLimits&);
//     // Optional, for models whose recursion can diverge on finite input: the largest |output|
//     // a run that has not run away can reach, and how that bound is stated in messages.
//     static double runaway_limit(const Model&);
//     static std::string runaway_explanation(const Model&);
//     // Optional, for models whose output depends on time (default TimeDependence::none):
//     static constexpr TimeDependence time_dependence = TimeDependence::continuous;
//     static std::optional<double> sample_time(const Model&);  // [s]
//     static Model at_sample_time(const Model&, double seconds);  // continuous models only
//   };

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "field_table.hpp"
#include "hyst/core/invert.hpp"
#include "hyst/core/simulate.hpp"
#include "hyst/identify/fit_record.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst::detail {

// Throws hyst::Error unless `seconds` is a sample time (finite, > 0); `model` names the model.
void require_sample_time(std::string_view model, double seconds);
// The domain of the records a model was fitted on together (merged_domain() of each record's),
// each record at its sample time (`sample_times`, else the model's own, else none); a record
// with oversampling has its input at that many steps per output sample.
FittedDomain records_domain(std::span<const FitRecord> records,
                            std::span<const double> sample_times, const DynamicModel& model);
// Throws hyst::Error naming both sample times unless `seconds` is within 0.1 % of `own`, the
// sample time of the discrete model `model` (none: fitted without a time axis, any is taken).
void require_own_sample_time(std::string_view model, std::optional<double> own, double seconds);

// The time hooks of a codec whose model is continuous in time, discretised at the sample time of
// its Params (or of its Params' pi_creep): re-discretised by the model's at_sample_time() where it
// has one (the creep models: exact decays), else rebuilt from its Params at the new step.
template <class M>
struct ContinuousTimeCodec {
  static constexpr TimeDependence time_dependence = TimeDependence::continuous;
  static std::optional<double> sample_time(const M& model) {
    if constexpr (requires { model.params().pi_creep.sample_time; }) {
      return model.params().pi_creep.sample_time;
    } else {
      return model.params().sample_time;
    }
  }
  static M at_sample_time(const M& model, double seconds) {
    if constexpr (requires { model.at_sample_time(seconds); }) {
      return model.at_sample_time(seconds);
    } else {
      auto params = model.params();
      params.sample_time = seconds;
      return M(std::move(params));
    }
  }
};

// A codec's name as a template argument: CodecOf<BoucWen, "bouc_wen">.
template <std::size_t N>
struct CodecName {
  constexpr CodecName(const char (&text)[N]) { std::copy_n(text, N, chars); }
  constexpr std::string_view view() const { return {chars, N - 1}; }
  char chars[N]{};
};

// What a codec starts from: its model, P (the parameter struct whose members the parameter
// table's rows point to) and the name of its entry and model files.
template <class M, CodecName Name>
struct CodecOf {
  using Model = M;
  using P = typename M::Params;
  static constexpr std::string_view name = Name.view();
};

// The codec's parameter table, built on first use and kept.
template <class Codec>
const FieldTable<typename Codec::Model::Params>& parameter_table() {
  static const auto table = Codec::parameters();
  return table;
}

template <class Codec>
class ModelAdapter final : public DynamicModel {
 public:
  using Model = typename Codec::Model;
  using State = typename Model::State;

  ModelAdapter(Model model, State state) : model_(std::move(model)), state_(std::move(state)) {}

  std::string_view name() const override { return Codec::name; }
  std::unique_ptr<DynamicModel> clone() const override {
    return std::make_unique<ModelAdapter>(*this);
  }
  nlohmann::json params() const override { return parameter_table<Codec>().write(model_.params()); }
  nlohmann::json state() const override { return Codec::state_to_json(model_, state_); }
  void set_state(const nlohmann::json& state) override {
    JsonFields fields(state, "state");
    auto new_state = Codec::state_from_json(model_, fields);
    fields.finish();
    state_ = std::move(new_state);
  }
  void reset() override { state_ = model_.initial_state(); }
  void simulate(std::span<const double> input, std::span<double> output) override {
    hyst::simulate(model_, state_, input, output);
    check_outputs(input, output);
  }
  void simulate_from_state(std::span<const double> input, std::span<double> output) const override {
    State state = state_;
    hyst::simulate(model_, state, input, output);
    check_outputs(input, output);
  }
  TimeDependence time_dependence() const override {
    if constexpr (requires { Codec::time_dependence; }) {
      return Codec::time_dependence;
    } else {
      return TimeDependence::none;
    }
  }
  std::optional<double> sample_time() const override {
    if constexpr (requires { Codec::sample_time(model_); }) {
      return Codec::sample_time(model_);
    } else {
      return std::nullopt;
    }
  }
  std::unique_ptr<DynamicModel> at_sample_time(double seconds) const override {
    require_sample_time(Codec::name, seconds);
    if constexpr (requires { Codec::at_sample_time(model_, seconds); }) {
      static_assert(Codec::time_dependence == TimeDependence::continuous);
      return std::make_unique<ModelAdapter>(Codec::at_sample_time(model_, seconds), state_);
    } else {
      if (time_dependence() == TimeDependence::discrete)
        require_own_sample_time(Codec::name, sample_time(), seconds);
      return clone();
    }
  }
  std::size_t parameter_count() const override { return Codec::parameter_count(model_); }
  std::string describe() const override { return Codec::describe(model_); }
  bool has_inverse() const override { return Codec::has_inverse(model_); }
  std::unique_ptr<DynamicInverse> inverse(const InverseLimits& limits) const override {
    return Codec::make_inverse(model_, state_, limits);
  }

  const Model& model() const { return model_; }
  const State& model_state() const { return state_; }

 private:
  void check_outputs(std::span<const double> input, std::span<const double> output) const {
    // A recursion that runs away reaches infinity later: its first sample beyond the bound is
    // the one to name.
    if constexpr (requires { Codec::runaway_limit(model_); }) throw_if_runaway(input, output);
    // Finite inputs can still overflow (e.g. 1e308 times a weight above 1): report, never pass
    // on infinities as results. One pass over the batch, outside the sample loop.
    for (std::size_t k = 0; k < output.size(); ++k) {
      if (!std::isfinite(output[k])) {
        throw Error(fmt::format("input[{}] = {} gives the output {}: it overflows the model", k,
                                input[k], output[k]),
                    "input");
      }
    }
  }

  // A recursion that diverges on finite input (an unstable feedback of the model's own outputs)
  // is an error at the first sample beyond the model's stated bound, not a result.
  void throw_if_runaway(std::span<const double> input, std::span<const double> output) const {
    const double limit = Codec::runaway_limit(model_);
    for (std::size_t k = 0; k < output.size(); ++k) {
      if (std::abs(output[k]) > limit) {
        throw Error(fmt::format("the simulation ran away at sample {} (input {}): the output {} "
                                "is beyond +-{:g} ({})",
                                k, input[k], output[k], limit, Codec::runaway_explanation(model_)),
                    "input");
      }
    }
  }

  Model model_;
  State state_;
};

// `use(model, state)` on the concrete model and state of `model`, which one of Codecs' adapters
// holds (the GPI has one codec per envelope); hyst::Error when another entry made it. This is how
// an entry's capabilities reach the concrete model: no JSON in between.
template <class Codec, class... Others, class Use>
decltype(auto) with_concrete(const DynamicModel& model, Use&& use) {
  if (const auto* adapter = dynamic_cast<const ModelAdapter<Codec>*>(&model)) {
    return use(adapter->model(), adapter->model_state());
  }
  if constexpr (sizeof...(Others) > 0) {
    return with_concrete<Others...>(model, std::forward<Use>(use));
  } else {
    throw Error(fmt::format("the model '{}' was not made by the registry's '{}' entry",
                            model.name(), Codec::name));
  }
}

// An inverse with its running state; the state is written as {"play": [...]} when it is a
// play-operator state, and by the inverse's own codec function otherwise.
template <class Inverse, class StateToJson>
class InverseAdapter final : public DynamicInverse {
 public:
  InverseAdapter(Inverse inverse, typename Inverse::State state, StateToJson state_to_json)
      : inverse_(std::move(inverse)),
        state_(std::move(state)),
        state_to_json_(std::move(state_to_json)) {}

  InverseReport invert(std::span<const double> targets, std::span<double> inputs) override {
    return hyst::invert(inverse_, state_, targets, inputs);
  }
  nlohmann::json state() const override { return state_to_json_(state_); }
  std::unique_ptr<DynamicInverse> clone() const override {
    return std::make_unique<InverseAdapter>(*this);
  }

 private:
  Inverse inverse_;
  typename Inverse::State state_;
  StateToJson state_to_json_;
};

// The model of validated `params` (a validation error gets "params." and its field in front),
// wrapped with its initial state or, when the model file has one, the file's state.
template <class Codec>
std::unique_ptr<DynamicModel> make_dynamic_model(typename Codec::Model::Params params,
                                                 const nlohmann::json* state_json) {
  using Model = typename Codec::Model;
  std::optional<Model> model;
  try {
    model.emplace(std::move(params));
  } catch (const Error& error) {
    rethrow_at(error, "params");
  }
  auto adapter = std::make_unique<ModelAdapter<Codec>>(*model, model->initial_state());
  if (state_json) adapter->set_state(*state_json);
  return adapter;
}

// The parameters of a model file's "params" object (or of another object at `path`) through the
// codec's parameter table: every field read, none left over.
template <class Codec>
typename Codec::Model::Params params_of_json(const nlohmann::json& params_json, std::string path) {
  return parameter_table<Codec>().read(params_json, std::move(path));
}

// The model of a model file's "params" (and "state", may be null): an entry's `create`.
template <class Codec>
std::unique_ptr<DynamicModel> create_from_json(const nlohmann::json& params_json,
                                               const nlohmann::json* state_json) {
  return make_dynamic_model<Codec>(params_of_json<Codec>(params_json, "params"), state_json);
}

// An entry's `fit` for a fitter of one record: the request's options read by `table`, its
// held-out fraction passed on, and the fitted model wrapped in the state the fit assumed (the
// model's initial state when the fit result names none).
template <class Codec, class Options, class Fit>
FitOutcome fit_with_table(const FitRequest& request, const FieldTable<Options>& table, Fit fit) {
  auto options = table.read(request.options, "fit options");
  options.validate_fraction = request.validate_fraction;
  if constexpr (requires { options.progress; }) options.progress = request.progress;
  auto result = fit(request.input, request.output, options);
  if constexpr (requires { result.initial_state; }) {
    return {std::make_unique<ModelAdapter<Codec>>(std::move(result.model),
                                                  std::move(result.initial_state)),
            std::move(result.report)};
  } else {
    auto initial = result.model.initial_state();
    return {std::make_unique<ModelAdapter<Codec>>(std::move(result.model), std::move(initial)),
            std::move(result.report)};
  }
}

// An entry of a codec with a parameter table: its name, `description` (one line), its parameter
// schema and `create`. The entry function then adds the example and the capabilities.
template <class Codec>
ModelEntry entry_of(std::string description) {
  ModelEntry entry;
  entry.name = std::string(Codec::name);
  entry.description = std::move(description);
  entry.parameters = parameter_table<Codec>().schema();
  entry.create = &create_from_json<Codec>;
  return entry;
}

// Gives `entry` a fitter of one record, `fit(input, output, options)`, whose options `table`
// reads and documents.
template <class Codec, class Options, class Fit>
void set_fitter(ModelEntry& entry, FieldTable<Options> table, Fit fit) {
  entry.fit_options = table.schema();
  entry.fit = [table = std::make_shared<const FieldTable<Options>>(std::move(table)),
               fit](const FitRequest& request) {
    return fit_with_table<Codec>(request, *table, fit);
  };
}

// Gives `entry` a fitter of several records, `fit(records, options)`, whose options `table` reads;
// the sample times go to the option sample_times where the options have one.
template <class Codec, class Options, class Fit>
void set_records_fitter(ModelEntry& entry, FieldTable<Options> table, Fit fit) {
  entry.fit_records = [table = std::make_shared<const FieldTable<Options>>(std::move(table)), fit](
                          std::span<const FitRecord> records, std::span<const double> sample_times,
                          const nlohmann::json& json) -> FitOutcome {
    require_fit_record_count(records.size());
    auto options = table->read(json, "fit options");
    if (!sample_times.empty()) {
      if constexpr (requires { options.sample_times; }) {
        options.sample_times.assign(sample_times.begin(), sample_times.end());
      } else {
        throw Error(fmt::format("model '{}' has no sample time: fit its records without sample "
                                "times",
                                Codec::name),
                    "sample_times");
      }
    }
    auto result = fit(records, options);
    FitOutcome outcome{std::make_unique<ModelAdapter<Codec>>(std::move(result.model),
                                                             std::move(result.initial_state)),
                       std::move(result.report)};
    outcome.report.domain = records_domain(records, sample_times, *outcome.model);
    return outcome;
  };
}

// A state built by `make` (the model's validating make_state), with the state object's path in
// front of a validation error: "state: Ikuta state fraction = 2 must be in [0, 1]".
template <class Make>
auto state_at(const JsonFields& fields, Make make) {
  try {
    return make();
  } catch (const Error& error) {
    throw Error(fields.path() + ": " + error.what());
  }
}

// {"play": [...]}: the state of every play-operator model (PI, GPI), validated by the model.
template <class Model>
typename Model::State play_state_from_json(const Model& model, JsonFields& fields) {
  auto play = fields.numbers("play");
  try {
    return model.make_state(std::move(play));
  } catch (const Error& error) {
    throw Error(fields.path_of("play") + ": " + error.what());
  }
}

}  // namespace hyst::detail
