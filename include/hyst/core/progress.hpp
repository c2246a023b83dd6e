#pragma once
//! \file
//! Progress of a long run (a model comparison, a batch of fits), for a display.

#include <cstddef>
#include <functional>
#include <string_view>

namespace hyst {

//! Where a long run stands: `done` of `total` steps of `task` ("models", "fits") are finished;
//! `current` names the step that starts now (empty in the last report, when done == total).
struct Progress {
  std::string_view task;
  std::size_t done = 0;
  std::size_t total = 0;
  std::string_view current;
};

//! Called by a long run before each of its steps and once at the end (done == total), from the
//! thread that runs it; never per sample. An exception thrown by it stops the run.
using ProgressCallback = std::function<void(const Progress&)>;

}  // namespace hyst
