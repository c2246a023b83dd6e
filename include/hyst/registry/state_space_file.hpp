#pragma once
//! \file
//! The model-file form of a linear state-space model (hyst/dynamics/state_space.hpp):
//!
//!     {"model": "state_space", "version": 1,
//!      "params": {"sample_time": 1.5625e-4,
//!                 "a": [[...], ...], "b": [[...], ...], "c": [[...], ...], "d": [[...], ...]},
//!      "state": {"x": [...]},
//!      "info": {...}}
//!
//! Matrices are arrays of rows, numbers written so that they read back exactly. A model with no
//! state (n = 0, the static gain D) has "a": [] and "b": [] (no rows: the input count m comes from
//! D) and "c": one empty row per output ([[], []] for p = 2); "state" then has "x": []. Loading
//! validates everything; unknown fields and wrong types are errors that name the file and the
//! field ("m.json: params.b[2][0]: expected a number"). "state" may be left out; "info" is
//! free-form and kept as it is.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hyst/dynamics/state_space.hpp"

namespace hyst {

struct StateSpaceFile {
  StateSpace model;
  std::optional<Eigen::VectorXd> state;  //!< the "state" field when present
  nlohmann::json info = nlohmann::json::object();
};

//! From a parsed document; `source` prefixes every message.
StateSpaceFile state_space_from_json(const nlohmann::json& document, std::string_view source);
//! The document of a model (and optionally a state, and free-form info). Throws hyst::Error for a
//! state of the wrong size or with a non-finite value.
nlohmann::json state_space_to_json(const StateSpace& model,
                                   const std::optional<Eigen::VectorXd>& state = std::nullopt,
                                   const nlohmann::json& info = nlohmann::json::object());
//! The "params" object of a state-space model file alone (also the linear block of other models'
//! files); messages name `path` ("params.linear.b[2][0]: expected a number").
StateSpace state_space_from_params(const nlohmann::json& params, const std::string& path);
//! The "params" object of a model.
nlohmann::json state_space_params_to_json(const StateSpace& model);
//! Reads and validates a model file.
StateSpaceFile load_state_space(const std::filesystem::path& path);
//! Writes a model file atomically (nothing is written when the state is refused).
void save_state_space(const std::filesystem::path& path, const StateSpace& model,
                      const std::optional<Eigen::VectorXd>& state = std::nullopt,
                      const nlohmann::json& info = nlohmann::json::object());

}  // namespace hyst
