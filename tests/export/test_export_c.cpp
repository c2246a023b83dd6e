// The exported C code against the library: every supported model (and its inverse) is exported,
// compiled with gcc -std=c99 -Wall -Wextra -Werror -pedantic (plain and -DNDEBUG -O2), run on
// seeded inputs, and its outputs compared with the library's simulate/invert from the same
// states: to 1e-12 (relative to the output scale) in double, within a stated bound in float.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/shell_command.hpp"
#include "../support/temp_folder_test.hpp"
#include "../support/test_signals.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/models/preisach.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

std::vector<double> numbers_in(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> values;
  std::string token;
  while (in >> token)
    values.push_back(std::stod(token));
  return values;
}

// The driver: reads n inputs and n targets, runs the model from init() and from reset() and the
// inverse (if any) from inverse_init() and inverse_reset(), printing every value with %.17g.
std::string driver(const std::string& prefix, bool has_inverse) {
  std::string text = fmt::format(R"(#include <stdio.h>
#include "{0}.h"
#define COUNT 4000
static double input[COUNT];
static double target[COUNT];
int main(void) {{
  int n = 0, k;
  {0}_state state;
  FILE *file = fopen("data.txt", "r");
  if (!file) return 2;
  while (n < COUNT && fscanf(file, "%lf %lf", &input[n], &target[n]) == 2) ++n;
  fclose(file);
  {0}_init(&state);
  for (k = 0; k < n; ++k) printf("%.17g\n", (double){0}_step(&{0}_PARAMS, &state, ({0}_real)input[k]));
  {0}_reset(&state);
  for (k = 0; k < n; ++k) printf("%.17g\n", (double){0}_step(&{0}_PARAMS, &state, ({0}_real)input[k]));
)",
                                 prefix);
  if (has_inverse) {
    text += fmt::format(R"(  {{
    {0}_inverse_state inverse;
    {0}_inverse_init(&inverse);
    for (k = 0; k < n; ++k)
      printf("%.17g\n", (double){0}_inverse_step(&{0}_INVERSE_PARAMS, &inverse, ({0}_real)target[k]));
    {0}_inverse_reset(&inverse);
    for (k = 0; k < n; ++k)
      printf("%.17g\n", (double){0}_inverse_step(&{0}_INVERSE_PARAMS, &inverse, ({0}_real)target[k]));
  }}
)",
                        prefix);
  }
  return text + "  return 0;\n}\n";
}

struct Case {
  nlohmann::json document;  // model file
  double low = -1.0;        // input range of the test signal
  double high = 1.0;
  std::size_t warm_up = 300;  // library samples before the export: a state that is not the default
  std::vector<double> input{};  // the test input and the source of the targets; empty = seeded
};

class ExportCTest : public test::TempFolderTest {
 protected:
  // The library's outputs in the order the driver prints them.
  static std::vector<double> library_run(const DynamicModel& exported, bool has_inverse,
                                         const InverseLimits& limits,
                                         const std::vector<double>& input,
                                         const std::vector<double>& target) {
    std::vector<double> all;
    std::vector<double> out(input.size());
    auto model = exported.clone();
    model->simulate(input, out);
    all.insert(all.end(), out.begin(), out.end());
    model = exported.clone();
    model->reset();
    model->simulate(input, out);
    all.insert(all.end(), out.begin(), out.end());
    if (has_inverse) {
      exported.inverse(limits)->invert(target, out);
      all.insert(all.end(), out.begin(), out.end());
      model = exported.clone();
      model->reset();
      model->inverse(limits)->invert(target, out);
      all.insert(all.end(), out.begin(), out.end());
    }
    return all;
  }

  // Exports, compiles with `flags`, runs; returns the C outputs and the library's.
  void compare(const Case& c, CScalar scalar, const std::string& flags, double tolerance,
               const InverseLimits& limits = {}) {
    auto model = model_from_json(c.document, "test");
    const auto warm = test::seeded_input(7, c.low, c.high, c.warm_up, 0.02);
    std::vector<double> ignored(warm.size());
    model->simulate(warm, ignored);  // the exported state is this one, not the default

    const auto input =
        c.input.empty() ? test::seeded_input(11, c.low, c.high, 3000, 0.02) : c.input;
    // Reachable targets: the library's own output for another input.
    std::vector<double> target(input.size());
    model->clone()->simulate(
        c.input.empty() ? test::seeded_input(13, c.low, c.high, input.size(), 0.02) : c.input,
        target);

    CExportOptions options;
    options.prefix = "exported";
    options.scalar = scalar;
    options.limits = limits;
    options.source = "test.json";
    const CCode code = export_c(*model, dir_, options);
    {
      std::ofstream data(dir_ / "data.txt");
      for (std::size_t k = 0; k < input.size(); ++k)
        data << fmt::format("{:.17g} {:.17g}\n", input[k], target[k]);
      std::ofstream(dir_ / "driver.c") << driver("exported", code.has_inverse);
    }
    const std::string compile = fmt::format(
        "cd '{}' && gcc -std=c99 -Wall -Wextra -Werror -pedantic {} -o driver driver.c exported.c "
        "-lm 2>&1",
        dir_.string(), flags);
    std::string log;
    ASSERT_EQ(test::run_command(compile, &log), 0) << compile << "\n" << log;
    std::string printed;
    ASSERT_EQ(test::run_command(fmt::format("cd '{}' && ./driver", dir_.string()), &printed), 0);
    const auto from_c = numbers_in(printed);
    const auto from_library = library_run(*model, code.has_inverse, limits, input, target);
    ASSERT_EQ(from_c.size(), from_library.size());
    double scale = 1.0;
    for (const double y : from_library)
      scale = std::max(scale, std::abs(y));
    double worst = 0.0;
    std::size_t worst_at = 0;
    for (std::size_t k = 0; k < from_c.size(); ++k) {
      const double error = std::abs(from_c[k] - from_library[k]);
      if (error > worst) {
        worst = error;
        worst_at = k;
      }
    }
    EXPECT_LE(worst, tolerance * scale)
        << "sample " << worst_at << " (run " << worst_at / input.size() << "): C "
        << from_c[worst_at] << " library " << from_library[worst_at];
    last_worst_ = worst / scale;
    std::printf("[ worst    ] %s %s %s: %.3g of scale %.3g over %zu values\n",
                c.document.at("model").get<std::string>().c_str(),
                scalar == CScalar::single_precision ? "float" : "double", flags.c_str(),
                worst / scale, scale, from_c.size());
  }

  // Exports and compiles to an object file; returns its undefined symbols (nm -u).
  std::set<std::string> undefined_symbols(const Case& c, CScalar scalar) {
    auto model = model_from_json(c.document, "test");
    CExportOptions options;
    options.prefix = "exported";
    options.scalar = scalar;
    export_c(*model, dir_, options);
    const std::string compile = fmt::format(
        "cd '{}' && gcc -std=c99 -Wall -Wextra -Werror -pedantic -DNDEBUG -O2 -c exported.c 2>&1",
        dir_.string());
    std::string log;
    EXPECT_EQ(test::run_command(compile, &log), 0) << log;
    std::string listing;
    EXPECT_EQ(
        test::run_command(fmt::format("nm -u '{}'", (dir_ / "exported.o").string()), &listing), 0);
    std::set<std::string> symbols;
    std::istringstream in(listing);
    std::string kind;
    std::string name;
    while (in >> kind >> name)
      symbols.insert(name);
    return symbols;
  }

  void check_everything(const Case& c, double float_bound, const InverseLimits& limits = {}) {
    compare(c, CScalar::double_precision, "", 1e-12, limits);
    compare(c, CScalar::double_precision, "-DNDEBUG -O2", 1e-12, limits);
    compare(c, CScalar::single_precision, "-DNDEBUG -O2", float_bound, limits);
    // Only math.h functions (and nothing from the heap).
    const std::set<std::string> math = {"exp",    "expf", "log1p", "log1pf",   "expm1",
                                        "expm1f", "pow",  "powf",  "atanh",    "atanhf",
                                        "tan",    "tanf", "atan",  "atanf",    "ceil",
                                        "ceilf",  "fabs", "fabsf", "copysign", "copysignf"};
    for (const auto scalar : {CScalar::double_precision, CScalar::single_precision}) {
      for (const auto& symbol : undefined_symbols(c, scalar)) {
        EXPECT_TRUE(math.count(symbol) == 1) << "the object code references " << symbol;
        EXPECT_NE(symbol, "malloc");
        EXPECT_NE(symbol, "free");
      }
    }
  }

  double last_worst_ = 0.0;
};

nlohmann::json model_document(std::string_view name, nlohmann::json params) {
  return {{"model", name}, {"version", 1}, {"params", std::move(params)}};
}

// The relay-grid parameters of a Preisach model document.
Preisach::Params preisach_params_of(const nlohmann::json& document) {
  const auto& p = document.at("params");
  Preisach::Params params;
  params.everett.levels = p.at("levels").get<std::size_t>();
  params.everett.lower = p.at("lower").get<double>();
  params.everett.upper = p.at("upper").get<double>();
  params.everett.weights = p.at("weights").get<std::vector<double>>();
  return params;
}

nlohmann::json example_document(std::string_view name) {
  return model_document(name, ModelRegistry::builtin().find(name).example_params);
}

// Float bounds, relative to the largest output magnitude of the run (>= 1): single precision has
// a 6e-8 unit roundoff; the bounds leave room for the sums over the operators and for the
// inverses, which amplify it where the model is flat.
constexpr double kFloatBound = 2e-5;

TEST_F(ExportCTest, PrandtlIshlinskiiAndItsInverse) {
  Case c{model_document("pi", {{"thresholds", {0.0, 0.15, 0.3, 0.45, 0.6, 0.75}},
                               {"weights", {1.1, 0.4, 0.3, -0.2, 0.25, 0.1}},
                               {"offset", 0.35}})};
  check_everything(c, kFloatBound);
}

TEST_F(ExportCTest, TheFittedDomainCountsInputsAndTargetsBeyondIt) {
  // Fitted on inputs [-1, 1] and outputs [0, 4]: widened by 5 % of the widths, [-1.1, 1.1] and
  // [-0.2, 4.2]. The same samples through the library's checks give the same counts.
  const auto model = model_from_json(
      model_document("pi", {{"thresholds", {0.0, 0.2}}, {"weights", {0.9, 0.5}}, {"offset", 0.0}}),
      "test");
  FittedDomain domain;
  domain.input_min = -1.0;
  domain.input_max = 1.0;
  domain.output_min = 0.0;
  domain.output_max = 4.0;
  CExportOptions options;
  options.prefix = "ranged";
  options.domain = domain;
  const CCode code = export_c(*model, dir_, options);
  ASSERT_TRUE(code.has_inverse);
  EXPECT_NE(code.header.find("int ranged_check_input("), std::string::npos);
  std::ofstream(dir_ / "ranged_driver.c") << R"(#include <math.h>
#include <stdio.h>
#include "ranged.h"
int main(void) {
  const double inputs[] = {0.0, 1.05, 1.2, -1.3, NAN, 0.5};
  const double targets[] = {4.1, 4.3, -0.1, -0.25};
  ranged_domain_status status;
  unsigned int k;
  ranged_domain_status_reset(&status);
  for (k = 0; k < 6; ++k) printf("%d ", ranged_check_input(&ranged_DOMAIN, &status, inputs[k]));
  printf("%lu %lu %lu\n", status.samples, status.outside, status.first_outside);
  ranged_domain_status_reset(&status);
  for (k = 0; k < 4; ++k) printf("%d ", ranged_check_target(&ranged_DOMAIN, &status, targets[k]));
  printf("%lu %lu %lu %d\n", status.samples, status.outside, status.first_outside,
         ranged_check_input(&ranged_DOMAIN, NULL, 2.0));
  return 0;
}
)";
  std::string log;
  ASSERT_EQ(test::run_command(
                fmt::format("cd '{}' && gcc -std=c99 -Wall -Wextra -Werror -pedantic -o ranged "
                            "ranged_driver.c ranged.c -lm 2>&1",
                            dir_.string()),
                &log),
            0)
      << log;
  std::string printed;
  ASSERT_EQ(test::run_command(fmt::format("cd '{}' && ./ranged", dir_.string()), &printed), 0);
  EXPECT_EQ(printed, "1 1 0 0 0 1 6 3 2\n1 0 1 0 4 2 1 0\n");
  const std::vector<double> inputs{0.0, 1.05, 1.2, -1.3, std::nan(""), 0.5};
  const auto library = check_inputs(domain, inputs);
  std::size_t outside = 0;
  for (const auto& excursion : library.excursions)
    outside += excursion.samples;
  EXPECT_EQ(outside, 3u);

  // Without a domain, none of it.
  options.domain.reset();
  EXPECT_EQ(generate_c(*model, options).header.find("check_input"), std::string::npos);
}

TEST_F(ExportCTest, InversePrandtlIshlinskiiWithInputLimits) {
  Case c{model_document(
      "pi", {{"thresholds", {0.0, 0.2, 0.4}}, {"weights", {0.9, 0.5, 0.3}}, {"offset", 0.0}})};
  compare(c, CScalar::double_precision, "-O2", 1e-12, {-0.5, 0.6});
}

TEST_F(ExportCTest, PrandtlIshlinskiiWithCreepAndItsInverse) {
  check_everything({example_document("pi_creep"), -2.0, 2.0}, kFloatBound);
  // Input limits (the inverse then resynchronises its plays) and a model without lags.
  check_everything({example_document("pi_creep"), -2.0, 2.0}, kFloatBound, {-0.8, 0.9});
  check_everything({model_document("pi_creep", {{"thresholds", {0.0, 0.3}},
                                                {"weights", {1.0, 0.4}},
                                                {"time_constants", nlohmann::json::array()},
                                                {"creep_weights", nlohmann::json::array()},
                                                {"sample_time", 0.01}}),
                    -1.0, 1.0},
                   kFloatBound);
  // With the leakage drift: the C step integrates it and the inverse subtracts it as memory.
  auto leaky = example_document("pi_creep");
  leaky["params"]["leakage_conductance"] = 0.05;
  leaky["params"]["leakage_current"] = -0.02;
  check_everything({leaky, -2.0, 2.0}, kFloatBound);
}

TEST_F(ExportCTest, ModifiedPrandtlIshlinskiiAndItsInverse) {
  check_everything({example_document("modified_pi"), -2.0, 2.0}, kFloatBound);
  // With output limits inside the reached range, so that the clamp acts.
  auto limited = example_document("modified_pi");
  limited["params"]["output_min"] = -0.3;
  limited["params"]["output_max"] = 0.4;
  check_everything({limited, -2.0, 2.0}, kFloatBound);
}

TEST_F(ExportCTest, ModifiedPrandtlIshlinskiiWithCreepAndItsInverse) {
  check_everything({example_document("modified_pi_creep"), -2.0, 2.0}, kFloatBound);
  // Output limits that act, and input limits on the inverse.
  auto limited = example_document("modified_pi_creep");
  limited["params"]["output_min"] = -0.4;
  limited["params"]["output_max"] = 0.5;
  limited["params"]["pi_offset"] = 0.05;
  limited["params"]["offset"] = 0.1;
  check_everything({limited, -2.0, 2.0}, kFloatBound, {-0.8, 0.9});
}

TEST_F(ExportCTest, GeneralizedPrandtlIshlinskiiAndItsInverseForEveryEnvelope) {
  auto tanh = example_document("gpi");
  check_everything({tanh, -2.5, 2.5}, kFloatBound);
  auto arctan = tanh;
  arctan["params"]["envelope"] = "arctan";
  check_everything({arctan, -2.5, 2.5}, kFloatBound);
  auto linear = tanh;
  linear["params"]["envelope"] = "linear";
  linear["params"]["ascending"] = {1.0, -0.1};
  linear["params"]["descending"] = {1.0, 0.1};
  check_everything({linear, -2.5, 2.5}, kFloatBound);
}

TEST_F(ExportCTest, PreisachAndItsNumericalInverse) {
  // Random non-negative weights on an 11-level grid; the input also leaves the range (saturation).
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> weights(66);
  for (auto& w : weights)
    w = unit(random);
  Case c{model_document("preisach", {{"levels", 11},
                                     {"lower", -1.0},
                                     {"upper", 1.0},
                                     {"weights", weights},
                                     {"offset", 0.2},
                                     {"initial_state", "demagnetised"}})};
  // Float: the relay grid makes the output a step function of the input, so an input within
  // float rounding of a level may switch one relay more or less; and the inverse answers with a
  // float input. The bound is one relay weight (< 1) relative to the output scale (F0 ~ 33).
  check_everything(c, 0.04);
}

TEST_F(ExportCTest, PreisachMemoryOverflowDropsTheSamePairs) {
  // 400 loops nested in one another (ever-shrinking oscillations) overflow the 256-pair memory:
  // the C code must drop the same innermost pairs as the library.
  std::vector<double> input;
  for (int k = 0; k < 800; ++k)
    input.push_back((k % 2 == 0 ? 1.0 : -1.0) * (0.95 - 0.001 * k));
  Case c{model_document("preisach", {{"levels", 41},
                                     {"lower", -1.0},
                                     {"upper", 1.0},
                                     {"weights", std::vector<double>(861, 1.0)}}),
         -1.0, 1.0, 0, input};
  Preisach preisach(preisach_params_of(c.document));
  auto state = preisach.initial_state();
  for (const double v : input)
    preisach.step(state, v);
  ASSERT_GT(state.truncations, 0U);  // the input does overflow the library's memory
  compare(c, CScalar::double_precision, "-O2", 1e-12);
}

TEST_F(ExportCTest, BoucWenRk4AndExactSolution) {
  check_everything({example_document("bouc_wen"), -3.0, 3.0}, kFloatBound);  // n = 1.5: RK4
  auto exact = example_document("bouc_wen");
  exact["params"]["n"] = 1.0;
  check_everything({exact, -3.0, 3.0}, kFloatBound);
}

// Every exported inverse, in double and float, with and without input limits: +-inf and +-1e308
// give the limits (a finite input without them), never NaN; a NaN target holds the last input.
// Compiles a driver of the inverse exported as "odd" into `dir` and returns its answers to the
// targets 0.1, 1e308, 0.2, +inf, 0.1, -inf, 0.15, -1e308, 0.05, NaN (in this order).
std::vector<double> odd_inverse_answers(const std::filesystem::path& dir) {
  const std::string driver = R"(#include <math.h>
#include <stdio.h>
#include "odd.h"
int main(void) {
  const double targets[] = {0.1, 1e308, 0.2, HUGE_VAL, 0.1, -HUGE_VAL, 0.15, -1e308, 0.05, NAN};
  odd_inverse_state state;
  unsigned int k;
  odd_inverse_init(&state);
  for (k = 0; k < sizeof targets / sizeof targets[0]; ++k)
    printf("%.17g\n", (double)odd_inverse_step(&odd_INVERSE_PARAMS, &state, (odd_real)targets[k]));
  return 0;
}
)";
  std::ofstream(dir / "odd_driver.c") << driver;
  std::string log;
  if (test::run_command(
          fmt::format("cd '{}' && gcc -std=c99 -Wall -Wextra -Werror -pedantic -o odd "
                      "odd_driver.c odd.c -lm 2>&1",
                      dir.string()),
          &log) != 0) {
    ADD_FAILURE() << log;
    return {};
  }
  std::string printed;
  EXPECT_EQ(test::run_command(fmt::format("cd '{}' && ./odd", dir.string()), &printed), 0);
  return numbers_in(printed);
}

class ExportCInverseTest : public ExportCTest, public testing::WithParamInterface<std::string> {};

TEST_P(ExportCInverseTest, NonFiniteTargetsGiveTheLimitsOrTheHeldInput) {
  const std::string name = GetParam();
  const auto model = model_from_json(example_document(name), "test.json");
  for (const CScalar scalar : {CScalar::double_precision, CScalar::single_precision}) {
    for (const bool limited : {true, false}) {
      CExportOptions options;
      options.prefix = "odd";
      options.scalar = scalar;
      if (limited) options.limits = {-0.5, 0.5};
      const CCode code = export_c(*model, dir_, options);
      ASSERT_TRUE(code.has_inverse) << name;
      const auto inputs = odd_inverse_answers(dir_);
      const std::string what =
          fmt::format("{} ({}, {})", name, scalar == CScalar::single_precision ? "float" : "double",
                      limited ? "limits [-0.5, 0.5]" : "no limits");
      ASSERT_EQ(inputs.size(), 10U) << what;
      for (std::size_t k = 0; k < inputs.size(); ++k)
        EXPECT_TRUE(std::isfinite(inputs[k])) << what << ": target " << k << " gave " << inputs[k];
      if (limited) {
        EXPECT_EQ(inputs[1], 0.5) << what << ": 1e308";
        EXPECT_EQ(inputs[3], 0.5) << what << ": +inf";
        EXPECT_EQ(inputs[5], -0.5) << what << ": -inf";
        EXPECT_EQ(inputs[7], -0.5) << what << ": -1e308";
      }
      EXPECT_EQ(inputs[9], inputs[8]) << what << ": NaN holds the last input";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryModelWithAnInverse, ExportCInverseTest,
                         testing::Values("pi", "modified_pi", "gpi", "preisach", "pi_creep",
                                         "modified_pi_creep"));

// Inverse weights near the library's limit (ph = 1e300, -5e299): the bound of the targets scales
// with them, so that +-inf and 1e308 still give the limit of their direction. A fixed bound of
// 1e150 gave -0.5 for +inf and 1e308 here (1e300 * 1e150 - 5e299 * 1e150 = inf - inf = NaN, which
// the clamp answers with input_min).
TEST_F(ExportCTest, HugeInverseWeightsStillBoundTheTargets) {
  const auto model = model_from_json(
      model_document("pi", {{"thresholds", {0.0, 0.3}}, {"weights", {1e-300, 1e-300}}}),
      "test.json");
  CExportOptions options;
  options.prefix = "odd";
  options.limits = {-0.5, 0.5};
  export_c(*model, dir_, options);
  const auto inputs = odd_inverse_answers(dir_);
  ASSERT_EQ(inputs.size(), 10U);
  EXPECT_EQ(inputs[1], 0.5) << "1e308";
  EXPECT_EQ(inputs[3], 0.5) << "+inf";
  EXPECT_EQ(inputs[5], -0.5) << "-inf";
  EXPECT_EQ(inputs[7], -0.5) << "-1e308";
  EXPECT_EQ(inputs[9], inputs[8]) << "NaN";
}

// The list above is every exported model with an inverse.
TEST_F(ExportCTest, EveryExportedInverseIsCheckedWithNonFiniteTargets) {
  std::set<std::string> with_inverse;
  for (const auto& entry : ModelRegistry::builtin().entries()) {
    if (entry.can_export_c() &&
        generate_c(*model_from_json(example_document(entry.name), "test.json"), {}).has_inverse)
      with_inverse.insert(entry.name);
  }
  EXPECT_EQ(with_inverse, (std::set<std::string>{"pi", "modified_pi", "gpi", "preisach", "pi_creep",
                                                 "modified_pi_creep"}));
}

TEST_F(ExportCTest, NmListsTheMathFunctionsTheCodeCalls) {
  // The symbol check of check_everything() reads nm's listing: it does see the calls there are.
  const Case c{example_document("gpi")};
  const auto in_double = undefined_symbols(c, CScalar::double_precision);
  EXPECT_EQ(in_double.count("exp"), 1U);
  EXPECT_EQ(in_double.count("atanh"), 1U);
  const auto in_float = undefined_symbols(c, CScalar::single_precision);
  EXPECT_EQ(in_float.count("expf"), 1U);
  EXPECT_EQ(in_float.count("exp"), 0U);
}

TEST_F(ExportCTest, UnsupportedModelIsNamed) {
  auto model = model_from_json(example_document("kp"), "test");
  EXPECT_HYST_ERROR(generate_c(*model, {}), "'kp' is not supported");
}

// An entry's C export takes its own concrete model: a model another entry made is refused by name
// (no JSON is read to get around it).
TEST_F(ExportCTest, EntryRefusesAnotherEntrysModel) {
  const auto gpi = model_from_json(example_document("gpi"), "test");
  CExportOptions options;
  options.prefix = "m";
  EXPECT_HYST_ERROR(ModelRegistry::builtin().find("pi").c_code(*gpi, options),
                    "the model 'gpi' was not made by the registry's 'pi' entry");
}

TEST_F(ExportCTest, AdaptiveBoucWenIsRefused) {
  auto document = example_document("bouc_wen");
  document["params"]["tolerance"] = 1e-8;
  auto model = model_from_json(document, "test");
  EXPECT_HYST_ERROR(generate_c(*model, {}), "tolerance = 0");
}

TEST_F(ExportCTest, BadPrefixAndAFileAsFolderAreNamed) {
  auto model = model_from_json(example_document("pi"), "test");
  CExportOptions options;
  options.prefix = "9lives";
  EXPECT_HYST_ERROR(generate_c(*model, options), "must be a C identifier");
  std::ofstream(dir_ / "file") << "x";
  EXPECT_HYST_ERROR(export_c(*model, dir_ / "file" / "ctrl", {}),
                    "C export: cannot create the folder '" + (dir_ / "file" / "ctrl").string() +
                        "': '" + (dir_ / "file").string() + "' is not a folder");
}

TEST_F(ExportCTest, CreatesAMissingFolder) {
  auto model = model_from_json(example_document("pi"), "test");
  const auto code = export_c(*model, dir_ / "new" / "ctrl", {});
  EXPECT_TRUE(std::filesystem::is_regular_file(dir_ / "new" / "ctrl" / code.header_name));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir_ / "new" / "ctrl" / code.source_name));
}

}  // namespace
}  // namespace hyst
