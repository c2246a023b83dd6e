#pragma once
// Synthetic records with exactly known reversal points, branches and cycles: piecewise-linear
// inputs through integer nodes in unit steps, so every sample is an exact small integer.

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <vector>

namespace hyst::test {

// The path through `nodes` in steps of 1 (each node once, at its exact value).
inline std::vector<double> through_nodes(const std::vector<int>& nodes) {
  std::vector<double> path{static_cast<double>(nodes.front())};
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const int step = nodes[i] > nodes[i - 1] ? 1 : -1;
    for (int v = nodes[i - 1] + step; v != nodes[i] + step; v += step)
      path.push_back(v);
  }
  return path;
}

// A triangle wave of amplitude `peak` with 4 * peak samples per period, starting at 0 rising:
// maxima at k = peak + 4 peak j, minima at 3 peak + 4 peak j. `periods` whole periods plus one
// closing sample (the record ends at 0 rising, like it started).
inline std::vector<double> triangle(int peak, int periods) {
  std::vector<int> nodes{0};
  for (int j = 0; j < periods; ++j) {
    nodes.push_back(peak);
    nodes.push_back(-peak);
    nodes.push_back(0);
  }
  return through_nodes(nodes);
}

}  // namespace hyst::test
