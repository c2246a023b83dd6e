// The FMU under a host that breaks the FMI rules: NULL components and pointers, a second free,
// parameters the library refuses, changed or forged saved states, non-finite targets of the
// inverse. Each risky call runs in a forked child, so that a crash is a failed expectation (the
// signal named), not a crashed test program; the FMU must answer fmi2Error (with a log line
// through the host's callback where it has one), never take the host down. The call sequence
// of common importers (a state restored into a fresh instance) must work.

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/fmu_host.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/export/export_fmu.hpp"
#include "hyst/models/preisach_state.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {

using test::Fmu;
using test::FmuInstance;
namespace fmi2 = test::fmi2;

constexpr fmi2::ValueReference kInput = 0;
constexpr fmi2::ValueReference kOutput = 1;
constexpr double kInf = std::numeric_limits<double>::infinity();

nlohmann::json hostile_pi_document() {
  return {{"model", "pi"},
          {"version", 1},
          {"params",
           {{"thresholds", {0.0, 0.15, 0.3, 0.45, 0.6}},
            {"weights", {1.1, 0.4, 0.3, 0.2, 0.25}},
            {"offset", 0.35}}}};
}

// What a call did in a forked child: the status it returned (and whether the FMU logged a line
// with `expected_log` in it), or the signal that ended the child.
struct Outcome {
  int status = -1;
  bool logged = false;
  int signal = 0;
};

std::string describe(const Outcome& outcome) {
  if (outcome.signal != 0)
    return fmt::format("crashed with signal {} ({})", outcome.signal, strsignal(outcome.signal));
  return fmt::format("status {}{}", outcome.status, outcome.logged ? ", logged" : ", no log line");
}

// Runs `call` in a child process; `call` returns a status and may read the instance's log.
Outcome in_child(const std::function<int(bool& logged)>& call) {
  const pid_t child = ::fork();
  if (child == 0) {
    bool logged = false;
    const int status = call(logged);
    ::_exit(status * 2 + (logged ? 1 : 0));
  }
  int wait_status = 0;
  ::waitpid(child, &wait_status, 0);
  Outcome outcome;
  if (WIFSIGNALED(wait_status)) {
    outcome.signal = WTERMSIG(wait_status);
  } else {
    outcome.status = WEXITSTATUS(wait_status) / 2;
    outcome.logged = WEXITSTATUS(wait_status) % 2 == 1;
  }
  return outcome;
}

// FNV-1a, 64 bits, written here apart from the FMU's: a forger's checksum of a changed state.
std::uint64_t fnv1a(const char* begin, const char* end) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char* c = begin; c < end; ++c) {
    hash ^= static_cast<unsigned char>(*c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

// The serialised layout the FMU documents in its wrapper: mark, checksum (of every byte after
// it), time, input, output, the output flag and the mode, then the states.
constexpr std::size_t kChecksumAt = 8;
constexpr std::size_t kInputAt = 24;
constexpr std::size_t kFirstStateValueAt = 48;

template <class T>
void forge(std::vector<char>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
  const std::uint64_t checksum = fnv1a(bytes.data() + kChecksumAt + 8, bytes.data() + bytes.size());
  std::memcpy(bytes.data() + kChecksumAt, &checksum, sizeof checksum);
}

class FmuHostileHostTest : public test::TempFolderTest {
 protected:
  // The PI model's FMU and its inverse, the inverse limited to [-1, 1] or unlimited.
  void export_pi(bool limited) {
    const auto model = model_from_json(hostile_pi_document(), "test.json");
    FmuExportOptions options;
    options.code.prefix = limited ? "plant" : "free";
    options.inverse = true;
    if (limited) options.code.limits = {-1.0, 1.0};
    const auto files = export_fmu(*model, dir_ / "out", options);
    fmu_ = std::make_unique<Fmu>(files.model, dir_ / (options.code.prefix + "_model"));
    inverse_ = std::make_unique<Fmu>(files.inverse, dir_ / (options.code.prefix + "_inverse"));
    for (const auto* fmu : {fmu_.get(), inverse_.get()})
      for (const auto& problem : fmu->description_problems())
        ADD_FAILURE() << fmu->identifier() << ": " << problem;
  }

  // `call` on a stepping instance of `fmu` must answer fmi2Error with a log line, in a child.
  static void expect_refused(
      const Fmu& fmu, const char* what,
      const std::function<int(const fmi2::Functions&, fmi2::Component)>& call,
      fmi2::Status expected = fmi2::Error) {
    const Outcome outcome = in_child([&](bool& logged) {
      FmuInstance instance(fmu);
      const int status = call(fmu.functions(), instance.component());
      logged = !instance.log().empty();
      return status;
    });
    EXPECT_EQ(outcome.signal, 0) << what << ": " << describe(outcome);
    EXPECT_EQ(outcome.status, expected) << what << ": " << describe(outcome);
    EXPECT_TRUE(outcome.logged) << what << ": " << describe(outcome);
  }

  // `call` on no instance at all must answer fmi2Error (there is no callback to log through).
  static void expect_refused_without_instance(const char* what, const std::function<int()>& call) {
    const Outcome outcome = in_child([&](bool&) { return call(); });
    EXPECT_EQ(outcome.signal, 0) << what << ": " << describe(outcome);
    EXPECT_EQ(outcome.status, fmi2::Error) << what << ": " << describe(outcome);
  }

  // The bytes of a saved state.
  static std::vector<char> serialise(const fmi2::Functions& f, fmi2::Component c,
                                     fmi2::FMUstate state) {
    std::size_t size = 0;
    EXPECT_EQ(f.serialized_fmu_state_size(c, state, &size), fmi2::OK);
    std::vector<char> bytes(size);
    EXPECT_EQ(f.serialize_fmu_state(c, state, bytes.data(), size), fmi2::OK);
    return bytes;
  }

  // The saved state of an instance after a few samples, serialised.
  static std::vector<char> serialised_state(const Fmu& fmu, FmuInstance& instance) {
    for (int k = 0; k < 20; ++k)
      instance.sample(0.04 * k, 1e-3);
    const auto& f = fmu.functions();
    fmi2::FMUstate state = nullptr;
    EXPECT_EQ(f.get_fmu_state(instance.component(), &state), fmi2::OK);
    auto bytes = serialise(f, instance.component(), state);
    f.free_fmu_state(instance.component(), &state);
    return bytes;
  }

  std::unique_ptr<Fmu> fmu_;
  std::unique_ptr<Fmu> inverse_;
};

TEST_F(FmuHostileHostTest, NullComponentsAreRefused) {
  export_pi(true);
  const auto& f = fmu_->functions();
  const fmi2::ValueReference in = kInput;
  double value = 0.5;
  expect_refused_without_instance("fmi2DoStep(NULL)",
                                  [&] { return f.do_step(nullptr, 0, 1e-3, 0); });
  expect_refused_without_instance("fmi2GetReal(NULL)",
                                  [&] { return f.get_real(nullptr, &in, 1, &value); });
  expect_refused_without_instance("fmi2SetReal(NULL)",
                                  [&] { return f.set_real(nullptr, &in, 1, &value); });
  expect_refused_without_instance("fmi2EnterInitializationMode(NULL)",
                                  [&] { return f.enter_initialization_mode(nullptr); });
  expect_refused_without_instance("fmi2ExitInitializationMode(NULL)",
                                  [&] { return f.exit_initialization_mode(nullptr); });
  expect_refused_without_instance("fmi2Terminate(NULL)", [&] { return f.terminate(nullptr); });
  expect_refused_without_instance("fmi2Reset(NULL)", [&] { return f.reset(nullptr); });
  expect_refused_without_instance("fmi2SetupExperiment(NULL)",
                                  [&] { return f.setup_experiment(nullptr, 0, 0.0, 0.0, 0, 0.0); });
  expect_refused_without_instance("fmi2GetFMUstate(NULL)", [&] {
    fmi2::FMUstate state = nullptr;
    return f.get_fmu_state(nullptr, &state);
  });
  expect_refused_without_instance("fmi2CancelStep(NULL)", [&] { return f.cancel_step(nullptr); });
  // A pointer that is no instance of this FMU (here: a stack variable) is not read either.
  expect_refused_without_instance("fmi2DoStep(foreign pointer)",
                                  [&] { return f.do_step(&value, 0, 1e-3, 0); });
}

TEST_F(FmuHostileHostTest, NullArraysAndOutPointersAreRefused) {
  export_pi(true);
  const fmi2::ValueReference in = kInput;
  const fmi2::ValueReference out = kOutput;
  expect_refused(*fmu_, "fmi2SetReal(value NULL)",
                 [&](const auto& f, auto c) { return f.set_real(c, &in, 1, nullptr); });
  expect_refused(*fmu_, "fmi2SetReal(vr NULL)", [&](const auto& f, auto c) {
    const double value = 0.1;
    return f.set_real(c, nullptr, 1, &value);
  });
  expect_refused(*fmu_, "fmi2GetReal(value NULL)",
                 [&](const auto& f, auto c) { return f.get_real(c, &out, 1, nullptr); });
  expect_refused(*fmu_, "fmi2GetFMUstate(FMUstate NULL)",
                 [&](const auto& f, auto c) { return f.get_fmu_state(c, nullptr); });
  expect_refused(*fmu_, "fmi2SerializedFMUstateSize(size NULL)", [&](const auto& f, auto c) {
    fmi2::FMUstate state = nullptr;
    f.get_fmu_state(c, &state);
    return f.serialized_fmu_state_size(c, state, nullptr);
  });
  expect_refused(*fmu_, "fmi2SerializeFMUstate(buffer NULL)", [&](const auto& f, auto c) {
    fmi2::FMUstate state = nullptr;
    std::size_t size = 0;
    f.get_fmu_state(c, &state);
    f.serialized_fmu_state_size(c, state, &size);
    return f.serialize_fmu_state(c, state, nullptr, size);
  });
  expect_refused(*fmu_, "fmi2SetFMUstate(NULL)",
                 [&](const auto& f, auto c) { return f.set_fmu_state(c, nullptr); });
  expect_refused(*fmu_, "fmi2DeSerializeFMUstate(bytes NULL)", [&](const auto& f, auto c) {
    fmi2::FMUstate state = nullptr;
    return f.deserialize_fmu_state(c, nullptr, 64, &state);
  });
  expect_refused(*fmu_, "fmi2GetDirectionalDerivative(dvKnown NULL)", [&](const auto& f, auto c) {
    double dy = 0.0;
    return f.get_directional_derivative(c, &out, 1, &in, 1, nullptr, &dy);
  });
  expect_refused(*fmu_, "fmi2GetDirectionalDerivative(dvUnknown NULL)", [&](const auto& f, auto c) {
    const double seed = 1.0;
    return f.get_directional_derivative(c, &out, 1, &in, 1, &seed, nullptr);
  });
  expect_refused(*fmu_, "fmi2GetRealStatus(value NULL)",
                 [&](const auto& f, auto c) { return f.get_real_status(c, 2, nullptr); });
  expect_refused(*fmu_, "fmi2GetStatus(value NULL)",
                 [&](const auto& f, auto c) { return f.get_status(c, 0, nullptr); });
  expect_refused(*fmu_, "fmi2SetDebugLogging(categories NULL)",
                 [&](const auto& f, auto c) { return f.set_debug_logging(c, 1, 2, nullptr); });
}

TEST_F(FmuHostileHostTest, FreeingTwiceIsHarmlessAndTheFreedInstanceIsRefused) {
  export_pi(true);
  const auto& f = fmu_->functions();
  const Outcome outcome = in_child([&](bool&) {
    fmi2::CallbackFunctions callbacks{nullptr, std::calloc, std::free, nullptr, nullptr};
    fmi2::Component c =
        f.instantiate("twice", fmi2::CoSimulation, fmu_->guid().c_str(), "", &callbacks, 0, 0);
    if (c == nullptr) return 9;
    f.free_instance(c);
    f.free_instance(c);
    return static_cast<int>(f.do_step(c, 0.0, 1e-3, 0));  // on the freed pointer
  });
  EXPECT_EQ(outcome.signal, 0) << describe(outcome);
  EXPECT_EQ(outcome.status, fmi2::Error) << describe(outcome);
}

TEST_F(FmuHostileHostTest, StatePointersThatAreNotLiveStatesAreRefused) {
  export_pi(true);
  double not_a_state[64] = {};
  expect_refused(*fmu_, "fmi2FreeFMUstate twice (a copy of the pointer)",
                 [&](const auto& f, auto c) {
                   fmi2::FMUstate state = nullptr;
                   f.get_fmu_state(c, &state);
                   fmi2::FMUstate copy = state;
                   f.free_fmu_state(c, &state);
                   return f.free_fmu_state(c, &copy);
                 });
  expect_refused(*fmu_, "fmi2SetFMUstate(a freed state)", [&](const auto& f, auto c) {
    fmi2::FMUstate state = nullptr;
    f.get_fmu_state(c, &state);
    fmi2::FMUstate copy = state;
    f.free_fmu_state(c, &state);
    return f.set_fmu_state(c, copy);
  });
  expect_refused(*fmu_, "fmi2SetFMUstate(foreign memory)",
                 [&](const auto& f, auto c) { return f.set_fmu_state(c, not_a_state); });
  expect_refused(*fmu_, "fmi2GetFMUstate(*FMUstate foreign)", [&](const auto& f, auto c) {
    fmi2::FMUstate state = not_a_state;  // an uninitialised variable of the host, say
    return f.get_fmu_state(c, &state);
  });
  expect_refused(*fmu_, "fmi2SerializeFMUstate(foreign memory)", [&](const auto& f, auto c) {
    char bytes[4096];
    return f.serialize_fmu_state(c, not_a_state, bytes, sizeof bytes);
  });
  expect_refused(*fmu_, "fmi2SerializedFMUstateSize(foreign memory)", [&](const auto& f, auto c) {
    std::size_t size = 0;
    return f.serialized_fmu_state_size(c, not_a_state, &size);
  });
}

TEST_F(FmuHostileHostTest, ParametersTheLibraryRefusesAreRefusedByName) {
  export_pi(true);
  // Each is refused at fmi2ExitInitializationMode with the parameter's name in the log, and the
  // instance stays in initialisation mode (no step).
  struct BadParameter {
    const Fmu* fmu;
    std::string name;
    double value;
    std::string message;
  };
  const std::vector<BadParameter> cases = {
      {fmu_.get(), "thresholds[3]", -7.0, "thresholds[3] = -7 must be > the element before it"},
      {fmu_.get(), "thresholds[4]", 0.3, "thresholds[4] = 0.29999999999999999 must be >"},
      {fmu_.get(), "thresholds[1]", 0.1, "thresholds[1] = 0.10000000000000001 must be 0"},
      {inverse_.get(), "weights[2]", -1e300,
       "weights[2] = -1.0000000000000001e+300 makes a partial"},
      {inverse_.get(), "input_min", 2.0, "input_min = 2 must be <= the upper limit"}};
  for (const auto& bad : cases) {
    const auto& f = bad.fmu->functions();
    FmuInstance::Log log;
    const fmi2::CallbackFunctions callbacks{&FmuInstance::log_to, std::calloc, std::free, nullptr,
                                            &log};
    fmi2::Component c =
        f.instantiate("bad", fmi2::CoSimulation, bad.fmu->guid().c_str(), "", &callbacks, 0, 0);
    ASSERT_NE(c, nullptr);
    const fmi2::ValueReference reference = bad.fmu->variable(bad.name).reference;
    ASSERT_EQ(f.setup_experiment(c, 0, 0.0, 0.0, 0, 0.0), fmi2::OK);
    ASSERT_EQ(f.enter_initialization_mode(c), fmi2::OK);
    ASSERT_EQ(f.set_real(c, &reference, 1, &bad.value), fmi2::OK);
    EXPECT_EQ(f.exit_initialization_mode(c), fmi2::Error) << bad.name;
    EXPECT_NE(log.text.find(bad.message), std::string::npos) << log.text;
    EXPECT_EQ(f.do_step(c, 0.0, 1e-3, 0), fmi2::Error) << bad.name;
    f.free_instance(c);
  }
}

TEST_F(FmuHostileHostTest, EveryChangedByteOfASavedStateIsRefused) {
  export_pi(true);
  FmuInstance instance(*fmu_);
  const auto bytes = serialised_state(*fmu_, instance);
  const auto& f = fmu_->functions();
  int accepted = 0;
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    auto changed = bytes;
    changed[at] = static_cast<char>(changed[at] ^ 0x10);
    fmi2::FMUstate state = nullptr;
    if (f.deserialize_fmu_state(instance.component(), changed.data(), changed.size(), &state) !=
        fmi2::Error) {
      ++accepted;
      ADD_FAILURE() << "a flip of byte " << at << " of " << bytes.size() << " was accepted";
    }
    EXPECT_EQ(state, nullptr);
  }
  EXPECT_EQ(accepted, 0);
  // The unchanged bytes are taken.
  fmi2::FMUstate state = nullptr;
  EXPECT_EQ(f.deserialize_fmu_state(instance.component(), bytes.data(), bytes.size(), &state),
            fmi2::OK);
  f.free_fmu_state(instance.component(), &state);
}

TEST_F(FmuHostileHostTest, StatesWrittenByTheHostOrForgedAreRefused) {
  export_pi(true);
  FmuInstance instance(*fmu_);
  const auto& f = fmu_->functions();
  const auto bytes = serialised_state(*fmu_, instance);
  // A value written into the memory of a state the FMU handed out: its checksum no longer
  // matches.
  for (const double value : {std::nan(""), -1e300}) {
    fmi2::FMUstate state = nullptr;
    ASSERT_EQ(f.get_fmu_state(instance.component(), &state), fmi2::OK);
    std::memcpy(static_cast<char*>(state) + kFirstStateValueAt, &value, sizeof value);
    EXPECT_EQ(f.set_fmu_state(instance.component(), state), fmi2::Error) << value;
    EXPECT_NE(instance.log().find("checksum"), std::string::npos) << instance.log();
    f.free_fmu_state(instance.component(), &state);
  }
  // Forged bytes with a matching checksum: the contents are checked.
  for (const auto& [at, value] :
       {std::pair{kInputAt, std::nan("")}, std::pair{kInputAt, kInf},
        std::pair{kFirstStateValueAt, std::nan("")}, std::pair{kFirstStateValueAt, -kInf}}) {
    auto forged = bytes;
    forge(forged, at, value);
    fmi2::FMUstate state = nullptr;
    EXPECT_EQ(f.deserialize_fmu_state(instance.component(), forged.data(), forged.size(), &state),
              fmi2::Error)
        << "value " << value << " at byte " << at;
    EXPECT_EQ(state, nullptr);
  }
  // A forged -1e300 that the checks let through must still give a finite output, or be refused.
  auto forged = bytes;
  forge(forged, kFirstStateValueAt, -1e300);
  fmi2::FMUstate state = nullptr;
  if (f.deserialize_fmu_state(instance.component(), forged.data(), forged.size(), &state) ==
      fmi2::OK) {
    ASSERT_EQ(f.set_fmu_state(instance.component(), state), fmi2::OK);
    EXPECT_TRUE(std::isfinite(instance.get(kOutput)));
    f.free_fmu_state(instance.component(), &state);
  }
}

// A forged Preisach memory whose size lies outside its capacity would make the step read past
// the state: it is refused, in a child so that a crash would be seen as one.
TEST_F(FmuHostileHostTest, APreisachMemoryOutOfItsBoundsIsRefused) {
  const auto& entry = ModelRegistry::builtin().find("preisach");
  const auto model = model_from_json(
      {{"model", "preisach"}, {"version", 1}, {"params", entry.example_params}}, "test.json");
  FmuExportOptions options;
  options.code.prefix = "memory";
  const auto files = export_fmu(*model, dir_ / "out", options);
  const Fmu fmu(files.model, dir_ / "memory");
  // The state after the snapshot's header: extrema[capacity], partial[capacity], then the size.
  const std::size_t capacity = 2 * PreisachState::max_pairs + 1;
  const std::size_t size_at = kFirstStateValueAt + 2 * capacity * sizeof(double);
  // The forgery itself is right: a size within the bounds (the memory cut to x_0) is taken.
  {
    FmuInstance instance(fmu);
    auto bytes = serialised_state(fmu, instance);
    forge(bytes, size_at, 1U);
    fmi2::FMUstate state = nullptr;
    EXPECT_EQ(fmu.functions().deserialize_fmu_state(instance.component(), bytes.data(),
                                                    bytes.size(), &state),
              fmi2::OK)
        << instance.log();
    fmu.functions().free_fmu_state(instance.component(), &state);
  }
  for (const unsigned size : {0U, static_cast<unsigned>(capacity) + 1U, 0x7fffffffU}) {
    const Outcome outcome = in_child([&](bool& logged) {
      FmuInstance instance(fmu);
      auto bytes = serialised_state(fmu, instance);
      forge(bytes, size_at, size);
      fmi2::FMUstate state = nullptr;
      const int status = fmu.functions().deserialize_fmu_state(instance.component(), bytes.data(),
                                                               bytes.size(), &state);
      logged = instance.log().find("out of its bounds") != std::string::npos;
      return status;
    });
    EXPECT_EQ(outcome.signal, 0) << "size " << size << ": " << describe(outcome);
    EXPECT_EQ(outcome.status, fmi2::Error) << "size " << size << ": " << describe(outcome);
    EXPECT_TRUE(outcome.logged) << "size " << size << ": " << describe(outcome);
  }
}

TEST_F(FmuHostileHostTest, NonFiniteTargetsGiveTheClampedExtremeWithAWarning) {
  export_pi(true);
  FmuInstance instance(*inverse_);
  for (int k = 0; k < 10; ++k)
    instance.sample(0.1 * k, 1e-3);
  const auto& f = inverse_->functions();
  // The expected answers: the limits of [-1, 1] for +-inf and the overflowing 1e308; NaN holds
  // the input of the last step.
  const double last = instance.get(kOutput);
  struct Target {
    double value;
    double input;
  };
  for (const auto& [target, expected] :
       {Target{1e308, 1.0}, Target{kInf, 1.0}, Target{-kInf, -1.0}, Target{-1e308, -1.0}}) {
    EXPECT_EQ(instance.set(kInput, target), fmi2::Warning) << target;
    EXPECT_EQ(instance.get(kOutput), expected) << target;
    EXPECT_EQ(instance.step(1e-3), fmi2::OK);
    // The state after it (plays out at the target bound) is a valid one: saved, it restores.
    fmi2::FMUstate state = nullptr;
    ASSERT_EQ(f.get_fmu_state(instance.component(), &state), fmi2::OK);
    EXPECT_EQ(f.set_fmu_state(instance.component(), state), fmi2::OK) << instance.log();
    f.free_fmu_state(instance.component(), &state);
    instance.sample(0.5, 1e-3);  // back inside
  }
  const double before_nan = instance.sample(0.42, 1e-3);
  EXPECT_EQ(instance.set(kInput, std::nan("")), fmi2::Warning);
  EXPECT_EQ(instance.get(kOutput), before_nan);
  EXPECT_NE(instance.log().find("target is NaN"), std::string::npos) << instance.log();
  EXPECT_NE(instance.log().find("extreme one"), std::string::npos) << instance.log();
  EXPECT_TRUE(std::isfinite(last));
}

TEST_F(FmuHostileHostTest, WithoutLimitsNonFiniteTargetsStillGiveFiniteInputs) {
  export_pi(false);
  // The limits are infinite: the model description says so in the schema's spelling.
  EXPECT_EQ(inverse_->variable("input_min").start, -kInf);
  const auto node = inverse_->description()
                        .child("fmiModelDescription")
                        .child("ModelVariables")
                        .find_child_by_attribute("ScalarVariable", "name", "input_max");
  EXPECT_STREQ(node.child("Real").attribute("start").value(), "INF");
  FmuInstance instance(*inverse_);
  for (int k = 0; k < 10; ++k)
    instance.sample(0.1 * k, 1e-3);
  for (const double target : {1e308, kInf, -kInf, std::nan(""), -1e308}) {
    instance.set(kInput, target);
    const double input = instance.get(kOutput);
    EXPECT_TRUE(std::isfinite(input)) << target << " gave " << input;
    if (target > 0) {
      EXPECT_GT(input, 1e100) << target;
    }
    if (target < 0) {
      EXPECT_LT(input, -1e100) << target;
    }
    EXPECT_EQ(instance.step(1e-3), fmi2::OK);
    instance.sample(0.5, 1e-3);
    EXPECT_TRUE(std::isfinite(instance.sample(0.3, 1e-3)));  // and the state recovered
  }
}

// Every model kind's inverse (the C export's inverse step inside the FMU): a non-finite or
// overflowing target never gives NaN, and within limits gives the limit.
class FmuInverseKindTest : public FmuHostileHostTest,
                           public testing::WithParamInterface<std::string> {};

TEST_P(FmuInverseKindTest, ClampsNonFiniteTargets) {
  const std::string name = GetParam();
  const auto& entry = ModelRegistry::builtin().find(name);
  const nlohmann::json document = {
      {"model", name}, {"version", 1}, {"params", entry.example_params}};
  const auto model = model_from_json(document, "test.json");
  FmuExportOptions options;
  options.code.prefix = "kind_" + name;
  options.code.limits = {-0.5, 0.5};
  options.inverse = true;
  const auto files = export_fmu(*model, dir_ / "kinds", options);
  Fmu inverse(files.inverse, dir_ / options.code.prefix);
  for (const auto& problem : inverse.description_problems())
    ADD_FAILURE() << name << ": " << problem;
  FmuInstance instance(inverse);
  const double h = inverse.description()
                       .child("fmiModelDescription")
                       .child("DefaultExperiment")
                       .attribute("stepSize")
                       .as_double(1e-3);
  for (const auto& [target, expected] : {std::pair{1e308, 0.5}, std::pair{kInf, 0.5},
                                         std::pair{-kInf, -0.5}, std::pair{-1e308, -0.5}}) {
    EXPECT_EQ(instance.set(kInput, target), fmi2::Warning) << target;
    EXPECT_EQ(instance.get(kOutput), expected) << name << ", target " << target;
    ASSERT_EQ(instance.step(h), fmi2::OK);
    EXPECT_TRUE(std::isfinite(instance.sample(0.0, h))) << name << " after " << target;
  }
  const double held = instance.sample(0.1, h);
  EXPECT_EQ(instance.set(kInput, std::nan("")), fmi2::Warning);
  // The last input, held (the creep models' lags run on with it).
  EXPECT_EQ(instance.get(kOutput), held) << name;
  ASSERT_EQ(instance.step(h), fmi2::OK);
  EXPECT_TRUE(std::isfinite(instance.sample(0.2, h))) << name;
}

INSTANTIATE_TEST_SUITE_P(EveryKindWithAnInverse, FmuInverseKindTest,
                         testing::Values("modified_pi", "gpi", "preisach", "pi_creep",
                                         "modified_pi_creep"));

TEST_F(FmuHostileHostTest, ImportersRestoreAStateIntoAFreshInstance) {
  export_pi(true);
  const auto& f = fmu_->functions();
  // The sequence of common importers: instantiate, set up, initialise, step, save; then a fresh
  // instance (only instantiated) restores the state and steps on, as the first would.
  FmuInstance first(*fmu_);
  for (int k = 0; k < 30; ++k)
    first.sample(0.03 * k, 1e-3);
  fmi2::FMUstate saved = nullptr;
  ASSERT_EQ(f.get_fmu_state(first.component(), &saved), fmi2::OK);
  const auto bytes = serialise(f, first.component(), saved);
  const double expected = first.sample(0.2, 1e-3);

  for (const bool serialised : {false, true}) {
    FmuInstance::Log log;
    const fmi2::CallbackFunctions callbacks{&FmuInstance::log_to, std::calloc, std::free, nullptr,
                                            &log};
    fmi2::Component fresh =
        f.instantiate("fresh", fmi2::CoSimulation, fmu_->guid().c_str(), "", &callbacks, 0, 0);
    ASSERT_NE(fresh, nullptr);
    fmi2::FMUstate state = saved;
    if (serialised) {
      state = nullptr;
      ASSERT_EQ(f.deserialize_fmu_state(fresh, bytes.data(), bytes.size(), &state), fmi2::OK)
          << log.text;
    }
    ASSERT_EQ(f.set_fmu_state(fresh, state), fmi2::OK) << log.text;
    const double input = 0.2;
    double output = 0.0;
    ASSERT_EQ(f.set_real(fresh, &kInput, 1, &input), fmi2::OK);
    ASSERT_EQ(f.get_real(fresh, &kOutput, 1, &output), fmi2::OK);
    EXPECT_EQ(output, expected);
    EXPECT_EQ(f.do_step(fresh, 0.030, 1e-3, 0), fmi2::OK) << log.text;
    if (serialised) f.free_fmu_state(fresh, &state);
    f.free_instance(fresh);
  }
  f.free_fmu_state(first.component(), &saved);
}

}  // namespace
}  // namespace hyst
