#pragma once
//! \file
//! The fitted domain (identify/fitted_domain.hpp) in a model file: the object info.domain that
//! `hyst fit` writes, read back by the commands that check a record against it.

#include <filesystem>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "hyst/identify/fitted_domain.hpp"

namespace hyst {

//! {"input_min": ..., "input_max": ..., "output_min": ..., "output_max": ..., "samples": ...,
//!  "largest_input_step": ..., "longest_hold_samples": ..., "sample_time": ... (when known)}.
nlohmann::json fitted_domain_json(const FittedDomain& domain);

//! The domain of a model-file document (its info.domain), or nothing when it has none (a model
//! written by hand, or by a version before domains). hyst::Error naming `source` and the field
//! for a malformed one.
std::optional<FittedDomain> fitted_domain_of(const nlohmann::json& document,
                                             std::string_view source);

//! fitted_domain_of() on the model file at `path`.
std::optional<FittedDomain> load_fitted_domain(const std::filesystem::path& path);

}  // namespace hyst
