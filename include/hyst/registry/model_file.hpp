#pragma once
//! \file
//! Model files: one model with its parameters and (optionally) its state, as JSON.
//!
//!     {"model": "pi", "version": 1,
//!      "params": {"thresholds": [0, 0.3, 0.7], "weights": [0.8, 0.5, 0.3], "offset": 0},
//!      "state":  {"play": [0, 0, 0]},
//!      "info":   {...}}
//!
//! Loading validates everything; unknown fields and wrong types are errors, and every message
//! names the file and the field: "m.json: params.thresholds[3]: PI threshold r[3] = -0.2 must be
//! > r[2] = 1". "state" may be left out (the model's default initial state); "info" is free-form
//! (e.g. the fit report that produced the file) and ignored when loading. Writes are atomic.

#include <filesystem>
#include <memory>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {

//! The model-file format version this library reads and writes.
inline constexpr int kModelFileVersion = 1;

//! Checks a document's "version" field (null when missing); hyst::Error says what this library
//! reads ("version: 2 is not supported (this library reads version 1)").
void require_model_file_version(const nlohmann::json* version);

//! Builds a model from a parsed model-file document; `source` (a file name) prefixes messages.
std::unique_ptr<DynamicModel> model_from_json(
    const nlohmann::json& document, std::string_view source,
    const ModelRegistry& registry = ModelRegistry::builtin());

//! The model-file document of a model in its current state; `info` is stored as given.
nlohmann::json model_to_json(const DynamicModel& model,
                             const nlohmann::json& info = nlohmann::json::object());

//! Reads and validates a model file.
std::unique_ptr<DynamicModel> load_model(const std::filesystem::path& path,
                                         const ModelRegistry& registry = ModelRegistry::builtin());

//! Writes a model file atomically (temporary file, then rename).
void save_model(const std::filesystem::path& path, const DynamicModel& model,
                const nlohmann::json& info = nlohmann::json::object());

}  // namespace hyst
