#pragma once
//! \file
//! The one exception type of hyst: invalid user input (parameters, files, data).
//!
//! It is thrown at construction or load time, never from a model's `step()`. Numerical outcomes
//! inside a loop (an inverse asked for an output it cannot reach) are returned as a status instead.

#include <stdexcept>
#include <string>

namespace hyst {

//! Invalid user input. The message names the quantity, its index and value, and the rule broken,
//! e.g. "PI threshold r[3] = -0.2 must be >= 0".
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hyst
