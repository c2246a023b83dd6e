#pragma once
//! \file
//! The memory of a Preisach model: the staircase of alternating dominant input extrema.
//!
//! At any time the Preisach triangle {lower <= beta <= alpha <= upper} splits into the relays at
//! +1 (S+) and at -1 (S-), separated by a staircase whose corners are the input extrema that have
//! not been wiped out (Mayergoyz 1991, ch. 1):
//!
//!     x_0, x_1, x_2, ..., x_n        x_0 = -inf (history starts at negative saturation)
//!                                    x_0 = +inf (history starts at positive saturation)
//!
//! alternating minima and maxima, the maxima strictly decreasing and the minima strictly
//! increasing (m_0 < m_1 < ... < ... < M_2 < M_1): each new extremum lies inside the previous
//! loop. A new maximum wipes out every stored maximum it reaches (and the minimum stored after
//! it), a new minimum every stored minimum it reaches; an input below the lower saturation value
//! resets the memory to negative saturation, one above the upper to positive saturation.
//!
//! Next to each extremum the state keeps the running sum of the Everett terms up to it (see
//! preisach.hpp), so that a sample costs one or two Everett evaluations plus one comparison per
//! wiped pair, whatever the number of relays. The sums are not accumulated over time: a pop
//! restores a value computed earlier and a push adds one term to it, so rounding stays bounded by
//! the memory depth (a few ulp of the total weight), also after millions of samples.
//!
//! **Capacity.** The memory is a fixed-capacity array inside the state, so stepping never
//! allocates: at most `max_pairs` = 256 (maximum, minimum) pairs after x_0. Only an input with
//! ever-shrinking oscillations (more than 256 loops nested in one another) fills it; the next new
//! extremum then drops the innermost stored pair (the two most recent extrema) before it is
//! stored, i.e. the model forgets the smallest remembered loop, and `truncations` counts it.
//! A random walk of a million samples (test_preisach) kept at most 50 pairs. The state is
//! ~8 KiB, copied without allocation.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst {

//! The initial state of a Preisach model.
enum class PreisachInitialState : unsigned char {
  negative_saturation,  //!< every relay at -1: memory {-inf}; the usual default
  positive_saturation,  //!< every relay at +1: memory {+inf}
  //! relays with alpha + beta < lower + upper at +1, the others at -1 (staircase along the
  //! anti-diagonal through the centre of the input range), reached from negative saturation by a
  //! decaying alternating input: what an AC demagnetisation leaves behind
  demagnetised,
};

//! "negative_saturation", "positive_saturation", "demagnetised".
constexpr EnumNames<PreisachInitialState, 3> enumerator_names(PreisachInitialState) {
  return {{
      {PreisachInitialState::negative_saturation, "negative_saturation"},
      {PreisachInitialState::positive_saturation, "positive_saturation"},
      {PreisachInitialState::demagnetised, "demagnetised"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
PreisachInitialState preisach_initial_state_from_string(std::string_view text);

//! The alternating input M_1, m_1, ..., M_K, m_K with m_k = lower + k h, M_k = upper - (k - 1/2) h,
//! h = (upper - lower) / (2K), K = pairs. From negative saturation it leaves a staircase whose
//! steps cross the anti-diagonal alpha + beta = lower + upper at their midpoints: the demagnetised
//! state of a continuous Preisach model (its area is exact to O(h^2) for a smooth density).
//! Throws hyst::Error unless 1 <= pairs <= PreisachState::max_pairs and lower < upper are finite.
std::vector<double> preisach_midpoint_staircase(double lower, double upper, std::size_t pairs);

//! The running memory of any Preisach model (see the file comment). Create it with the model's
//! initial_state() or make_state(); the fields are public for serialisation, but only states made
//! by a model (or validated by its make_state()) may be stepped.
struct PreisachState {
  static constexpr std::size_t max_pairs = 256;               //!< capacity in extremum pairs
  static constexpr std::size_t capacity = 2 * max_pairs + 1;  //!< entries, x_0 included

  //! x_0 = -inf or +inf, then the stored extrema x_1 .. x_{size-1} [input units]. A default
  //! constructed state is negative saturation.
  std::array<double, capacity> extrema = negative_saturation_extrema();
  //! partial[t] = measure of S+ contributed by x_0 .. x_t (partial[0] = 0 or the total weight).
  std::array<double, capacity> partial{};
  std::size_t size = 1;  //!< entries in use, x_0 included (1 .. capacity)
  //! The last input [input units]; equal to x_0 (+-inf) when no input was applied since the state
  //! was (re)set to saturation.
  double input = -std::numeric_limits<double>::infinity();
  std::uint64_t truncations = 0;  //!< pairs dropped because the memory was full

  //! {-inf, 0, 0, ...}: x_0 of a history from negative saturation.
  static constexpr std::array<double, capacity> negative_saturation_extrema() {
    std::array<double, capacity> x{};
    x[0] = -std::numeric_limits<double>::infinity();
    return x;
  }

  //! True if the history starts at positive saturation (x_0 = +inf).
  bool from_positive_saturation() const { return extrema[0] > 0.0; }
  //! The stored extrema after x_0, oldest first (alternating max/min when x_0 = -inf,
  //! min/max when x_0 = +inf). Finite values within the model's input range.
  std::span<const double> memory() const { return {extrema.data() + 1, size - 1}; }
  //! True if entry t (0 <= t < size) is a minimum, i.e. the input rises from it.
  bool is_minimum(std::size_t t) const { return ((t & 1U) == 0) == (extrema[0] < 0.0); }
};

}  // namespace hyst
