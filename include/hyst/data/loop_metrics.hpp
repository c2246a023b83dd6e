#pragma once
//! \file
//! Figures of a hysteresis loop traced by an input/output record: the loop area (energy per
//! cycle), the coercive inputs and remanent outputs, and the loop closure error.
//!
//! Area: the signed area of the polygon (x_k, y_k) = (input, output), closed by the segment from
//! the last sample back to the first (shoelace formula):
//!     A = 1/2 sum_k (x_k y_{k+1} - x_{k+1} y_k)
//! It equals the contour integral of input d(output), positive for a loop traversed
//! counter-clockwise (ascending branch below the descending one, the usual orientation of
//! hysteresis with the output lagging the input). For a B(H) loop (input H, output B) it is the
//! energy dissipated per cycle and volume [J/m^3]; for a P(E) loop likewise.
//! Example: x = A sin t, y = B sin(t - phi) gives A = pi A B sin(phi); N samples per period give
//! exactly (N/2) sin(2 pi / N) A B sin(phi) (an affine image of a regular N-gon).
//!
//! Coercive inputs: the input where the output crosses `output_level` (0: the coercive field);
//! remanent outputs: the output where the input crosses `input_level` (0: the remanence). Both
//! are interpolated linearly between the two samples of the crossing (a crossing is a segment
//! from strictly below to at-or-above the level, or from strictly above to at-or-below it) and
//! carry the direction the input moves in there. Closure error: output at the end of a cycle
//! minus output at its start (0 for a closed loop; drift makes it non-zero).

#include <cstddef>
#include <span>
#include <vector>

#include "hyst/data/branches.hpp"

namespace hyst::data {

//! Signed polygon area of (input, output), see the file comment. Throws hyst::Error unless both
//! have the same length >= 3 and every sample is finite.
double loop_area(std::span<const double> input, std::span<const double> output);

struct LevelCrossing {
  double value = 0.0;     //!< the interpolated other quantity at the crossing
  std::size_t index = 0;  //!< the crossing lies between samples index and index + 1
  Direction direction = Direction::ascending;  //!< direction the input moves in there
};

//! Inputs at which the output crosses `output_level`, in record order.
std::vector<LevelCrossing> coercive_inputs(std::span<const double> input,
                                           std::span<const double> output,
                                           double output_level = 0.0);
//! Outputs at which the input crosses `input_level`, in record order.
std::vector<LevelCrossing> remanent_outputs(std::span<const double> input,
                                            std::span<const double> output,
                                            double input_level = 0.0);

//! The figures of one loop (one cycle of a record).
struct LoopMetrics {
  std::size_t first = 0;        //!< first sample of the cycle in the record
  std::size_t last = 0;         //!< last sample (inclusive)
  double area = 0.0;            //!< loop_area() [input units x output units]
  double closure_error = 0.0;   //!< output[last] - output[first] [output units]
  double input_mismatch = 0.0;  //!< input[last] - input[first] (0 for an exactly closed cycle)
  double input_min = 0.0, input_max = 0.0, output_min = 0.0, output_max = 0.0;
  std::vector<LevelCrossing> coercive;  //!< coercive_inputs() of the cycle (indices in record)
  std::vector<LevelCrossing> remanent;  //!< remanent_outputs() of the cycle (indices in record)
};

//! LoopMetrics of the samples first..last (inclusive) of a record. Throws hyst::Error for invalid
//! data or a range outside the record or shorter than 3 samples.
LoopMetrics loop_metrics(std::span<const double> input, std::span<const double> output,
                         std::size_t first, std::size_t last, double input_level = 0.0,
                         double output_level = 0.0);

//! LoopMetrics of every cycle (cycles.hpp) of the record, with hysteresis band `band`.
std::vector<LoopMetrics> cycle_metrics(std::span<const double> input,
                                       std::span<const double> output, double band,
                                       double input_level = 0.0, double output_level = 0.0);

}  // namespace hyst::data
