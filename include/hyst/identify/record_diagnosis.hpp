#pragma once
//! \file
//! Why may no model describe a record? Three cheap looks at the measured data alone, given with
//! the no-fit verdict of a comparison. They are hints, not proofs:
//!
//! - butterfly: the output turns back on input branches (data/branches.hpp, band 2 % of the input
//!   range): on a branch, the output goes beyond both of its end values by more than 5 % of the
//!   record's output range (well above measurement noise: the monotone piezo loops of
//!   MeasurementData.mat turn back by 0.5 % at most, the 1.9 kV butterfly by 9.7 %). Flagged when
//!   the branches that do so cover at least a third of the input travel of all branches (one branch
//!   through the whole input range of a one-period record is enough), as the strain of a piezo
//!   ceramic driven through its coercive field turns back. Rate-independent hysteresis models with
//!   monotone branches cannot follow that.
//! - drift: the output at a repeated input value trends: at every crossing of the input through
//!   the middle of its range in one direction (rising or falling) the output is interpolated, and
//!   a straight line is fitted through these outputs over the crossing number; flagged when that
//!   line changes by more than 10 % of the output range from the first to the last crossing (at
//!   least three crossings). Memory of different reversal histories can look alike.
//! - extrapolation: the held-out input leaves the fit part's input range by more than 5 % of that
//!   range; the models never saw those inputs.

#include <span>
#include <string>
#include <vector>

#include "hyst/identify/data_split.hpp"

namespace hyst {

struct RecordDiagnosis {
  bool butterfly = false;
  bool drift = false;
  bool extrapolation = false;
  std::vector<std::string> findings;  //!< one phrase with the figures per flag that is set
};

//! The three looks of the file comment at `input`/`output` split by `split`. Throws hyst::Error
//! when the lengths differ or the split lies outside the record; data too short or too flat for a
//! look simply does not raise its flag.
RecordDiagnosis diagnose_record(std::span<const double> input, std::span<const double> output,
                                const DataSplit& split);

//! The looks at a separate held-out record (cross_record_compare.hpp): butterfly and drift on the
//! held-out record itself, extrapolation of its input beyond the input range of the records the
//! models were fitted on (`fit_input`, joined). Throws hyst::Error when the held-out lengths
//! differ or a record is empty.
RecordDiagnosis diagnose_held_out_record(std::span<const double> fit_input,
                                         std::span<const double> held_input,
                                         std::span<const double> held_output);

}  // namespace hyst
