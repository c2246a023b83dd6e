#pragma once
// An FMI 2.0 co-simulation importer for the tests: unpacks an FMU, checks its
// modelDescription.xml against the rules of the standard that an importer relies on, loads its
// binary and drives it. The FMI types and signatures are declared here from the standard's text,
// apart from the exporter's own declarations, so that a mismatch between the two shows.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <pugixml.hpp>

namespace hyst::test {

namespace fmi2 {
using Component = void*;
using ComponentEnvironment = void*;
using FMUstate = void*;
using ValueReference = unsigned int;
using Real = double;
using Integer = int;
using Boolean = int;
using String = const char*;
using Byte = char;
enum Status : int { OK, Warning, Discard, Error, Fatal, Pending };
enum Type : int { ModelExchange, CoSimulation };

using Logger = void (*)(ComponentEnvironment, String, Status, String, String, ...);
struct CallbackFunctions {
  Logger logger;
  void* (*allocate_memory)(std::size_t, std::size_t);
  void (*free_memory)(void*);
  void (*step_finished)(ComponentEnvironment, Status);
  ComponentEnvironment environment;
};

// The functions of a co-simulation FMU, resolved from its binary.
struct Functions {
  const char* (*get_types_platform)();
  const char* (*get_version)();
  Component (*instantiate)(String, Type, String, String, const CallbackFunctions*, Boolean,
                           Boolean);
  void (*free_instance)(Component);
  Status (*setup_experiment)(Component, Boolean, Real, Real, Boolean, Real);
  Status (*enter_initialization_mode)(Component);
  Status (*exit_initialization_mode)(Component);
  Status (*terminate)(Component);
  Status (*reset)(Component);
  Status (*get_real)(Component, const ValueReference*, std::size_t, Real*);
  Status (*set_real)(Component, const ValueReference*, std::size_t, const Real*);
  Status (*get_integer)(Component, const ValueReference*, std::size_t, Integer*);
  Status (*get_fmu_state)(Component, FMUstate*);
  Status (*set_fmu_state)(Component, FMUstate);
  Status (*free_fmu_state)(Component, FMUstate*);
  Status (*serialized_fmu_state_size)(Component, FMUstate, std::size_t*);
  Status (*serialize_fmu_state)(Component, FMUstate, Byte*, std::size_t);
  Status (*deserialize_fmu_state)(Component, const Byte*, std::size_t, FMUstate*);
  Status (*get_directional_derivative)(Component, const ValueReference*, std::size_t,
                                       const ValueReference*, std::size_t, const Real*, Real*);
  Status (*do_step)(Component, Real, Real, Boolean);
  Status (*get_real_status)(Component, int, Real*);
  Status (*get_status)(Component, int, Status*);
  Status (*get_boolean_status)(Component, int, Boolean*);
  Status (*set_debug_logging)(Component, Boolean, std::size_t, const String*);
  Status (*cancel_step)(Component);
};
}  // namespace fmi2

// One variable of modelDescription.xml.
struct FmuVariable {
  std::string name;
  fmi2::ValueReference reference = 0;
  std::string causality;
  std::string unit;
  bool has_start = false;
  double start = 0.0;
};

class Fmu {
 public:
  // Unpacks `file` into `folder` (which must not exist yet), reads its model description and
  // loads its linux64 binary. Throws std::runtime_error naming what is missing.
  Fmu(const std::filesystem::path& file, const std::filesystem::path& folder);
  ~Fmu();
  Fmu(const Fmu&) = delete;
  Fmu& operator=(const Fmu&) = delete;

  // Every broken rule of modelDescription.xml, one sentence each; empty for a valid one.
  std::vector<std::string> description_problems() const;

  const std::filesystem::path& folder() const { return folder_; }
  const std::string& identifier() const { return identifier_; }
  const std::string& guid() const { return guid_; }
  const pugi::xml_document& description() const { return description_; }
  const std::vector<FmuVariable>& variables() const { return variables_; }
  const FmuVariable& variable(const std::string& name) const;
  const fmi2::Functions& functions() const { return functions_; }
  // The value of an attribute of <CoSimulation>.
  std::string capability(const char* name) const;

 private:
  std::filesystem::path folder_;
  pugi::xml_document description_;
  std::string identifier_;
  std::string guid_;
  std::vector<FmuVariable> variables_;
  void* library_ = nullptr;
  fmi2::Functions functions_{};
};

// One instance in stepping mode, freed on destruction; errors it logs are collected.
class FmuInstance {
 public:
  // Instantiates with `guid` (the FMU's own by default), sets `parameters` (value reference,
  // value) in initialisation mode and leaves it. Throws std::runtime_error when a call fails.
  explicit FmuInstance(const Fmu& fmu, const std::string& guid = {},
                       const std::vector<std::pair<fmi2::ValueReference, double>>& parameters = {});
  ~FmuInstance();
  FmuInstance(const FmuInstance&) = delete;
  FmuInstance& operator=(const FmuInstance&) = delete;

  fmi2::Component component() const { return component_; }
  const fmi2::Functions& call() const { return fmu_.functions(); }
  // The messages the FMU logged, joined by newlines.
  const std::string& log() const { return log_.text; }

  // set input, read output, step by h: the output for `input` at the current point.
  double sample(double input, double h);
  double get(fmi2::ValueReference reference) const;
  fmi2::Status set(fmi2::ValueReference reference, double value);
  // fmi2DoStep from the current point by h; the time moves on when it succeeds.
  fmi2::Status step(double h);
  double time() const { return time_; }

  // What a logger collects: every message, one line each.
  struct Log {
    std::string text;
  };
  // A logger callback for any instance whose component environment is a Log.
  static void log_to(fmi2::ComponentEnvironment environment, fmi2::String instance,
                     fmi2::Status status, fmi2::String category, fmi2::String message, ...);

 private:
  const Fmu& fmu_;
  Log log_;
  fmi2::CallbackFunctions callbacks_;
  fmi2::Component component_ = nullptr;
  double time_ = 0.0;
};

}  // namespace hyst::test
