#pragma once
//! \file
//! The hysteretic LFR (hyst/dynamics/hysteretic_lfr.hpp) chosen at run time, and its model file:
//!
//!     {"model": "hysteretic_lfr", "version": 1,
//!      "params": {"inputs": 3,
//!                 "linear": {"sample_time": ..., "a": [[...]], "b": ..., "c": ..., "d": ...},
//!                 "feedback": [{"model": "pi", "params": {...}}, ...]},
//!      "info": {...}}
//!
//! "linear" is the "params" object of a state-space model file (state_space_file.hpp) with the
//! inputs ordered (u, w) and the outputs (y, z); "feedback" has one model per hysteresis channel,
//! each in the model-file form of its registry entry, all of one kind among the models an actuator
//! force can follow (AnyHysteresis: pi, gpi, preisach, modified_pi, kp, maxwell_slip, ikuta_sma,
//! bouc_wen). A Hammerstein system is written as the LFR it is (z = u). Loading validates
//! everything; messages name the file and the field ("m.json: params.feedback[1].params.weights:
//! ..."). "info" is free-form and kept as it is.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string_view>
#include <variant>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "hyst/dynamics/initial_state_estimate.hpp"
#include "hyst/dynamics/periodic_signals.hpp"
#include "hyst/dynamics/simulation_score.hpp"
#include "hyst/registry/actuator_force.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst {

template <class Models>
struct HystereticLfrOf;
template <class... H>
struct HystereticLfrOf<std::variant<H...>> {
  using type = std::variant<HystereticLfr<H>...>;
};
//! A hysteretic LFR of any hysteresis model an actuator force can follow.
using AnyHystereticLfrModel = HystereticLfrOf<AnyHysteresis>::type;

class AnyHystereticLfr {
 public:
  //! The LFR of `linear` with `inputs` inputs u and one hysteresis channel per feedback model
  //! (models of the registry, all of one entry with an actuator force). Throws hyst::Error for
  //! models of different kinds, a model that cannot be a feedback channel, or the size errors of
  //! HystereticLfr.
  AnyHystereticLfr(StateSpace linear, std::size_t inputs,
                   const std::vector<const DynamicModel*>& feedback);
  //! The Hammerstein system: blocks[i] on input i, then `linear` (as many inputs as blocks).
  static AnyHystereticLfr hammerstein(const StateSpace& linear,
                                      const std::vector<const DynamicModel*>& blocks);

  const AnyHystereticLfrModel& model() const { return model_; }
  const StateSpace& linear() const;
  std::size_t inputs() const;
  std::size_t outputs() const;
  std::size_t order() const;
  double sample_time() const;
  std::size_t feedback_channels() const { return feedback_.size(); }
  //! The feedback models in model-file form: {"model": name, "params": {...}} each.
  const nlohmann::json& feedback_documents() const { return feedback_; }
  //! The registry name of the feedback models ("pi").
  const std::string& feedback_model() const { return feedback_name_; }
  //! The parameters of the model: the linear block's A by its order n (a change of state
  //! coordinates changes A's entries, not the model: its n eigenvalues count), the entries of B,
  //! C and D but the zero Dzw block, and every feedback model's parameters. A fit may hold some
  //! of them fixed (fit_hysteretic_lfr() fixes each PI channel's r = 0 weight and offset, which
  //! the linear block carries): its report counts the ones it fitted.
  std::size_t parameter_count() const { return parameter_count_; }
  //! The feedback models' part of parameter_count().
  std::size_t feedback_parameter_count() const { return feedback_parameter_count_; }

  //! y (N x p) for u (N x m) from rest, or (periodic_start) from the periodic steady state of
  //! `one_period` (N' x m), which `input` then continues. Errors as HystereticLfr's.
  Eigen::MatrixXd simulate(const Eigen::MatrixXd& input) const;
  Eigen::MatrixXd simulate_from_periodic_state(const Eigen::MatrixXd& input,
                                               const Eigen::MatrixXd& one_period) const;
  //! y (N x p) for u (N x m) from the linear-block state x0, the hysteresis channels at rest.
  Eigen::MatrixXd simulate_from_state(const Eigen::MatrixXd& input,
                                      const Eigen::VectorXd& x0) const;
  //! The linear-block state that the first `samples` of (input, output) show
  //! (initial_state_estimate.hpp): the linear block's least squares with the feedback open,
  //! refined by Gauss-Newton on the whole model with the hysteresis channels from rest.
  InitialStateEstimate estimate_initial_state(const Eigen::MatrixXd& input,
                                              const Eigen::MatrixXd& output,
                                              std::size_t samples) const;

 private:
  AnyHystereticLfr(AnyHystereticLfrModel model, nlohmann::json feedback, std::string name,
                   std::size_t feedback_parameters);
  AnyHystereticLfrModel model_;
  nlohmann::json feedback_;
  std::string feedback_name_;
  std::size_t parameter_count_ = 0;
  std::size_t feedback_parameter_count_ = 0;
};

//! A hysteretic LFR with PI models (e.g. fit_hysteretic_lfr()'s) in the run-time form.
AnyHystereticLfr any_hysteretic_lfr(const HystereticLfr<PrandtlIshlinskii>& model);

//! The benchmark score of a hysteretic LFR (simulation_score.hpp); periodic: each realisation
//! starts in the periodic steady state of its first period.
SimulationScore score_hysteretic_lfr(const AnyHystereticLfr& model, const PeriodicSignals& input,
                                     const PeriodicSignals& output,
                                     const ScoreOptions& options = {});

struct HystereticLfrFile {
  AnyHystereticLfr model;
  nlohmann::json info = nlohmann::json::object();
};

//! From a parsed document; `source` prefixes every message.
HystereticLfrFile hysteretic_lfr_from_json(const nlohmann::json& document, std::string_view source);
nlohmann::json hysteretic_lfr_to_json(const AnyHystereticLfr& model,
                                      const nlohmann::json& info = nlohmann::json::object());
HystereticLfrFile load_hysteretic_lfr(const std::filesystem::path& path);
//! Writes a model file atomically.
void save_hysteretic_lfr(const std::filesystem::path& path, const AnyHystereticLfr& model,
                         const nlohmann::json& info = nlohmann::json::object());

}  // namespace hyst
