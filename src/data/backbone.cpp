#include "hyst/data/backbone.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/data/branches.hpp"
#include "hyst/data/reversal_points.hpp"
#include "record_checks.hpp"

namespace hyst::data {
namespace {

//! The longest branch of a direction, or nullopt.
std::optional<Branch> longest(const std::vector<double>& input, const std::vector<Branch>& found,
                              Direction direction) {
  std::optional<Branch> best;
  double best_length = 0.0;
  for (const auto& branch : found) {
    const double length = std::abs(input[branch.last] - input[branch.first]);
    if (branch.direction == direction && length > best_length) {
      best = branch;
      best_length = length;
    }
  }
  return best;
}

//! The output where the branch first passes `target` (the branch's samples in its direction).
double output_at(const std::vector<double>& input, const std::vector<double>& output,
                 const Branch& branch, double target) {
  const double sense = branch.direction == Direction::ascending ? 1.0 : -1.0;
  if (sense * input[branch.first] >= sense * target) return output[branch.first];
  for (std::size_t j = branch.first + 1; j <= branch.last; ++j) {
    if (sense * input[j] >= sense * target) {
      const double t = (target - input[j - 1]) / (input[j] - input[j - 1]);
      return output[j - 1] + t * (output[j] - output[j - 1]);
    }
  }
  return output[branch.last];
}

}  // namespace

Backbone backbone(std::span<const double> input, std::span<const double> output, double band,
                  std::size_t first, std::size_t last, std::size_t points) {
  detail::require_record(input, output, 3);
  if (!(first < last && last < input.size())) {
    throw Error(fmt::format("loop samples {}..{} must lie in the record (0..{})", first, last,
                            input.size() - 1));
  }
  if (points < 2) throw Error(fmt::format("backbone points = {} must be >= 2", points));
  // A loop usually starts inside a branch, which the record's start splits in two: rotate it to
  // start and end at its first reversal point, so that each branch is whole.
  const auto loop_x = input.subspan(first, last - first + 1);
  const auto loop_y = output.subspan(first, last - first + 1);
  const auto turns = reversal_points(loop_x, band);
  std::vector<double> x, y;
  const std::size_t start = turns.empty() ? 0 : turns.front().index;
  for (std::size_t k = start; k < loop_x.size(); ++k) {
    x.push_back(loop_x[k]);
    y.push_back(loop_y[k]);
  }
  for (std::size_t k = 1; k <= start; ++k) {  // sample 0 is (about) the last one again
    x.push_back(loop_x[k]);
    y.push_back(loop_y[k]);
  }
  const auto found = branches(x, band);
  const auto up = longest(x, found, Direction::ascending);
  const auto down = longest(x, found, Direction::descending);
  if (!up || !down) {
    throw Error(
        fmt::format("the loop (samples {}..{}) needs an ascending and a descending "
                    "branch, but has only {} ones",
                    first, last, up ? "ascending" : "descending"));
  }
  // The input range both branches cover.
  const double low = std::max(x[up->first], x[down->last]);
  const double high = std::min(x[up->last], x[down->first]);
  if (!(high > low)) {
    throw Error(
        fmt::format("the ascending and descending branches of the loop do not cover a "
                    "common input range ([{}, {}] and [{}, {}])",
                    x[up->first], x[up->last], x[down->last], x[down->first]));
  }
  Backbone result;
  for (std::size_t i = 0; i < points; ++i) {
    const double v = low + (high - low) * static_cast<double>(i) / static_cast<double>(points - 1);
    const double a = output_at(x, y, *up, v);
    const double d = output_at(x, y, *down, v);
    result.input.push_back(v);
    result.ascending.push_back(a);
    result.descending.push_back(d);
    result.centre.push_back(0.5 * (a + d));
    result.half_width.push_back(0.5 * (d - a));
  }
  return result;
}

}  // namespace hyst::data
