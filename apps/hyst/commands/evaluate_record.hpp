#pragma once
// hyst evaluate on a single-input model (any model of the registry): its prediction of one
// measured record under the validation rule of `hyst fit --validation-data`, scored as there.

#include <cstddef>
#include <optional>
#include <string>

#include "../record_time.hpp"

namespace hyst::cli {

struct RecordEvaluation {
  std::string model;                 //!< model file
  std::string data;                  //!< data file
  std::optional<std::size_t> table;  //!< table of a multi-table file
  std::string input;                 //!< input column
  std::string output;                //!< measured output column
  std::string start = "rest";        //!< rest, periodic or file
  std::string align = "none";        //!< none or first-sample
  TimeOptions time;                  //!< the record's time axis
  bool json = false;
  bool strict = false;  //!< inputs beyond the fitted domain are an error, not a warning
};

//! Scores the model of `options.model` on the record and prints the result (text or JSON).
void evaluate_record(const RecordEvaluation& options);

}  // namespace hyst::cli
