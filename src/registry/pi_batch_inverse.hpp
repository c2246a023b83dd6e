#pragma once
// The inverse PI over a batch of targets in O(log m) amortised per sample instead of O(m), for
// `hyst invert` and Python on models with many operators. Same answers as InversePrandtlIshlinskii
// ::solve sample by sample, up to the rounding of the weighted sum, and the same state at the end.
//
// The inverse is a PI operator with thresholds 0 = rh_0 < rh_1 < ... and weights ph_j. In a
// reachable state neighbouring plays differ by at most rh_{j+1} - rh_j, so for an input v above
// w_0 the plays that move (w_j < v - rh_j) are a prefix j < J, found by binary search, and they
// become v - rh_j (v + rh_j for a falling input). The state is kept as a stack of such segments
// [a, b) with w_j = c + s rh_j over the untouched rest of the initial state, each with the output
// sum of itself and everything below it (prefix sums of ph, ph rh and ph w); a step pops the
// segments it wipes out, cuts one and pushes one. The play vector is written back at the end.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "hyst/core/checks.hpp"
#include "hyst/core/inverse_status.hpp"
#include "hyst/inverse/inverse_prandtl_ishlinskii.hpp"

namespace hyst::detail {

// A run of plays w_j = c + s r_j, j in [start, end), with start the end of the segment above it
// (or 0).
struct PiBatchSegment {
  std::size_t end;
  double c;
  double s;      // -1 (risen to c) or +1 (fallen to c)
  double total;  // output sum of this segment and of everything below it
};

// The memory invert_pi_batch works in, kept by its caller: a batch after the first on the same
// model allocates nothing.
struct PiBatchWorkspace {
  std::vector<double> sum_p, sum_pr, sum_pw;
  std::vector<PiBatchSegment> stack;
};

inline InverseReport invert_pi_batch(const InversePrandtlIshlinskii& inverse,
                                     PrandtlIshlinskii::State& state,
                                     std::span<const double> targets, std::span<double> inputs,
                                     PiBatchWorkspace& workspace) {
  require_same_size(targets.size(), "targets", inputs.size(), "inputs");
  require_finite(targets, "targets");
  const auto& r = inverse.inverse_operator().params().thresholds;
  const auto& p = inverse.inverse_operator().params().weights;
  const double offset = inverse.forward().params().offset;
  const auto& options = inverse.options();
  const double bound = inverse.target_bound();
  std::vector<double>& w = state.play;
  const std::size_t m = r.size();

  // Prefix sums: P[j] = sum_{i<j} p_i, Q[j] = sum_{i<j} p_i r_i, W[j] = sum_{i<j} p_i w_i.
  auto& sum_p = workspace.sum_p;
  auto& sum_pr = workspace.sum_pr;
  auto& sum_pw = workspace.sum_pw;
  sum_p.assign(m + 1, 0.0);
  sum_pr.assign(m + 1, 0.0);
  sum_pw.assign(m + 1, 0.0);
  for (std::size_t j = 0; j < m; ++j) {
    sum_p[j + 1] = sum_p[j] + p[j];
    sum_pr[j + 1] = sum_pr[j] + p[j] * r[j];
    sum_pw[j + 1] = sum_pw[j] + p[j] * w[j];
  }
  using Segment = PiBatchSegment;
  // stack.back() is the top segment, starting at j = 0. Every segment ends at another play, so
  // there are at most m.
  auto& stack = workspace.stack;
  stack.clear();
  stack.reserve(m);
  std::size_t untouched = 0;  // plays [untouched, m) still hold the initial state
  const auto segment_sum = [&](double c, double s, std::size_t a, std::size_t b) {
    return c * (sum_p[b] - sum_p[a]) + s * (sum_pr[b] - sum_pr[a]);
  };
  const auto below_total = [&]() {
    return stack.empty() ? sum_pw[m] - sum_pw[untouched] : stack.back().total;
  };
  double output = sum_pw[m];  // sum_j p_j w_j of the initial state

  InverseReport report;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    // Beyond the bound where the sum would overflow: answered as the bound (as solve() does).
    const double wanted = targets[k] - offset;
    const double v = std::clamp(wanted, -bound, bound);
    const InverseStatus bound_status = wanted > bound    ? InverseStatus::above_range
                                       : wanted < -bound ? InverseStatus::below_range
                                                         : InverseStatus::ok;
    const double w0 = stack.empty() ? w[0] : stack.back().c + stack.back().s * r[0];
    if (v != w0) {
      const double d = v > w0 ? 1.0 : -1.0;  // rising or falling
      // h_j = d (w_j - v) + r_j is non-decreasing in j; the plays with h_j < 0 move.
      std::size_t moved = 0;  // J: plays [0, J) move
      std::size_t lower = 0;  // the plays [0, lower) of wiped-out segments move
      bool found = false;
      while (!stack.empty()) {
        const Segment top = stack.back();
        const std::size_t a = lower;
        const std::size_t b = top.end;
        const auto h = [&](std::size_t j) { return d * (top.c + top.s * r[j] - v) + r[j]; };
        if (h(b - 1) < 0.0) {  // wiped out
          lower = b;
          stack.pop_back();
          continue;
        }
        moved = static_cast<std::size_t>(
            std::partition_point(r.begin() + static_cast<std::ptrdiff_t>(a),
                                 r.begin() + static_cast<std::ptrdiff_t>(b),
                                 [&](const double& rj) {
                                   return h(static_cast<std::size_t>(&rj - r.data())) < 0.0;
                                 }) -
            r.begin());
        found = true;
        break;
      }
      if (!found) {
        moved = static_cast<std::size_t>(
            std::partition_point(r.begin() + static_cast<std::ptrdiff_t>(untouched), r.end(),
                                 [&](const double& rj) {
                                   const auto j = static_cast<std::size_t>(&rj - r.data());
                                   return d * (w[j] - v) + r[j] < 0.0;
                                 }) -
            r.begin());
        moved = std::max(moved, untouched);
        untouched = moved;
      }
      if (moved > 0) {
        if (!stack.empty()) {
          // The cut segment now starts at `moved`: its total without the part that moved.
          Segment& cut = stack.back();
          const double below =
              stack.size() >= 2 ? stack[stack.size() - 2].total : sum_pw[m] - sum_pw[untouched];
          cut.total = below + segment_sum(cut.c, cut.s, moved, cut.end);
        }
        const double total = below_total() + segment_sum(v, -d, 0, moved);
        stack.push_back({moved, v, -d, total});
      }
      output = below_total();
    }
    const double input = output;
    InverseStatus status = bound_status;
    double answer = input;
    if (!(input >= options.input_min)) {
      answer = options.input_min;
      status = InverseStatus::below_range;
    } else if (input > options.input_max) {
      answer = options.input_max;
      status = InverseStatus::above_range;
    }
    inputs[k] = answer;
    report.record(k, status);
  }
  // Write the segments back into the play vector.
  for (std::size_t i = 0; i < stack.size(); ++i) {
    const Segment& segment = stack[i];
    for (std::size_t j = i + 1 < stack.size() ? stack[i + 1].end : 0; j < segment.end; ++j)
      w[j] = segment.c + segment.s * r[j];
  }
  return report;
}

}  // namespace hyst::detail
