#pragma once
//! \file
//! The one exception type of hyst: invalid user input (parameters, files, data).
//!
//! It is thrown at construction or load time, never from a model's `step()`. Numerical outcomes
//! inside a loop (an inverse asked for an output it cannot reach) are returned as a status instead.

#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace hyst {

//! Invalid user input. The message names the quantity, its index and value, and the rule broken,
//! e.g. "PI threshold r[3] = -0.2 must be >= 0".
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  //! An error about one parameter: `field` is its name in the Params struct (and in model files),
  //! with the index where it has one, e.g. "thresholds[3]".
  Error(const std::string& message, std::string field)
      : std::runtime_error(message), field_(std::move(field)) {}

  //! The offending parameter field, or empty when the error is not about one field.
  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

//! The system's text for an errno value ("No such file or directory"), for messages about files.
inline std::string errno_message(int error_number) {
  return std::generic_category().message(error_number);
}

}  // namespace hyst
