#include "hyst/registry/hysteretic_lfr_file.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include "../detail/json_fields.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/json_text.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/state_space_file.hpp"

namespace hyst {
namespace {

constexpr std::string_view kHystereticLfrModelName = "hysteretic_lfr";

// The feedback models as alternatives of AnyHysteresis, all of one kind, with their documents.
struct FeedbackModels {
  std::vector<AnyHysteresis> models;
  nlohmann::json documents = nlohmann::json::array();
  std::string name;
  std::size_t parameters = 0;
};

FeedbackModels feedback_models(const std::vector<const DynamicModel*>& feedback) {
  if (feedback.empty())
    throw Error("hysteretic LFR: no feedback model; a linear system is a state_space model",
                "feedback");
  FeedbackModels result;
  for (std::size_t i = 0; i < feedback.size(); ++i) {
    const DynamicModel& model = *feedback[i];
    const std::string name(model.name());
    const auto& entry = ModelRegistry::builtin().find(name);
    if (!entry.actuator_force)
      throw Error(fmt::format("hysteretic LFR: feedback[{}] is a '{}' model, which cannot be a "
                              "hysteresis channel (those that can: the actuator force models, see "
                              "`hyst models`)",
                              i, name),
                  fmt::format("feedback[{}].model", i));
    if (i > 0 && name != result.name)
      throw Error(fmt::format("hysteretic LFR: feedback[{}] is a '{}' model, feedback[0] a '{}' "
                              "model; every channel must be of one kind",
                              i, name, result.name),
                  fmt::format("feedback[{}].model", i));
    if (model.parameter_count() > io::limits::kMaxLfrChannelParameters)
      throw Error(fmt::format("hysteretic LFR: feedback[{}] has {} parameters, more than the "
                              "limit of {} for one hysteresis channel",
                              i, model.parameter_count(), io::limits::kMaxLfrChannelParameters),
                  fmt::format("feedback[{}].params", i));
    result.name = name;
    result.models.push_back(entry.actuator_force->hysteresis(model));
    if (result.models.back().index() != result.models.front().index())
      throw Error(fmt::format("hysteretic LFR: feedback[{}] differs in kind from feedback[0] "
                              "(e.g. another GPI envelope); every channel must be of one kind",
                              i),
                  fmt::format("feedback[{}].params", i));
    result.documents.push_back({{"model", name}, {"params", model.params()}});
    result.parameters += model.parameter_count();
  }
  return result;
}

// A by its order: a change of state coordinates changes A's entries but not the model, which
// its n eigenvalues (in the real modal form of the fits: one radius and angle per complex pair,
// one value per real pole) determine together with B and C.
std::size_t linear_parameters(const StateSpace& linear, std::size_t feedback) {
  const auto& p = linear.params();
  const auto q = std::size_t(feedback);
  return std::size_t(p.a.rows() + p.b.size() + p.c.size() + p.d.size()) - q * q;
}

template <class H>
std::vector<H> blocks_of(const std::vector<AnyHysteresis>& models) {
  std::vector<H> blocks;
  blocks.reserve(models.size());
  for (const auto& model : models)
    blocks.push_back(std::get<H>(model));
  return blocks;
}

}  // namespace

AnyHystereticLfr::AnyHystereticLfr(AnyHystereticLfrModel model, nlohmann::json feedback,
                                   std::string name, std::size_t feedback_parameters)
    : model_(std::move(model)), feedback_(std::move(feedback)), feedback_name_(std::move(name)) {
  feedback_parameter_count_ = feedback_parameters;
  parameter_count_ = linear_parameters(linear(), feedback_.size()) + feedback_parameters;
}

AnyHystereticLfr::AnyHystereticLfr(StateSpace linear, std::size_t inputs,
                                   const std::vector<const DynamicModel*>& feedback)
    : AnyHystereticLfr([&] {
        auto parts = feedback_models(feedback);
        auto model = std::visit(
            [&](const auto& first) -> AnyHystereticLfrModel {
              using H = std::decay_t<decltype(first)>;
              return HystereticLfr<H>(std::move(linear), inputs, blocks_of<H>(parts.models));
            },
            parts.models.front());
        return AnyHystereticLfr(std::move(model), std::move(parts.documents), std::move(parts.name),
                                parts.parameters);
      }()) {}

AnyHystereticLfr AnyHystereticLfr::hammerstein(const StateSpace& linear,
                                               const std::vector<const DynamicModel*>& blocks) {
  auto parts = feedback_models(blocks);
  auto model = std::visit(
      [&](const auto& first) -> AnyHystereticLfrModel {
        using H = std::decay_t<decltype(first)>;
        return HystereticLfr<H>::hammerstein(linear, blocks_of<H>(parts.models));
      },
      parts.models.front());
  return AnyHystereticLfr(std::move(model), std::move(parts.documents), std::move(parts.name),
                          parts.parameters);
}

const StateSpace& AnyHystereticLfr::linear() const {
  return std::visit([](const auto& m) -> const StateSpace& { return m.linear(); }, model_);
}
std::size_t AnyHystereticLfr::inputs() const {
  return std::visit([](const auto& m) { return m.inputs(); }, model_);
}
std::size_t AnyHystereticLfr::outputs() const {
  return std::visit([](const auto& m) { return m.outputs(); }, model_);
}
std::size_t AnyHystereticLfr::order() const {
  return linear().order();
}
double AnyHystereticLfr::sample_time() const {
  return linear().sample_time();
}

Eigen::MatrixXd AnyHystereticLfr::simulate(const Eigen::MatrixXd& input) const {
  return std::visit([&](const auto& m) { return m.simulate(input); }, model_);
}

Eigen::MatrixXd AnyHystereticLfr::simulate_from_periodic_state(
    const Eigen::MatrixXd& input, const Eigen::MatrixXd& one_period) const {
  return std::visit(
      [&](const auto& m) {
        auto state = m.periodic_state(one_period);
        return m.simulate(input, state);
      },
      model_);
}

Eigen::MatrixXd AnyHystereticLfr::simulate_from_state(const Eigen::MatrixXd& input,
                                                      const Eigen::VectorXd& x0) const {
  return std::visit(
      [&](const auto& m) {
        auto state = m.make_state(x0);
        return m.simulate(input, state);
      },
      model_);
}

InitialStateEstimate AnyHystereticLfr::estimate_initial_state(const Eigen::MatrixXd& input,
                                                              const Eigen::MatrixXd& output,
                                                              std::size_t samples) const {
  // The linear block's estimate with the hysteresis path open (its inputs w at 0), then the
  // whole model's residual by Gauss-Newton.
  const auto n = Eigen::Index(samples);
  const auto& lin = linear();
  const auto m = Eigen::Index(inputs());
  const auto p = Eigen::Index(outputs());
  const StateSpace to_y(StateSpace::Params{lin.params().a, lin.params().b.leftCols(m),
                                           lin.params().c.topRows(p),
                                           lin.params().d.topLeftCorner(p, m), lin.sample_time()});
  const auto start = hyst::estimate_initial_state(to_y, input, output, samples);
  return refine_initial_state(
      [&](const Eigen::VectorXd& x0) {
        return Eigen::MatrixXd(simulate_from_state(input.topRows(n), x0));
      },
      output.topRows(n), start.state);
}

AnyHystereticLfr any_hysteretic_lfr(const HystereticLfr<PrandtlIshlinskii>& model) {
  const auto& entry = ModelRegistry::builtin().find("pi");
  std::vector<std::unique_ptr<DynamicModel>> owned;
  std::vector<const DynamicModel*> feedback;
  for (const auto& block : model.feedback()) {
    const auto& p = block.params();
    owned.push_back(entry.create(
        {{"thresholds", p.thresholds}, {"weights", p.weights}, {"offset", p.offset}}, nullptr));
    feedback.push_back(owned.back().get());
  }
  return AnyHystereticLfr(model.linear(), model.inputs(), feedback);
}

SimulationScore score_hysteretic_lfr(const AnyHystereticLfr& model, const PeriodicSignals& input,
                                     const PeriodicSignals& output, const ScoreOptions& options) {
  if (options.init_samples > 0) {
    const std::size_t transient = scored_transient(options);
    std::size_t realisation = 0;
    return score_simulation(
        input, output,
        [&](const Eigen::MatrixXd& u, const Eigen::MatrixXd&) {
          const auto measured = realisation_record(output, realisation++);
          return model.simulate_from_state(
              u, model.estimate_initial_state(u, measured, options.init_samples).state);
        },
        transient);
  }
  if (options.periodic)
    return score_simulation(
        input, output,
        [&](const Eigen::MatrixXd& u, const Eigen::MatrixXd& one_period) {
          return model.simulate_from_periodic_state(u, one_period);
        },
        options.transient_samples);
  return score_simulation(
      input, output,
      [&](const Eigen::MatrixXd& u, const Eigen::MatrixXd&) { return model.simulate(u); },
      options.transient_samples);
}

HystereticLfrFile hysteretic_lfr_from_json(const nlohmann::json& document,
                                           std::string_view source) {
  try {
    if (!document.is_object())
      throw Error(fmt::format("expected a JSON object, got {}", detail::describe_json(document)));
    detail::JsonFields fields(document, "");
    const auto name = fields.string("model");
    if (name != kHystereticLfrModelName)
      throw Error(fmt::format("model: \"{}\" is not a hysteretic LFR model file (expected \"{}\")",
                              name, kHystereticLfrModelName));
    require_model_file_version(fields.raw("version"));
    const auto* params = fields.raw("params");
    if (!params) throw Error("params: missing field");
    const auto* info = fields.raw("info");
    if (info && !info->is_object())
      throw Error(fmt::format("info: expected an object, got {}", detail::describe_json(*info)));
    fields.finish();

    detail::JsonFields p(*params, "params");
    const auto inputs = p.count("inputs");
    const auto* linear_json = p.raw("linear");
    if (!linear_json) throw Error("params.linear: missing field");
    const auto* feedback_json = p.raw("feedback");
    if (!feedback_json || !feedback_json->is_array())
      throw Error("params.feedback: expected an array of model objects");
    p.finish();
    StateSpace linear = state_space_from_params(*linear_json, "params.linear");
    if (feedback_json->size() > StateSpace::max_channels)
      throw Error(fmt::format("params.feedback: {} hysteresis channels, more than the limit of {}",
                              feedback_json->size(), StateSpace::max_channels));
    std::vector<std::unique_ptr<DynamicModel>> owned;
    for (std::size_t i = 0; i < feedback_json->size(); ++i) {
      const auto path = fmt::format("params.feedback[{}]", i);
      detail::JsonFields block(feedback_json->at(i), path);
      const auto block_name = block.string("model");
      const auto* block_params = block.raw("params");
      if (!block_params) throw Error(path + ".params: missing field");
      block.finish();
      const auto* entry = ModelRegistry::builtin().find_if_known(block_name);
      if (!entry)
        throw Error(fmt::format("{}.model: unknown model '{}' (known: {})", path, block_name,
                                ModelRegistry::builtin().names()));
      try {
        owned.push_back(entry->create(*block_params, nullptr));
      } catch (const Error& error) {
        throw Error(fmt::format("{}.{}", path, error.what()), error.field());
      }
    }
    std::vector<const DynamicModel*> feedback;
    for (const auto& model : owned)
      feedback.push_back(model.get());
    try {
      return {AnyHystereticLfr(std::move(linear), inputs, feedback),
              info ? *info : nlohmann::json::object()};
    } catch (const Error& error) {
      detail::rethrow_at(error, "params");
    }
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", source, error.what()));
  }
}

nlohmann::json hysteretic_lfr_to_json(const AnyHystereticLfr& model, const nlohmann::json& info) {
  nlohmann::json document = {{"model", std::string(kHystereticLfrModelName)},
                             {"version", kModelFileVersion},
                             {"params",
                              {{"inputs", model.inputs()},
                               {"linear", state_space_params_to_json(model.linear())},
                               {"feedback", model.feedback_documents()}}}};
  if (!info.empty()) document["info"] = info;
  return document;
}

HystereticLfrFile load_hysteretic_lfr(const std::filesystem::path& path) {
  const nlohmann::json document = io::parse_json_text(io::read_file(path), path.string());
  return hysteretic_lfr_from_json(document, path.string());
}

void save_hysteretic_lfr(const std::filesystem::path& path, const AnyHystereticLfr& model,
                         const nlohmann::json& info) {
  io::write_file_atomically(path, hysteretic_lfr_to_json(model, info).dump(2) + "\n");
}

}  // namespace hyst
