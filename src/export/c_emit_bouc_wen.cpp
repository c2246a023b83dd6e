// C emitter of the Bouc-Wen model (bouc_wen.hpp): the exact solution for n = 1, the fixed-step
// RK4 rule for n != 1. The adaptive Dormand-Prince path (tolerance > 0) is not exported.

#include <string>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "hyst/core/error.hpp"

namespace hyst::detail {
namespace {

constexpr std::string_view kBoucWenHeader =
    R"(/* Parameters (standard form): A, beta, gamma, exponent n, stiffness k, alpha_k. */
typedef struct {
  @_real a;
  @_real beta;
  @_real gamma;
  @_real n;
  @_real stiffness;
  @_real alpha_k;
%RK4_FIELDS%} @_params;

/* State: the previous input x and the hysteretic variable z. */
typedef struct {
  @_real input;
  @_real z;
} @_state;
)";

constexpr std::string_view kRk4Fields =
    R"(  unsigned int substeps; /* fewest RK4 steps per sample */
  @_real max_input_step; /* longest RK4 step in x [input units] */
)";

constexpr std::string_view kExactAdvance =
    R"(/* z after an input change dx, exactly (n = 1): while z keeps its sign, dz/du = s A - c z in
   u = |x - x_start|; at most two pieces, since z crosses 0 at most once (the library's
   bouc_wen_exact_advance). */
static @_real @_advance(const @_params *params, @_real z, @_real dx) {
  const @_real s = dx > #(0.0) ? #(1.0) : #(-1.0);
  @_real remaining = $fabs(dx);
  int piece;
  for (piece = 0; piece < 2 && remaining > #(0.0); ++piece) {
    const @_real z_sign = z > #(0.0) ? #(1.0) : (z < #(0.0) ? #(-1.0) : s);
    const @_real c = params->beta + s * z_sign * params->gamma;
    const @_real slope_at_zero = s * params->a;
    const int crosses = z * s < #(0.0);
    @_real crossing = remaining;
    if (crosses) {
      crossing = c > #(0.0) ? $log1p(-z * c / slope_at_zero) / c : -z / slope_at_zero;
    }
    if (!crosses || crossing >= remaining) {
      if (c > #(0.0)) {
        const @_real equilibrium = slope_at_zero / c;
        return z - (equilibrium - z) * $expm1(-c * remaining);
      }
      return z + slope_at_zero * remaining;
    }
    z = #(0.0);
    remaining -= crossing;
  }
  return z;
}

)";

constexpr std::string_view kRk4Advance =
    R"(/* dz/dx = A - beta s |z|^(n-1) z - gamma |z|^n, s = sign(dx). */
static @_real @_rate(const @_params *params, @_real s, @_real z) {
  const @_real abs_z = $fabs(z);
  @_real power;
  if (abs_z == #(0.0)) return params->a;
  power = $pow(abs_z, params->n);
  return params->a - s * params->beta * (z < #(0.0) ? -power : power) - params->gamma * power;
}

/* z after an input change dx by classical RK4 with max(substeps, ceil(|dx| / max_input_step))
   equal steps, at most @_MAX_SUBSTEPS (the library's bouc_wen_advance with substeps_for). */
static @_real @_advance(const @_params *params, @_real z, @_real dx) {
  const @_real s = dx > #(0.0) ? #(1.0) : #(-1.0);
  const @_real needed = $ceil($fabs(dx) / params->max_input_step);
  unsigned long steps = params->substeps;
  unsigned long i;
  @_real h;
  if (needed > (@_real)steps) {
    steps = needed > (@_real)@_MAX_SUBSTEPS ? @_MAX_SUBSTEPS : (unsigned long)needed;
  }
  h = dx / (@_real)steps;
  for (i = 0; i < steps; ++i) {
    const @_real k1 = @_rate(params, s, z);
    const @_real k2 = @_rate(params, s, z + (#(0.5) * h) * k1);
    const @_real k3 = @_rate(params, s, z + (#(0.5) * h) * k2);
    const @_real k4 = @_rate(params, s, z + h * k3);
    z += (h / #(6.0)) * (k1 + #(2.0) * k2 + #(2.0) * k3 + k4);
  }
  return z;
}

)";

constexpr std::string_view kBoucWenFunctions = R"(void @_init(@_state *state) {
  state->input = %INPUT%;
  state->z = %Z%;
}

void @_reset(@_state *state) {
  state->input = #(0.0);
  state->z = #(0.0);
}

@_real @_step(const @_params *params, @_state *state, @_real input) {
  const @_real dx = input - state->input;
  if (dx != #(0.0)) {
    state->z = @_advance(params, state->z, dx);
    state->input = input;
  }
  return params->alpha_k * params->stiffness * state->input +
         (#(1.0) - params->alpha_k) * params->stiffness * state->z;
}
)";

}  // namespace

CModelCode emit_c(const BoucWen& bouc_wen, const BoucWen::State& state, const CWriter& writer,
                  const CExportOptions&) {
  const auto& p = bouc_wen.params();
  const bool exact = p.n == 1.0;
  if (!exact && p.tolerance > 0.0) {
    throw Error(fmt::format("C export: the Bouc-Wen model with n = {} integrates adaptively "
                            "(tolerance = {}), which the export does not reproduce; set "
                            "tolerance = 0 to use the fixed-step RK4 rule",
                            p.n, p.tolerance),
                "tolerance");
  }
  // The library's step bound: max_input_step, or z0 / (4 n A) when that is 0.
  const double max_step =
      p.max_input_step > 0.0 ? p.max_input_step : bouc_wen.z_bound() / (4.0 * p.n * p.a);
  CModelCode code;
  code.title = fmt::format("Bouc-Wen model (bouc_wen), n = {}", p.n);
  code.description = fmt::format(
      " *     F = alpha_k k x + (1 - alpha_k) k z,\n"
      " *     dz/dx = A - beta sign(dx) |z|^(n-1) z - gamma |z|^n   (integrated in the input)\n"
      " * (include/hyst/models/bouc_wen.hpp). Scheme: {}. No inverse is exported.\n",
      exact ? "the exact solution for n = 1 (any sample spacing)"
            : fmt::format("classical RK4 with max({}, ceil(|dx| / {})) equal steps per sample, "
                          "at most 1000000",
                          p.substeps, writer.number(max_step)));
  code.parameters = {
      c_scalar("a", p.a, CUnit::none, "A, the slope of z at z = 0", CRule::positive),
      c_scalar("beta", p.beta, CUnit::none, "beta"),
      c_scalar("gamma", p.gamma, CUnit::none, "gamma", CRule::within_previous),
      c_scalar("stiffness", p.stiffness, CUnit::output_per_input, "stiffness k", CRule::positive),
      c_scalar("alpha_k", p.alpha_k, CUnit::none, "ratio alpha_k of the linear part",
               CRule::unit_interval)};
  // The exact scheme holds for n = 1 alone: n is a parameter of the RK4 rule only.
  if (!exact) {
    code.parameters.push_back(c_scalar("n", p.n, CUnit::none, "exponent n", CRule::at_least_one));
  }
  code.state_check = "fmu_finite(&s->input, 1) && fmu_finite(&s->z, 1)";
  code.header =
      CWriter::fill(kBoucWenHeader, {{"RK4_FIELDS", exact ? "" : std::string(kRk4Fields)}}) +
      c_model_declarations("x = 0, z = 0",
                           "input linear between samples; advances z and returns F.");
  const std::string rk4_values =
      exact ? "" : fmt::format(",\n    {}u, {}", p.substeps, writer.number(max_step));
  code.source = (exact ? std::string(kExactAdvance)
                       : "#define @_MAX_SUBSTEPS 1000000UL\n\n" + std::string(kRk4Advance)) +
                fmt::format("const @_params @_PARAMS = {{\n    {}, {}, {}, {}, {}, {}{}}};\n\n",
                            writer.number(p.a), writer.number(p.beta), writer.number(p.gamma),
                            writer.number(p.n), writer.number(p.stiffness),
                            writer.number(p.alpha_k), rk4_values) +
                CWriter::fill(kBoucWenFunctions, {{"INPUT", writer.number(state.input)},
                                                  {"Z", writer.number(state.hysteretic)}});
  return code;
}

}  // namespace hyst::detail
