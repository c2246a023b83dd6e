// C emitter of the discrete Preisach model in its Everett table form and of its numerical
// inverse (preisach.hpp, preisach_state.hpp, everett_relay_grid.hpp, inverse_preisach.hpp,
// bracketed_search.hpp).

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "hyst/inverse/inverse_preisach.hpp"

namespace hyst::detail {
namespace {

constexpr std::string_view kPreisachHeader = R"(#define @_LEVELS %N%
#define @_TABLE_SIZE %TABLE%
/* Memory capacity: at most @_MAX_PAIRS (maximum, minimum) pairs after x_0. A new extremum that
   finds the memory full first drops the innermost stored pair (the two most recent extrema) and
   counts it in `truncations`; the library does exactly the same with the same capacity. */
#define @_MAX_PAIRS %PAIRS%
#define @_CAPACITY (2 * @_MAX_PAIRS + 1)

/* Parameters: the threshold levels c_k [input units], the diagonal relay weights mu_kk, the
   Everett table T[a][c] = sum of mu_ij over c <= j <= i <= a - 1 (at a (N + 1) + c), the input
   range [lower, upper], the offset y_off and the total weight F0 [output units]. */
typedef struct {
  @_real thresholds[@_LEVELS];
  @_real diagonal[@_LEVELS];
  @_real everett[@_TABLE_SIZE];
  @_real inverse_spacing; /* (N - 1) / (c_{N-1} - c_0): first guess of a level index */
  @_real lower;
  @_real upper;
  @_real offset;
  @_real total;
} @_params;

/* State: the staircase memory x_0 = -+inf, x_1, ... of alternating dominant extrema, the running
   sums of the Everett terms up to each, the number of entries in use and the last input. */
typedef struct {
  @_real extrema[@_CAPACITY];
  @_real partial[@_CAPACITY];
  unsigned int size;
  @_real input;
  unsigned long truncations;
} @_state;
%MODEL_DECLARATIONS%
/* Inverse parameters: the model, the admissible input range, the search tolerances and the
   most search steps per sample. */
typedef struct {
  const @_params *model;
  @_real input_min;
  @_real input_max;
  @_real tolerance;        /* bracket width that ends the search [input units] */
  @_real output_tolerance; /* |y - target| that ends it [output units] */
  unsigned int max_iterations;
} @_inverse_params;

/* The inverse's state is the model's state. */
typedef @_state @_inverse_state;
%INVERSE_DECLARATIONS%)";

constexpr std::string_view kModelFunctions = R"(
/* A level index near u for c_0 < u < c_{N-1}; the callers correct it by single steps. */
static unsigned int @_guess(const @_params *params, @_real u) {
  const @_real g = (u - params->thresholds[0]) * params->inverse_spacing;
  const unsigned int k = (unsigned int)(g > #(0.0) ? g : #(0.0));
  return k < @_LEVELS - 1 ? k : @_LEVELS - 2;
}

/* #{k : c_k <= u}. The corrections stop inside the table since c_0 <= u < c_{N-1}. */
static unsigned int @_count_at_or_below(const @_params *params, @_real u) {
  const @_real *c = params->thresholds;
  unsigned int k;
  if (!(u >= c[0])) return 0;
  if (u >= c[@_LEVELS - 1]) return @_LEVELS;
  k = @_guess(params, u);
  while (c[k + 1] <= u) ++k;
  while (c[k] > u) --k;
  return k + 1;
}

/* #{k : c_k < u}. */
static unsigned int @_count_below(const @_params *params, @_real u) {
  const @_real *c = params->thresholds;
  unsigned int k;
  if (!(u > c[0])) return 0;
  if (u > c[@_LEVELS - 1]) return @_LEVELS;
  k = @_guess(params, u);
  while (c[k + 1] < u) ++k;
  while (c[k] >= u) --k;
  return k + 1;
}

/* The Everett function E(alpha, beta): one table read. */
static @_real @_everett(const @_params *params, @_real alpha, @_real beta) {
  return params->everett[@_count_at_or_below(params, alpha) * (@_LEVELS + 1) +
                         @_count_below(params, beta)];
}

/* mu_kk if u equals a level c_k exactly (that diagonal relay stays at +1), else 0. */
static @_real @_diagonal_tie(const @_params *params, @_real u) {
  const unsigned int k = @_count_below(params, u);
  return k < @_LEVELS && params->thresholds[k] == u ? params->diagonal[k] : #(0.0);
}

/* True if entry t of the memory is a minimum (the input rises from it). */
static int @_is_minimum(const @_state *state, unsigned int t) {
  return ((t & 1U) == 0) == (state->extrema[0] < #(0.0));
}

/* The Everett term of the pair from entry t to the next extremum. */
static @_real @_pair_term(const @_params *params, const @_state *state, unsigned int t,
                          @_real next) {
  const @_real from = state->extrema[t];
  return @_is_minimum(state, t) ? @_everett(params, next, from) : -@_everett(params, from, next);
}

/* The term of the current branch, with the relay grid's tie rule on falling branches. */
static @_real @_current_term(const @_params *params, int rising, @_real from, @_real input) {
  return rising ? @_everett(params, input, from)
                : @_diagonal_tie(params, input) - @_everett(params, from, input);
}

/* Negative (positive = 0) or positive saturation: every relay at -1 or +1. */
static void @_saturate(const @_params *params, @_state *state, int positive) {
  state->size = 1;
  state->extrema[0] = positive ? HUGE_VAL%F% : -HUGE_VAL%F%;
  state->partial[0] = positive ? params->total : #(0.0);
  state->input = state->extrema[0];
}

/* What a step does to the memory: keep entries [0, keep); if push, the previous input becomes
   entry `keep` (after the innermost pair was dropped when the memory was full: truncated). */
typedef struct {
  unsigned int keep;
  int push;
  int truncated;
} @_plan;

static @_plan @_make_plan(const @_state *state, @_real input) {
  const unsigned int n = state->size;
  const @_real *x = state->extrema;
  unsigned int t = n - 1;
  @_plan plan;
  plan.keep = n;
  plan.push = 0;
  plan.truncated = 0;
  if (input == state->input) return plan;
  {
    const int rising = @_is_minimum(state, t);
    if (rising ? input < state->input : input > state->input) {
      /* A reversal: the previous input becomes an extremum, unless the input already passed
         x_t, which wipes out both. */
      const int wiped = rising ? input <= x[t] : input >= x[t];
      if (!wiped) {
        plan.push = 1;
        if (n < @_CAPACITY) return plan;
        plan.keep = n - 2;
        plan.truncated = 1;
        return plan;
      }
      --t;
    }
  }
  /* Wiping-out, one pair per pass; x_0 = -+inf is never passed, so at most size / 2 passes. */
  if (@_is_minimum(state, t)) {
    while (t >= 1 && input >= x[t - 1]) t -= 2;
  } else {
    while (t >= 1 && input <= x[t - 1]) t -= 2;
  }
  plan.keep = t + 1;
  return plan;
}

/* The output step() would return, without changing the state. */
static @_real @_preview(const @_params *restrict params, const @_state *restrict state,
                        @_real input) {
  @_plan plan;
  unsigned int top;
  @_real sum;
  @_real top_value;
  if (input < params->lower) return params->offset - params->total;
  if (input > params->upper) return params->offset + params->total;
  plan = @_make_plan(state, input);
  top = plan.keep - 1;
  sum = state->partial[top];
  top_value = state->extrema[top];
  if (plan.push) {
    top = plan.keep;
    sum = state->partial[top - 1] + @_pair_term(params, state, top - 1, state->input);
    top_value = state->input;
  }
  return params->offset - params->total +
         #(2.0) * (sum + @_current_term(params, @_is_minimum(state, top), top_value, input));
}

@_real @_step(const @_params *restrict params, @_state *restrict state, @_real input) {
  @_plan plan;
  unsigned int top;
  if (input < params->lower) {
    @_saturate(params, state, 0);
    return params->offset - params->total;
  }
  if (input > params->upper) {
    @_saturate(params, state, 1);
    return params->offset + params->total;
  }
  plan = @_make_plan(state, input);
  if (plan.push) {
    const unsigned int t = plan.keep;
    state->extrema[t] = state->input;
    state->partial[t] = state->partial[t - 1] + @_pair_term(params, state, t - 1, state->input);
    state->size = t + 1;
    state->truncations += plan.truncated ? 1U : 0U;
  } else {
    state->size = plan.keep;
  }
  state->input = input;
  top = state->size - 1;
  return params->offset - params->total +
         #(2.0) * (state->partial[top] +
                   @_current_term(params, @_is_minimum(state, top), state->extrema[top], input));
}

/* Copies an exported memory into a state. */
static void @_load(@_state *state, const @_real *extrema, const @_real *partial,
                   unsigned int size, @_real input) {
  unsigned int t;
  for (t = 0; t < size; ++t) {
    state->extrema[t] = extrema[t];
    state->partial[t] = partial[t];
  }
  state->size = size;
  state->input = input;
  state->truncations = 0;
}

void @_init(@_state *state) {
  @_load(state, @_INIT_EXTREMA, @_INIT_PARTIAL, @_INIT_SIZE, @_INIT_INPUT);
}

void @_reset(@_state *state) {
  @_load(state, @_RESET_EXTREMA, @_RESET_PARTIAL, @_RESET_SIZE, @_RESET_INPUT);
}

void @_inverse_init(@_inverse_state *state) { @_init(state); }

void @_inverse_reset(@_inverse_state *state) { @_reset(state); }

/* The input in [input_min, input_max] whose one-step-ahead output is nearest the target
   (the library's bracketed_search). */
static @_real @_search(const @_inverse_params *search, const @_state *state, @_real target) {
  const @_params *params = search->model;
  @_real lo = search->input_min;
  @_real hi = search->input_max;
  @_real now = state->input < lo ? lo : (hi < state->input ? hi : state->input);
  const @_real y_now = @_preview(params, state, now);
  @_real y_lo = #(0.0);
  @_real y_hi = #(0.0);
  @_real a, fa, b, fb, c, fc, t, checkpoint;
  int since_checkpoint = 0;
  unsigned int k;
  if (y_now == target) return now;
  if (target > y_now) {
    lo = now;
    y_lo = y_now;
    y_hi = @_preview(params, state, hi);
    if (y_hi < target) return hi;
  } else {
    hi = now;
    y_hi = y_now;
    y_lo = @_preview(params, state, lo);
    if (y_lo > target) return lo;
  }
  /* a: newest end, b: the other end (opposite signs of y - target), c: the end dropped last. */
  a = hi;
  fa = y_hi - target;
  b = lo;
  fb = y_lo - target;
  c = a;
  fc = fa;
  t = fa / (fa - fb);
  checkpoint = hi - lo;
  for (k = 0; k < search->max_iterations; ++k) {
    @_real u, fu, width, xi, phi, margin;
    if (since_checkpoint >= 3) t = #(0.5);
    u = a + t * (b - a);
    if (!(u > (b < a ? b : a) && u < (a < b ? b : a))) break; /* no value left between */
    fu = @_preview(params, state, u) - target;
    if (fu == #(0.0) || $fabs(fu) <= search->output_tolerance) return u;
    if ((fu < #(0.0)) == (fa < #(0.0))) {
      c = a;
      fc = fa;
    } else {
      c = b;
      fc = fb;
      b = a;
      fb = fa;
    }
    a = u;
    fa = fu;
    width = $fabs(b - a);
    if (width <= search->tolerance) break;
    if (width <= #(0.5) * checkpoint) {
      checkpoint = width;
      since_checkpoint = 0;
    } else {
      ++since_checkpoint;
    }
    /* Inverse quadratic interpolation where it is safe (Chandrupatla 1997), else bisection. */
    t = #(0.5);
    xi = (a - b) / (c - b);
    phi = (fa - fb) / (fc - fb);
    if (phi * phi < xi && (#(1.0) - phi) * (#(1.0) - phi) < #(1.0) - xi) {
      t = fa / (fb - fa) * fc / (fb - fc) + (c - a) / (b - a) * fa / (fc - fa) * fb / (fc - fb);
    }
    margin = #(0.5) * search->tolerance / width;
    t = t < margin ? margin : ((#(1.0) - margin) < t ? #(1.0) - margin : t);
  }
  lo = b < a ? b : a;
  hi = a < b ? b : a;
  y_lo = target + (a < b ? fa : fb);
  y_hi = target + (a < b ? fb : fa);
  return target - y_lo <= y_hi - target ? lo : hi;
}

@_real @_inverse_step(const @_inverse_params *params, @_inverse_state *state, @_real target) {
  const @_real input = @_search(params, state, target);
  @_step(params->model, state, input);
  return input;
}
)";

std::string memory_tables(const CWriter& writer, std::string_view name,
                          const PreisachState& state) {
  const std::vector<double> extrema(state.extrema.begin(), state.extrema.begin() + state.size);
  const std::vector<double> partial(state.partial.begin(), state.partial.begin() + state.size);
  return CWriter::fill(
      "static const @_real @_%NAME%_EXTREMA[%SIZE%] = %X%;\n"
      "static const @_real @_%NAME%_PARTIAL[%SIZE%] = %S%;\n"
      "#define @_%NAME%_SIZE %SIZE%U\n"
      "#define @_%NAME%_INPUT %INPUT%\n",
      {{"NAME", std::string(name)},
       {"SIZE", std::to_string(state.size)},
       {"X", writer.table(extrema)},
       {"S", writer.table(partial)},
       {"INPUT", fmt::format("({})", writer.number(state.input))}});
}

// The state rebuilt from what a model file stores of it (the saturation, the memory, the last
// input or none), as loading that file would: the exported tables are those of the model file.
PreisachState state_as_in_file(const Preisach& preisach, const PreisachState& state) {
  const auto saturation = state.from_positive_saturation()
                              ? PreisachInitialState::positive_saturation
                              : PreisachInitialState::negative_saturation;
  double input = saturation == PreisachInitialState::positive_saturation
                     ? std::numeric_limits<double>::infinity()
                     : -std::numeric_limits<double>::infinity();
  if (std::isfinite(state.input)) input = state.input;
  return preisach.make_state(saturation, state.memory(), input);
}

}  // namespace

CModelCode emit_c(const Preisach& preisach, const PreisachState& state, const CWriter& writer,
                  const CExportOptions& options) {
  InversePreisachOptions inverse_options;
  if (std::isfinite(options.limits.input_min)) inverse_options.input_min = options.limits.input_min;
  if (std::isfinite(options.limits.input_max)) inverse_options.input_max = options.limits.input_max;
  const InversePreisach inverse(preisach, inverse_options);
  const auto& everett = preisach.everett();
  const std::size_t n = everett.levels();
  const auto levels = everett.thresholds();
  const double infinity = std::numeric_limits<double>::infinity();

  // T[a][c] = E(c_{a-1}, c_c) with c_{-1} = -inf and c_N = +inf: the library's own table.
  std::vector<double> table((n + 1) * (n + 1));
  std::vector<double> diagonal(n);
  for (std::size_t a = 0; a <= n; ++a) {
    for (std::size_t c = 0; c <= n; ++c) {
      table[a * (n + 1) + c] =
          everett(a == 0 ? -infinity : levels[a - 1], c == n ? infinity : levels[c]);
    }
  }
  for (std::size_t k = 0; k < n; ++k)
    diagonal[k] = everett.diagonal_tie(levels[k]);
  const double inverse_spacing =
      n > 1 ? static_cast<double>(n - 1) / (levels[n - 1] - levels[0]) : 0.0;

  CModelCode code;
  code.title = fmt::format("Preisach model (preisach), {} levels, {} relays, Everett table form", n,
                           everett.params().weights.size());
  code.description =
      " *     y = y_off - F0 + 2 (sum of the Everett terms of the staircase memory)\n"
      " * (include/hyst/models/preisach.hpp; relay grid: everett_relay_grid.hpp). Inverse: the\n"
      " * numerical inverse by bracketed search on the monotone one-step-ahead output\n"
      " * (include/hyst/inverse/inverse_preisach.hpp, bracketed_search.hpp).\n";
  code.has_inverse = true;
  // The Everett table is the model's weight distribution in the form the step uses; the level
  // spacing only speeds up the level search and stays as exported.
  code.parameters = {
      c_array("thresholds", levels, CUnit::input, "threshold levels c_k", CRule::increasing),
      c_array("diagonal", diagonal, CUnit::output, "diagonal relay weights mu_kk"),
      c_array("everett", table, CUnit::output, "Everett table T[a][c] at a (N + 1) + c"),
      c_scalar("lower", everett.lower(), CUnit::input, "lowest input of the relay grid",
               CRule::lower_limit),
      c_scalar("upper", everett.upper(), CUnit::input, "highest input of the relay grid"),
      c_scalar("offset", preisach.params().offset, CUnit::output, "output offset y_off"),
      c_scalar("total", preisach.total_weight(), CUnit::output, "total relay weight F0")};
  code.inverse_parameters = {c_scalar("input_min", inverse.input_min(), CUnit::input,
                                      "lowest input returned", CRule::lower_limit),
                             c_scalar("input_max", inverse.input_max(), CUnit::input,
                                      "highest input returned", CRule::upper_limit),
                             c_scalar("tolerance", inverse.input_tolerance(), CUnit::input,
                                      "bracket width that ends the search", CRule::nonnegative),
                             c_scalar("output_tolerance", 0.0, CUnit::output,
                                      "|y - target| that ends the search", CRule::nonnegative)};
  // The memory: 1 ... capacity entries, x_0 = -+inf, the later extrema and every running sum
  // finite (the last input may be -+inf after a saturation).
  code.state_check = code.inverse_state_check =
      "s->size >= 1u && s->size <= @_CAPACITY && isinf(s->extrema[0]) && "
      "fmu_finite(s->extrema + 1, s->size - 1u) && fmu_finite(s->partial, s->size) && "
      "s->input == s->input";
  code.header = CWriter::fill(
      kPreisachHeader,
      {{"N", std::to_string(n)},
       {"TABLE", std::to_string(table.size())},
       {"PAIRS", std::to_string(PreisachState::max_pairs)},
       {"MODEL_DECLARATIONS",
        c_model_declarations(to_string(preisach.params().initial_state),
                             "updates the memory and returns y; O(1) + O(wiped pairs).")},
       {"INVERSE_DECLARATIONS",
        c_inverse_declarations(" (bracketed search on the model's output one step "
                               "ahead, Chandrupatla's method)")}});
  code.source = fmt::format(
      "const @_params @_PARAMS = {{\n    {},\n    {},\n    {},\n    {}, {}, {}, {}, {}}};\n\n",
      writer.table(levels), writer.table(diagonal), writer.table(table),
      writer.number(inverse_spacing), writer.number(everett.lower()),
      writer.number(everett.upper()), writer.number(preisach.params().offset),
      writer.number(preisach.total_weight()));
  code.source += fmt::format(
      "const @_inverse_params @_INVERSE_PARAMS = {{\n    &@_PARAMS, {}, {}, {}, {}, {}u}};\n\n",
      writer.number(inverse.input_min()), writer.number(inverse.input_max()),
      writer.number(inverse.input_tolerance()), writer.number(0.0), inverse.max_iterations());
  code.source +=
      "/* The state stored in the model file (INIT) and the default initial state (RESET). */\n";
  code.source += memory_tables(writer, "INIT", state_as_in_file(preisach, state));
  code.source += memory_tables(writer, "RESET", preisach.initial_state());
  code.source += CWriter::fill(kModelFunctions, {{"F", writer.single() ? "F" : ""}});
  return code;
}

}  // namespace hyst::detail
