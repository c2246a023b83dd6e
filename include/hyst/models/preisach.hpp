#pragma once
//! \file
//! The Preisach model in its fast form: staircase memory of dominant input extrema and the
//! Everett function, at a cost per sample that does not grow with the number of relays.
//!
//!     y(t) = y_off + integral_{alpha >= beta} mu(alpha, beta) gamma_{alpha,beta}[v](t) dalpha
//!     dbeta
//!          = y_off - F0 + 2 mu(S+(t))
//!
//! gamma_{alpha,beta} is the relay (relay.hpp: +1 once v >= alpha, -1 once v <= beta), mu >= 0 the
//! Preisach density on the triangle lower <= beta <= alpha <= upper, F0 = mu(triangle) the total
//! weight and S+ the relays at +1. With the memory x_0, x_1, ..., x_n of alternating dominant
//! extrema (preisach_state.hpp) and the Everett function E(alpha, beta) = mu({beta <= beta' <=
//! alpha' <= alpha}), mu(S+) is a sum over the staircase (Mayergoyz 1991, ch. 1):
//!
//!     mu(S+) = B + sum_{t=1..n} T(x_{t-1}, x_t) + T(x_n, v)
//!     T(m, M) = +E(M, m)   when the pair rises from a minimum m to M
//!     T(M, m) = -E(M, m)   when it falls from a maximum M to m
//!
//! with B = 0 for a history from negative saturation (x_0 = -inf) and B = F0 from positive
//! saturation (x_0 = +inf). This is the reference's formula (preisach.md sec. 3) written as one
//! sum; e.g. rising from m_n: y = -F0 + 2 [sum_k (E(M_k, m_{k-1}) - E(M_k, m_k)) + E(v, m_n)].
//! The state keeps the partial sums B + sum_{t<=s} T so that step() evaluates E once for the
//! current term and once more when a reversal stores a new extremum; wiping out just drops
//! entries. Cost per sample: O(1) + O(wiped pairs), independent of the number of relays.
//!
//! The Everett function is a compile-time policy (no virtual call per sample):
//! - Preisach            = BasicPreisach<RelayGridEverett>   discrete relay grid, exact
//! - GaussianPreisach    = BasicPreisach<GaussianEverett>    factorised Gaussian density
//! - LorentzianPreisach  = BasicPreisach<LorentzianEverett>  factorised Lorentzian density
//! - TabulatedPreisach   = BasicPreisach<TabulatedEverett>   bilinear table, e.g. from FORCs
//! For the relay grid the falling current term is -E(x_n, v) + mu_kk when v equals a threshold c_k
//! exactly: the relay rule tests v >= alpha first, so the diagonal relay at v stays at +1 (this
//! reproduces the reference's 101 for the unweighted model at v = 0).
//!
//! Parameters: the Everett function's own (input range [lower, upper] [input units], weights or
//! density [output units]), the output offset y_off [output units] and the initial state.
//! Properties (Mayergoyz's representation theorem): wiping-out, congruent minor loops between the
//! same input extrema (rise = 2 E(v2, v1)), rate independence, return-point memory; the output
//! lies in [y_off - F0, y_off + F0], is y_off - F0 for v < lower and y_off + F0 for v > upper,
//! and never moves against the input.
//!
//! Common mistakes: expecting the first sample to produce a reversal (from negative saturation the
//! first input only rises); an initial state that does not match the experiment (a measured FORC
//! starts at positive saturation, a demagnetised sample is not saturated); inputs outside
//! [lower, upper] saturate the model and erase its memory, so choose the range to cover the data.
//! Sources: Preisach (1935) Z. Physik 94:277; Mayergoyz (1991/2003) "Mathematical Models of
//! Hysteresis"; Doong & Mayergoyz (1985) IEEE Trans. Magn. 21:1853.

#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/assert.hpp"
#include "hyst/core/error.hpp"
#include "hyst/models/everett_factorised.hpp"
#include "hyst/models/everett_relay_grid.hpp"
#include "hyst/models/everett_table.hpp"
#include "hyst/models/preisach_state.hpp"

namespace hyst {

//! What BasicPreisach needs from an Everett-function policy.
template <class E>
concept EverettFunction = std::constructible_from<E, typename E::Params> &&
    requires(const E& everett, double v) {
  //! E(alpha, beta) [output units], for any arguments incl. +-inf
  { everett(v, v) } -> std::same_as<double>;
  //! weight of a diagonal relay exactly at v (discrete grids), else 0
  { everett.diagonal_tie(v) } -> std::same_as<double>;
  { everett.total() } -> std::convertible_to<double>;  //!< F0
  { everett.lower() } -> std::convertible_to<double>;
  { everett.upper() } -> std::convertible_to<double>;
  { everett.demagnetising_input() } -> std::same_as<std::vector<double>>;
};

template <EverettFunction Everett>
class BasicPreisach {
 public:
  using EverettType = Everett;
  struct Params {
    typename Everett::Params everett;  //!< the Everett function (input range, weights/density)
    double offset = 0.0;               //!< y_off [output units]
    PreisachInitialState initial_state = PreisachInitialState::negative_saturation;
  };
  using State = PreisachState;

  //! Validates; throws hyst::Error naming the field (the Everett function's or "offset").
  explicit BasicPreisach(Params params)
      : params_(std::move(params)), everett_(params_.everett), total_(everett_.total()) {
    if (!std::isfinite(params_.offset)) {
      throw Error(fmt::format("Preisach offset = {} is not finite", params_.offset), "offset");
    }
  }

  const Params& params() const { return params_; }
  const Everett& everett() const { return everett_; }
  //! Input range [input units]: the output saturates outside it.
  double lower() const { return everett_.lower(); }
  double upper() const { return everett_.upper(); }
  //! F0 [output units].
  double total_weight() const { return total_; }
  //! y_off - F0 and y_off + F0 [output units].
  double output_min() const { return params_.offset - total_; }
  double output_max() const { return params_.offset + total_; }

  //! The state chosen by params().initial_state.
  State initial_state() const { return make_state(params_.initial_state); }
  //! Negative or positive saturation, or the demagnetised state (the demagnetising input of the
  //! Everett function replayed from negative saturation).
  State make_state(PreisachInitialState kind) const {
    State state;
    reset(state, kind == PreisachInitialState::positive_saturation);
    if (kind == PreisachInitialState::demagnetised) {
      for (double v : everett_.demagnetising_input())
        step(state, v);
    }
    return state;
  }
  //! A state from its stored form (e.g. a file): the saturation the history starts from, the
  //! extrema after x_0 (PreisachState::memory()) and the last input (+-inf = none since
  //! saturation, only with an empty memory). Throws hyst::Error unless the extrema alternate,
  //! are nested (maxima decreasing, minima increasing), lie in [lower, upper] and the input is
  //! consistent with them.
  State make_state(PreisachInitialState saturation, std::span<const double> memory,
                   double input) const;

  //! The output in `state`, recomputed from its memory without the running sums: the reference
  //! formula of the file comment, O(memory). step() returns the same value up to rounding.
  double output(const State& state) const;

  //! Advances one sample and returns y. No allocation, no virtual call; O(1) + O(wiped pairs).
  //! Precondition: `state` comes from this model (or one with the same Everett function) and
  //! `input` is finite.
  double step(State& state, double input) const noexcept {
    HYST_ASSERT(std::isfinite(input), "step() needs a finite input");
    if (input < everett_.lower()) {
      reset(state, false);
      return params_.offset - total_;
    }
    if (input > everett_.upper()) {
      reset(state, true);
      return params_.offset + total_;
    }
    const Plan plan = make_plan(state, input);
    if (plan.push) {
      const std::size_t t = plan.keep;  // index of the new extremum: the previous input
      state.extrema[t] = state.input;
      state.partial[t] = state.partial[t - 1] + pair_term(state, t - 1, state.input);
      state.size = t + 1;
      state.truncations += plan.truncated ? 1 : 0;
    } else {
      state.size = plan.keep;
    }
    state.input = input;
    const std::size_t top = state.size - 1;
    return params_.offset - total_ +
           2.0 * (state.partial[top] +
                  current_term(state.is_minimum(top), state.extrema[top], input));
  }

  //! The output step(state, input) would return, without changing `state` (the numerical inverse
  //! searches with it). Same preconditions as step().
  double preview(const State& state, double input) const noexcept {
    if (input < everett_.lower()) return params_.offset - total_;
    if (input > everett_.upper()) return params_.offset + total_;
    const Plan plan = make_plan(state, input);
    std::size_t top = plan.keep - 1;
    double sum = state.partial[top];
    double top_value = state.extrema[top];
    if (plan.push) {
      top = plan.keep;
      sum = state.partial[top - 1] + pair_term(state, top - 1, state.input);
      top_value = state.input;
    }
    return params_.offset - total_ +
           2.0 * (sum + current_term(state.is_minimum(top), top_value, input));
  }

 private:
  // What a step does to the memory: keep entries [0, keep); if push, the previous input becomes
  // entry `keep` (after the innermost pair was dropped when the memory was full: truncated).
  struct Plan {
    std::size_t keep;
    bool push;
    bool truncated;
  };

  static Plan make_plan(const State& state, double input) noexcept {
    const std::size_t n = state.size;
    if (input == state.input) return {n, false, false};
    const double* x = state.extrema.data();
    std::size_t t = n - 1;
    const bool rising = state.is_minimum(t);
    if (rising ? input < state.input : input > state.input) {
      // Reversal: the previous input becomes a maximum (or minimum) at t + 1, unless the input
      // already passed x_t, which wipes out both at once.
      const bool wiped = rising ? input <= x[t] : input >= x[t];
      if (!wiped) {
        if (n < State::capacity) return {n, true, false};
        return {n - 2, true, true};  // full: drop the innermost pair x_{n-2}, x_{n-1}
      }
      --t;
    }
    // Wiping-out. x_0 = +-inf is never passed, so t stays >= 0.
    if (state.is_minimum(t)) {
      while (t >= 1 && input >= x[t - 1])
        t -= 2;
    } else {
      while (t >= 1 && input <= x[t - 1])
        t -= 2;
    }
    return {t + 1, false, false};
  }

  // T(x_t, next) for the pair from entry t to the next extremum (file comment).
  double pair_term(const State& state, std::size_t t, double next) const noexcept {
    const double from = state.extrema[t];
    return state.is_minimum(t) ? everett_(next, from) : -everett_(from, next);
  }
  // T(x_n, v) for the current branch, with the relay grid's tie rule on falling branches.
  double current_term(bool rising, double from, double input) const noexcept {
    return rising ? everett_(input, from) : everett_.diagonal_tie(input) - everett_(from, input);
  }

  void reset(State& state, bool positive) const noexcept {
    const double infinity = std::numeric_limits<double>::infinity();
    state.size = 1;
    state.extrema[0] = positive ? infinity : -infinity;
    state.partial[0] = positive ? total_ : 0.0;
    state.input = state.extrema[0];
  }

  Params params_;
  Everett everett_;
  double total_;
};

template <EverettFunction Everett>
PreisachState BasicPreisach<Everett>::make_state(PreisachInitialState saturation,
                                                 std::span<const double> memory,
                                                 double input) const {
  if (saturation == PreisachInitialState::demagnetised) {
    throw Error(
        "Preisach state: the history must start at negative_saturation or "
        "positive_saturation (the demagnetised state is a memory of extrema from "
        "negative saturation)");
  }
  if (memory.size() >= State::capacity) {
    throw Error(fmt::format("Preisach state memory has {} extrema; at most {} fit", memory.size(),
                            State::capacity - 1));
  }
  State state;
  reset(state, saturation == PreisachInitialState::positive_saturation);
  const double lo = lower();
  const double hi = upper();
  for (std::size_t k = 0; k < memory.size(); ++k) {
    const double value = memory[k];
    const std::size_t t = k + 1;
    if (!std::isfinite(value) || value < lo || value > hi) {
      throw Error(
          fmt::format("Preisach state memory[{}] = {} must be finite and in the input "
                      "range [{}, {}]",
                      k, value, lo, hi));
    }
    const bool maximum = !state.is_minimum(t);
    const double previous = state.extrema[t - 1];
    if (maximum ? !(value > previous) : !(value < previous)) {
      throw Error(
          fmt::format("Preisach state memory[{}] = {} must be {} the extremum before it "
                      "({}): maxima and minima alternate",
                      k, value, maximum ? "above" : "below", previous));
    }
    if (t >= 2) {
      const double same_kind = state.extrema[t - 2];
      if (maximum ? !(value < same_kind) : !(value > same_kind)) {
        throw Error(fmt::format(
            "Preisach state memory[{}] = {} must be {} the {} before it ({}): "
            "stored maxima decrease and minima increase",
            k, value, maximum ? "below" : "above", maximum ? "maximum" : "minimum", same_kind));
      }
    }
    state.extrema[t] = value;
    state.partial[t] = state.partial[t - 1] + pair_term(state, t - 1, value);
    state.size = t + 1;
  }
  const std::size_t top = state.size - 1;
  if (memory.empty() && input == state.extrema[0]) return state;
  if (!std::isfinite(input) || input < lo || input > hi) {
    throw Error(
        fmt::format("Preisach state input = {} must be finite and in the input range "
                    "[{}, {}] (or equal to x_0 with an empty memory)",
                    input, lo, hi));
  }
  const bool rising = state.is_minimum(top);
  const double from = state.extrema[top];
  const double bound = top >= 1 ? state.extrema[top - 1] : -state.extrema[0];
  if (rising ? !(input >= from && input < bound) : !(input <= from && input > bound)) {
    throw Error(fmt::format(
        "Preisach state input = {} must lie {} the last extremum {} and {} "
        "the one before it ({}), or it would have wiped them out",
        input, rising ? "at or above" : "at or below", from, rising ? "below" : "above", bound));
  }
  state.input = input;
  return state;
}

template <EverettFunction Everett>
double BasicPreisach<Everett>::output(const State& state) const {
  double sum = state.from_positive_saturation() ? total_ : 0.0;
  for (std::size_t t = 1; t < state.size; ++t)
    sum += pair_term(state, t - 1, state.extrema[t]);
  const std::size_t top = state.size - 1;
  return params_.offset - total_ +
         2.0 * (sum + current_term(state.is_minimum(top), state.extrema[top], state.input));
}

using Preisach = BasicPreisach<RelayGridEverett>;
using GaussianPreisach = BasicPreisach<GaussianEverett>;
using LorentzianPreisach = BasicPreisach<LorentzianEverett>;
using TabulatedPreisach = BasicPreisach<TabulatedEverett>;

extern template class BasicPreisach<RelayGridEverett>;
extern template class BasicPreisach<GaussianEverett>;
extern template class BasicPreisach<LorentzianEverett>;
extern template class BasicPreisach<TabulatedEverett>;

}  // namespace hyst
