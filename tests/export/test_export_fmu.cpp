// The FMU export as an importer sees it: every model with a C export (and its inverse) becomes an
// FMU that tests/support/fmu_host.hpp unpacks, checks against the FMI 2.0 model-description
// rules, loads and drives for 10^6 samples against the library's own simulation; saved and
// serialised states replay bit for bit; a sample allocates nothing; the directional derivative
// is checked against slopes worked out by hand.

#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/expect_error.hpp"
#include "../support/fmu_host.hpp"
#include "../support/shell_command.hpp"
#include "../support/temp_folder_test.hpp"
#include "../support/test_signals.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/export/export_fmu.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/timed_simulation.hpp"

namespace hyst {
namespace {

using test::Fmu;
using test::FmuInstance;
namespace fmi2 = test::fmi2;

nlohmann::json model_document(std::string_view name, nlohmann::json params) {
  return {{"model", name}, {"version", 1}, {"params", std::move(params)}};
}

nlohmann::json example_document(std::string_view name) {
  return model_document(name, ModelRegistry::builtin().find(name).example_params);
}

nlohmann::json pi_document() {
  return model_document("pi", {{"thresholds", {0.0, 0.15, 0.3, 0.45, 0.6}},
                               {"weights", {1.1, 0.4, 0.3, 0.2, 0.25}},
                               {"offset", 0.35}});
}

struct Case {
  nlohmann::json document;
  double low = -1.0;  // input range
  double high = 1.0;
};

class ExportFmuTest : public test::TempFolderTest {
 protected:
  // The model of `document` after 300 samples: the FMU starts from that state, not the default.
  static std::unique_ptr<DynamicModel> warmed_model(const Case& c) {
    auto model = model_from_json(c.document, "test.json");
    const auto warm = test::seeded_input(7, c.low, c.high, 300, 0.0);
    std::vector<double> ignored(warm.size());
    model->simulate(warm, ignored);
    return model;
  }

  FmuFiles export_fmus(const DynamicModel& model, bool inverse, CScalar scalar) {
    FmuExportOptions options;
    options.code.prefix = "plant";
    options.code.scalar = scalar;
    options.code.source = "test.json";
    options.input_unit = "V";
    options.output_unit = "um";
    options.inverse = inverse;
    return export_fmu(model, dir_ / "out", options);
  }

  std::unique_ptr<Fmu> open(const std::filesystem::path& file) {
    auto fmu = std::make_unique<Fmu>(file, dir_ / file.stem());
    const auto problems = fmu->description_problems();
    for (const auto& problem : problems)
      ADD_FAILURE() << file.filename() << ": " << problem;
    return fmu;
  }

  // The communication step: the model's sample time, or any for a rate-independent model.
  static double step_of(const Fmu& fmu) {
    const auto experiment =
        fmu.description().child("fmiModelDescription").child("DefaultExperiment");
    return experiment.attribute("stepSize").as_double(1e-3);
  }

  // Drives `fmu` with `input` (set, get, step) and checks it against `expected` to `tolerance`
  // of the output scale.
  static void expect_agreement(const Fmu& fmu, const std::vector<double>& input,
                               const std::vector<double>& expected, double tolerance) {
    FmuInstance instance(fmu);
    const double h = step_of(fmu);
    double scale = 1.0;
    for (const double y : expected)
      scale = std::max(scale, std::abs(y));
    double worst = 0.0;
    std::size_t worst_at = 0;
    for (std::size_t k = 0; k < input.size(); ++k) {
      const double error = std::abs(instance.sample(input[k], h) - expected[k]);
      if (error > worst) {
        worst = error;
        worst_at = k;
      }
    }
    EXPECT_LE(worst, tolerance * scale)
        << fmu.identifier() << ": sample " << worst_at << " of " << input.size();
    std::printf("[ worst    ] %s: %.3g of scale %.3g over %zu samples\n", fmu.identifier().c_str(),
                worst / scale, scale, input.size());
  }

  // Saved states (in memory and serialised into another instance) replay bit for bit.
  static void expect_replay(const Fmu& fmu, const std::vector<double>& input) {
    const double h = step_of(fmu);
    FmuInstance instance(fmu);
    for (std::size_t k = 0; k < 1000; ++k)
      instance.sample(input[k], h);
    const auto& f = instance.call();
    fmi2::FMUstate saved = nullptr;
    ASSERT_EQ(f.get_fmu_state(instance.component(), &saved), fmi2::OK);
    const double saved_time = instance.time();
    std::vector<double> first;
    for (std::size_t k = 1000; k < 3000; ++k)
      first.push_back(instance.sample(input[k], h));

    ASSERT_EQ(f.set_fmu_state(instance.component(), saved), fmi2::OK);
    FmuInstance* replaying = &instance;
    std::vector<double> again;
    double t = saved_time;
    const fmi2::ValueReference in = 0;
    const fmi2::ValueReference out = 1;
    for (std::size_t k = 1000; k < 3000; ++k) {
      double y = 0.0;
      ASSERT_EQ(f.set_real(replaying->component(), &in, 1, &input[k]), fmi2::OK);
      ASSERT_EQ(f.get_real(replaying->component(), &out, 1, &y), fmi2::OK);
      ASSERT_EQ(f.do_step(replaying->component(), t, h, 0), fmi2::OK);
      t += h;
      again.push_back(y);
    }
    EXPECT_EQ(again, first) << fmu.identifier() << ": restored state";

    // Serialised, then read by a fresh instance of the same FMU.
    std::size_t size = 0;
    ASSERT_EQ(f.serialized_fmu_state_size(instance.component(), saved, &size), fmi2::OK);
    std::vector<char> bytes(size);
    ASSERT_EQ(f.serialize_fmu_state(instance.component(), saved, bytes.data(), size), fmi2::OK);
    FmuInstance fresh(fmu);
    fmi2::FMUstate copy = nullptr;
    ASSERT_EQ(f.deserialize_fmu_state(fresh.component(), bytes.data(), size, &copy), fmi2::OK);
    ASSERT_EQ(f.set_fmu_state(fresh.component(), copy), fmi2::OK);
    double time = 0.0;
    ASSERT_EQ(f.get_real_status(fresh.component(), 2 /* fmi2LastSuccessfulTime */, &time),
              fmi2::OK);
    EXPECT_EQ(time, saved_time);
    std::vector<double> serialised;
    t = saved_time;
    for (std::size_t k = 1000; k < 3000; ++k) {
      double y = 0.0;
      f.set_real(fresh.component(), &in, 1, &input[k]);
      f.get_real(fresh.component(), &out, 1, &y);
      ASSERT_EQ(f.do_step(fresh.component(), t, h, 0), fmi2::OK);
      t += h;
      serialised.push_back(y);
    }
    EXPECT_EQ(serialised, first) << fmu.identifier() << ": serialised state";
    // Bytes of another size or with another mark are refused.
    fmi2::FMUstate refused = nullptr;
    EXPECT_EQ(f.deserialize_fmu_state(fresh.component(), bytes.data(), size - 1, &refused),
              fmi2::Error);
    bytes[0] = static_cast<char>(bytes[0] ^ 0x5a);
    EXPECT_EQ(f.deserialize_fmu_state(fresh.component(), bytes.data(), size, &refused),
              fmi2::Error);
    EXPECT_EQ(refused, nullptr);
    f.free_fmu_state(instance.component(), &saved);
    f.free_fmu_state(fresh.component(), &copy);
    EXPECT_EQ(saved, nullptr);
  }

  static void expect_no_allocation(const Fmu& fmu, const std::vector<double>& input) {
    FmuInstance instance(fmu);
    const double h = step_of(fmu);
    instance.sample(input[0], h);
    const long before = test::allocation_count();
    for (std::size_t k = 1; k < 10000; ++k)
      instance.sample(input[k], h);
    EXPECT_EQ(test::allocation_count() - before, 0) << fmu.identifier();
  }

  // Everything for one model: 10^6 samples of the model and 10^5 of its inverse (when it has
  // one) against the library, the replay and the allocation check.
  void check_everything(const Case& c) {
    const auto model = warmed_model(c);
    const bool has_inverse = generate_c(*model, {}).has_inverse;
    const auto files = export_fmus(*model, has_inverse, CScalar::double_precision);
    const auto input = test::seeded_input(11, c.low, c.high, 1000000, 0.0);
    std::vector<double> expected(input.size());
    model->clone()->simulate(input, expected);
    const auto fmu = open(files.model);
    expect_agreement(*fmu, input, expected, 1e-12);
    expect_replay(*fmu, input);
    expect_no_allocation(*fmu, input);
    if (!has_inverse) return;

    // Reachable targets: the model's output for another input.
    std::vector<double> target(100000);
    model->clone()->simulate(test::seeded_input(13, c.low, c.high, target.size(), 0.0), target);
    std::vector<double> inverted(target.size());
    model->inverse({})->invert(target, inverted);
    const auto inverse = open(files.inverse);
    expect_agreement(*inverse, target, inverted, 1e-12);
    expect_replay(*inverse, target);
    expect_no_allocation(*inverse, target);
  }
};

TEST_F(ExportFmuTest, PrandtlIshlinskiiAndItsInverse) {
  check_everything({pi_document()});
}

TEST_F(ExportFmuTest, ModifiedPrandtlIshlinskiiAndItsInverse) {
  check_everything({example_document("modified_pi"), -2.0, 2.0});
}

TEST_F(ExportFmuTest, GeneralizedPrandtlIshlinskiiAndItsInverse) {
  check_everything({example_document("gpi"), -2.5, 2.5});
}

TEST_F(ExportFmuTest, PreisachAndItsNumericalInverse) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> weights(66);
  for (auto& w : weights)
    w = unit(random);
  check_everything({model_document("preisach", {{"levels", 11},
                                                {"lower", -1.0},
                                                {"upper", 1.0},
                                                {"weights", weights},
                                                {"offset", 0.2},
                                                {"initial_state", "demagnetised"}})});
}

TEST_F(ExportFmuTest, BoucWenRk4AndExactSolution) {
  check_everything({example_document("bouc_wen"), -3.0, 3.0});
  auto exact = example_document("bouc_wen");
  exact["params"]["n"] = 1.0;
  check_everything({exact, -3.0, 3.0});
}

TEST_F(ExportFmuTest, CreepModelsAtTheirSampleTime) {
  check_everything({example_document("pi_creep"), -2.0, 2.0});
  check_everything({example_document("modified_pi_creep"), -2.0, 2.0});
}

TEST_F(ExportFmuTest, EveryModelWithCExportIsCovered) {
  // The cases above; a new exportable model must get its FMU test too.
  const std::set<std::string> covered = {
      "pi", "modified_pi", "gpi", "preisach", "bouc_wen", "pi_creep", "modified_pi_creep"};
  std::set<std::string> exportable;
  for (const auto& entry : ModelRegistry::builtin().entries())
    if (entry.can_export_c()) exportable.insert(entry.name);
  EXPECT_EQ(exportable, covered);
}

TEST_F(ExportFmuTest, VariablesParametersAndUnits) {
  const auto model = model_from_json(pi_document(), "test.json");
  const auto files = export_fmus(*model, true, CScalar::double_precision);
  const auto fmu = open(files.model);
  EXPECT_EQ(fmu->identifier(), "plant");
  EXPECT_EQ(fmu->variable("u").causality, "input");
  EXPECT_EQ(fmu->variable("u").unit, "V");
  EXPECT_EQ(fmu->variable("y").causality, "output");
  EXPECT_EQ(fmu->variable("y").unit, "um");
  // The document's values, elements counted from 1.
  EXPECT_EQ(fmu->variable("thresholds[2]").start, 0.15);
  EXPECT_EQ(fmu->variable("thresholds[2]").unit, "V");
  EXPECT_EQ(fmu->variable("weights[1]").start, 1.1);
  EXPECT_EQ(fmu->variable("weights[1]").unit, "um/V");
  EXPECT_EQ(fmu->variable("offset").start, 0.35);
  EXPECT_EQ(fmu->variable("offset").causality, "parameter");
  EXPECT_EQ(fmu->variables().size(), 2U + 5U + 5U + 1U);
  EXPECT_EQ(fmu->capability("canHandleVariableCommunicationStepSize"), "true");
  EXPECT_EQ(fmu->capability("canGetAndSetFMUstate"), "true");
  EXPECT_EQ(fmu->capability("canSerializeFMUstate"), "true");
  EXPECT_EQ(fmu->capability("providesDirectionalDerivative"), "true");
  FmuInstance instance(*fmu);
  EXPECT_EQ(instance.get(fmu->variable("weights[3]").reference), 0.3);
  EXPECT_STREQ(fmu->functions().get_version(), "2.0");
  EXPECT_STREQ(fmu->functions().get_types_platform(), "default");

  // The inverse takes the model's output and gives its input.
  const auto inverse = open(files.inverse);
  EXPECT_EQ(inverse->identifier(), "plant_inverse");
  EXPECT_EQ(inverse->variable("y").causality, "input");
  EXPECT_EQ(inverse->variable("y").unit, "um");
  EXPECT_EQ(inverse->variable("u").causality, "output");
  EXPECT_EQ(inverse->variable("u").unit, "V");
  EXPECT_NE(inverse->guid(), fmu->guid());
}

TEST_F(ExportFmuTest, ParametersSetBeforeInitialisationChangeTheModel) {
  const auto model = model_from_json(pi_document(), "test.json");
  const auto fmu = open(export_fmus(*model, false, CScalar::double_precision).model);
  // A second algorithm: the library's PI with the changed values.
  auto changed = pi_document();
  changed["params"]["offset"] = -0.5;
  changed["params"]["weights"][1] = 0.9;
  auto reference = model_from_json(changed, "changed.json");
  const auto input = test::seeded_input(3, -1.0, 1.0, 5000);
  std::vector<double> expected(input.size());
  reference->simulate(input, expected);
  FmuInstance instance(
      *fmu, {},
      {{fmu->variable("offset").reference, -0.5}, {fmu->variable("weights[2]").reference, 0.9}});
  for (std::size_t k = 0; k < input.size(); ++k)
    ASSERT_NEAR(instance.sample(input[k], 1e-3), expected[k], 1e-12) << k;
  // Fixed parameters stay fixed once initialised; outputs and unknown references are refused.
  EXPECT_EQ(instance.set(fmu->variable("offset").reference, 1.0), fmi2::Error);
  EXPECT_NE(instance.log().find("fixed parameter"), std::string::npos) << instance.log();
  EXPECT_EQ(instance.set(1, 1.0), fmi2::Error);
  EXPECT_EQ(instance.set(999, 1.0), fmi2::Error);
  EXPECT_EQ(instance.set(0, std::nan("")), fmi2::Error);
  EXPECT_NE(instance.log().find("not finite"), std::string::npos) << instance.log();
}

TEST_F(ExportFmuTest, DirectionalDerivativeIsTheSlopeInTheSeedsDirection) {
  // A PI from rest (every play at 0), the input raised to 0.5: the plays with r_j < 0.5 move on
  // with the input, so dy/du = 1.1 + 0.4 + 0.3 + 0.2 = 2.0 upwards; downwards only the play with
  // r = 0 follows at once: dy/du = 1.1.
  const auto model = model_from_json(pi_document(), "test.json");
  const auto fmu = open(export_fmus(*model, false, CScalar::double_precision).model);
  FmuInstance instance(*fmu);
  for (int k = 0; k <= 50; ++k)
    instance.sample(0.01 * k, 1e-3);
  ASSERT_EQ(instance.set(0, 0.5), fmi2::OK);
  const auto& f = instance.call();
  const fmi2::ValueReference in = 0;
  const fmi2::ValueReference out = 1;
  double dy = 0.0;
  const double up = 1.0;
  ASSERT_EQ(f.get_directional_derivative(instance.component(), &out, 1, &in, 1, &up, &dy),
            fmi2::OK);
  EXPECT_NEAR(dy, 2.0, 1e-7);
  const double down = -0.5;
  ASSERT_EQ(f.get_directional_derivative(instance.component(), &out, 1, &in, 1, &down, &dy),
            fmi2::OK);
  EXPECT_NEAR(dy, -0.5 * 1.1, 1e-7);
  // The derivative leaves the state alone: the next sample is the library's.
  std::vector<double> input;
  for (int k = 0; k <= 50; ++k)
    input.push_back(0.01 * k);
  input.push_back(0.2);
  std::vector<double> expected(input.size());
  model->clone()->simulate(input, expected);
  EXPECT_NEAR(instance.sample(0.5, 1e-3), expected[50], 1e-12);
  EXPECT_NEAR(instance.sample(0.2, 1e-3), expected[51], 1e-12);
  // Only d output / d input exists.
  const fmi2::ValueReference offset = fmu->variable("offset").reference;
  EXPECT_EQ(f.get_directional_derivative(instance.component(), &out, 1, &offset, 1, &up, &dy),
            fmi2::Error);
}

TEST_F(ExportFmuTest, FloatCodeStaysCloseToTheLibrary) {
  const auto model = model_from_json(pi_document(), "test.json");
  const auto files = export_fmus(*model, false, CScalar::single_precision);
  const auto input = test::seeded_input(11, -1.0, 1.0, 100000);
  std::vector<double> expected(input.size());
  model->clone()->simulate(input, expected);
  expect_agreement(*open(files.model), input, expected, 2e-5);
}

TEST_F(ExportFmuTest, ImporterMistakesAreRefusedWithAReason) {
  const auto model = model_from_json(example_document("pi_creep"), "test.json");
  const auto files = export_fmus(*model, true, CScalar::double_precision);
  const auto fmu = open(files.model);
  // The model steps at the host's communication step; its inverse at the exported one only.
  EXPECT_EQ(fmu->capability("canHandleVariableCommunicationStepSize"), "true");
  const auto inverse = open(files.inverse);
  EXPECT_EQ(inverse->capability("canHandleVariableCommunicationStepSize"), "false");
  const double h = step_of(*fmu);
  EXPECT_EQ(h, ModelRegistry::builtin().find("pi_creep").example_params.at("sample_time"));
  EXPECT_THROW(FmuInstance(*fmu, "{00000000-0000-0000-0000-000000000000}"), std::runtime_error);
  try {
    FmuInstance wrong(*fmu, "{00000000-0000-0000-0000-000000000000}");
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("GUID"), std::string::npos) << error.what();
  }
  FmuInstance compensator(*inverse);
  const auto& g = compensator.call();
  EXPECT_EQ(g.do_step(compensator.component(), 0.0, 1.5 * h, 0), fmi2::Error);
  EXPECT_NE(compensator.log().find("sample time"), std::string::npos) << compensator.log();
  FmuInstance instance(*fmu);
  const auto& f = instance.call();
  EXPECT_EQ(f.do_step(instance.component(), 5.0, h, 0), fmi2::Error);
  EXPECT_NE(instance.log().find("communication point"), std::string::npos) << instance.log();
  EXPECT_EQ(f.do_step(instance.component(), 0.0, h, 0), fmi2::OK);
}

// The creep model's FMU at a host step 7 times the fitted one, and at steps that change: the
// library's model on the same time axis (re-discretised, simulate_on_time_axis), to rounding.
// The first point's sample spans the model's own sample time: the host's step is not known
// before the first fmi2DoStep.
TEST_F(ExportFmuTest, TheCreepModelStepsAtTheHostsCommunicationStep) {
  for (const char* name : {"pi_creep", "modified_pi_creep"}) {
    const auto model = model_from_json(example_document(name), "test.json");
    const auto fmu = open(export_fmus(*model, false, CScalar::double_precision).model);
    const double ts = *model->sample_time();
    const auto input = test::seeded_input(11, -2.0, 2.0, 400, 0.0);
    for (const double factor : {7.0, 0.25}) {
      data::TimeAxis axis{ts * factor, std::vector<double>(input.size(), ts * factor)};
      axis.steps[0] = ts;
      std::unique_ptr<DynamicModel> timed = model->clone();
      std::vector<double> expected(input.size());
      simulate_on_time_axis(timed, axis, input, expected);
      FmuInstance instance(*fmu);
      double worst = 0.0;
      for (std::size_t k = 0; k < input.size(); ++k)
        worst = std::max(worst, std::abs(instance.sample(input[k], ts * factor) - expected[k]));
      EXPECT_LE(worst, 1e-12) << name << " at " << factor << " Ts";
      // Not the same as the model at its own sample time: the step matters.
      std::vector<double> untimed(input.size());
      model->clone()->simulate(input, untimed);
      double apart = 0.0;
      for (std::size_t k = 0; k < input.size(); ++k)
        apart = std::max(apart, std::abs(untimed[k] - expected[k]));
      EXPECT_GT(apart, 1e-3) << name;
    }
  }
}

TEST_F(ExportFmuTest, SourcesBuildWithoutWarningsAndOnlyTheInterfaceIsExported) {
  const auto model = model_from_json(example_document("gpi"), "test.json");
  const auto fmu = open(export_fmus(*model, false, CScalar::double_precision).model);
  std::string log;
  EXPECT_EQ(test::run_command(
                fmt::format("cd '{}' && gcc -std=c99 -Wall -Wextra -Werror -pedantic -c *.c 2>&1",
                            (fmu->folder() / "sources").string()),
                &log),
            0)
      << log;
  std::string symbols;
  ASSERT_EQ(test::run_command(fmt::format("nm -D --defined-only '{}'",
                                          (fmu->folder() / "binaries/linux64/plant.so").string()),
                              &symbols),
            0);
  std::istringstream in(symbols);
  std::string address;
  std::string kind;
  std::string name;
  std::set<std::string> exported;
  while (in >> address >> kind >> name) {
    if (kind == "T") exported.insert(name);
  }
  // The functions of the FMI 2.0 co-simulation interface (standard, sections 2.1 and 4.2), and
  // nothing else.
  const std::set<std::string> interface = {"fmi2GetTypesPlatform",
                                           "fmi2GetVersion",
                                           "fmi2SetDebugLogging",
                                           "fmi2Instantiate",
                                           "fmi2FreeInstance",
                                           "fmi2SetupExperiment",
                                           "fmi2EnterInitializationMode",
                                           "fmi2ExitInitializationMode",
                                           "fmi2Terminate",
                                           "fmi2Reset",
                                           "fmi2GetReal",
                                           "fmi2GetInteger",
                                           "fmi2GetBoolean",
                                           "fmi2GetString",
                                           "fmi2SetReal",
                                           "fmi2SetInteger",
                                           "fmi2SetBoolean",
                                           "fmi2SetString",
                                           "fmi2GetFMUstate",
                                           "fmi2SetFMUstate",
                                           "fmi2FreeFMUstate",
                                           "fmi2SerializedFMUstateSize",
                                           "fmi2SerializeFMUstate",
                                           "fmi2DeSerializeFMUstate",
                                           "fmi2GetDirectionalDerivative",
                                           "fmi2SetRealInputDerivatives",
                                           "fmi2GetRealOutputDerivatives",
                                           "fmi2DoStep",
                                           "fmi2CancelStep",
                                           "fmi2GetStatus",
                                           "fmi2GetRealStatus",
                                           "fmi2GetIntegerStatus",
                                           "fmi2GetBooleanStatus",
                                           "fmi2GetStringStatus"};
  EXPECT_EQ(exported, interface);
}

TEST_F(ExportFmuTest, ExportErrorsNameTheOption) {
  const auto model = model_from_json(pi_document(), "test.json");
  FmuExportOptions options;
  options.input_name = "1u";
  EXPECT_HYST_ERROR(export_fmu(*model, dir_, options), "variable name '1u'");
  options.input_name = "offset";
  EXPECT_HYST_ERROR(export_fmu(*model, dir_, options), "'offset' is a parameter's name");
  options.input_name = "u";
  options.output_unit = "micro metre";
  EXPECT_HYST_ERROR(export_fmu(*model, dir_, options), "without spaces");
  options.output_unit = "um";
  options.compiler = (dir_ / "no-such-compiler").string();
  EXPECT_HYST_ERROR(export_fmu(*model, dir_, options), "cannot start the C compiler");
  options.compiler = "false";  // starts, fails
  EXPECT_HYST_ERROR(export_fmu(*model, dir_, options), "the C compiler failed (exit status 1)");
  options.compiler.clear();
  const auto bouc_wen = model_from_json(example_document("bouc_wen"), "test.json");
  options.inverse = true;
  EXPECT_HYST_ERROR(export_fmu(*bouc_wen, dir_, options), "has no inverse");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "hyst_pi.fmu"));
}

}  // namespace
}  // namespace hyst
