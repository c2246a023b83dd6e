#include "fmu_host.hpp"

#include <dlfcn.h>
#include <zip.h>

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace hyst::test {
namespace {

void unpack(const std::filesystem::path& file, const std::filesystem::path& folder) {
  int error = 0;
  zip_t* archive = zip_open(file.c_str(), ZIP_RDONLY, &error);
  if (archive == nullptr) throw std::runtime_error(fmt::format("cannot open '{}'", file.string()));
  std::filesystem::create_directories(folder);
  const zip_int64_t count = zip_get_num_entries(archive, 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    zip_stat_t stat;
    zip_stat_index(archive, static_cast<zip_uint64_t>(i), 0, &stat);
    const std::string name = stat.name;
    if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos)
      throw std::runtime_error(fmt::format("unsafe member '{}' in '{}'", name, file.string()));
    const auto target = folder / name;
    if (name.back() == '/') {
      std::filesystem::create_directories(target);
      continue;
    }
    std::filesystem::create_directories(target.parent_path());
    std::string bytes(static_cast<std::size_t>(stat.size), '\0');
    zip_file_t* member = zip_fopen_index(archive, static_cast<zip_uint64_t>(i), 0);
    const zip_int64_t read = zip_fread(member, bytes.data(), stat.size);
    zip_fclose(member);
    if (read != static_cast<zip_int64_t>(stat.size))
      throw std::runtime_error(fmt::format("cannot read '{}' in '{}'", name, file.string()));
    std::ofstream(target, std::ios::binary) << bytes;
  }
  zip_close(archive);
}

template <class F>
void resolve(void* library, const char* name, F& function) {
  function = reinterpret_cast<F>(::dlsym(library, name));
  if (function == nullptr) throw std::runtime_error(fmt::format("the binary lacks {}", name));
}

// The lexical form of xs:double (XML Schema part 2, 3.2.5): a decimal with an optional exponent,
// INF, -INF or NaN; "inf", "nan" or "1e" are not one.
bool is_xs_double(const char* text) {
  static const std::regex form(
      R"(\s*((\+|-)?([0-9]+(\.[0-9]*)?|\.[0-9]+)([Ee](\+|-)?[0-9]+)?|(\+|-)?INF|NaN)\s*)");
  return std::regex_match(text, form);
}

bool one_of(const std::string& value, std::initializer_list<const char*> allowed) {
  for (const char* a : allowed)
    if (value == a) return true;
  return false;
}

}  // namespace

Fmu::Fmu(const std::filesystem::path& file, const std::filesystem::path& folder) : folder_(folder) {
  unpack(file, folder);
  const auto parsed = description_.load_file((folder / "modelDescription.xml").c_str());
  if (!parsed) {
    throw std::runtime_error(
        fmt::format("modelDescription.xml of '{}': {}", file.string(), parsed.description()));
  }
  const auto root = description_.child("fmiModelDescription");
  identifier_ = root.child("CoSimulation").attribute("modelIdentifier").value();
  guid_ = root.attribute("guid").value();
  for (const auto& node : root.child("ModelVariables").children("ScalarVariable")) {
    FmuVariable variable;
    variable.name = node.attribute("name").value();
    variable.reference = node.attribute("valueReference").as_uint();
    variable.causality = node.attribute("causality").as_string("local");
    const auto real = node.child("Real");
    variable.unit = real.attribute("unit").value();
    variable.has_start = !real.attribute("start").empty();
    variable.start = real.attribute("start").as_double();
    variables_.push_back(variable);
  }
  const auto binary = folder / "binaries" / "linux64" / (identifier_ + ".so");
  library_ = ::dlopen(binary.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library_ == nullptr) throw std::runtime_error(fmt::format("dlopen: {}", ::dlerror()));
  auto& f = functions_;
  resolve(library_, "fmi2GetTypesPlatform", f.get_types_platform);
  resolve(library_, "fmi2GetVersion", f.get_version);
  resolve(library_, "fmi2Instantiate", f.instantiate);
  resolve(library_, "fmi2FreeInstance", f.free_instance);
  resolve(library_, "fmi2SetupExperiment", f.setup_experiment);
  resolve(library_, "fmi2EnterInitializationMode", f.enter_initialization_mode);
  resolve(library_, "fmi2ExitInitializationMode", f.exit_initialization_mode);
  resolve(library_, "fmi2Terminate", f.terminate);
  resolve(library_, "fmi2Reset", f.reset);
  resolve(library_, "fmi2GetReal", f.get_real);
  resolve(library_, "fmi2SetReal", f.set_real);
  resolve(library_, "fmi2GetInteger", f.get_integer);
  resolve(library_, "fmi2GetFMUstate", f.get_fmu_state);
  resolve(library_, "fmi2SetFMUstate", f.set_fmu_state);
  resolve(library_, "fmi2FreeFMUstate", f.free_fmu_state);
  resolve(library_, "fmi2SerializedFMUstateSize", f.serialized_fmu_state_size);
  resolve(library_, "fmi2SerializeFMUstate", f.serialize_fmu_state);
  resolve(library_, "fmi2DeSerializeFMUstate", f.deserialize_fmu_state);
  resolve(library_, "fmi2GetDirectionalDerivative", f.get_directional_derivative);
  resolve(library_, "fmi2DoStep", f.do_step);
  resolve(library_, "fmi2GetRealStatus", f.get_real_status);
  resolve(library_, "fmi2GetStatus", f.get_status);
  resolve(library_, "fmi2GetBooleanStatus", f.get_boolean_status);
  resolve(library_, "fmi2SetDebugLogging", f.set_debug_logging);
  resolve(library_, "fmi2CancelStep", f.cancel_step);
  // The rest of the co-simulation interface must be there too, even where unused here.
  for (const char* name :
       {"fmi2SetDebugLogging", "fmi2GetBoolean", "fmi2GetString", "fmi2SetInteger",
        "fmi2SetBoolean", "fmi2SetString", "fmi2SetRealInputDerivatives",
        "fmi2GetRealOutputDerivatives", "fmi2CancelStep", "fmi2GetStatus", "fmi2GetIntegerStatus",
        "fmi2GetBooleanStatus", "fmi2GetStringStatus"}) {
    if (::dlsym(library_, name) == nullptr)
      throw std::runtime_error(fmt::format("the binary lacks {}", name));
  }
}

Fmu::~Fmu() {
  if (library_ != nullptr) ::dlclose(library_);
}

const FmuVariable& Fmu::variable(const std::string& name) const {
  for (const auto& variable : variables_)
    if (variable.name == name) return variable;
  throw std::runtime_error(fmt::format("no variable '{}'", name));
}

std::string Fmu::capability(const char* name) const {
  return description_.child("fmiModelDescription").child("CoSimulation").attribute(name).value();
}

std::vector<std::string> Fmu::description_problems() const {
  std::vector<std::string> problems;
  const auto root = description_.child("fmiModelDescription");
  if (std::string(root.attribute("fmiVersion").value()) != "2.0")
    problems.push_back("fmiVersion is not 2.0");
  if (guid_.empty()) problems.push_back("no guid");
  if (std::string(root.attribute("modelName").value()).empty()) problems.push_back("no modelName");
  for (const char* attribute : {"startTime", "stopTime", "tolerance", "stepSize"}) {
    const auto value = root.child("DefaultExperiment").attribute(attribute);
    if (!value.empty() && !is_xs_double(value.value()))
      problems.push_back(
          fmt::format("DefaultExperiment {} '{}' is not an xs:double", attribute, value.value()));
  }
  const auto co_simulation = root.child("CoSimulation");
  if (!co_simulation) problems.push_back("no CoSimulation element");
  if (identifier_.empty()) problems.push_back("no modelIdentifier");
  for (const auto& file : co_simulation.child("SourceFiles").children("File")) {
    if (!std::filesystem::exists(folder_ / "sources" / file.attribute("name").value()))
      problems.push_back(
          fmt::format("source '{}' is not in sources/", file.attribute("name").value()));
  }

  std::set<std::string> units;
  for (const auto& unit : root.child("UnitDefinitions").children("Unit"))
    units.insert(unit.attribute("name").value());
  std::set<std::string> names;
  std::map<std::string, std::set<unsigned>> references;  // per type
  std::vector<std::string> causalities;
  for (const auto& node : root.child("ModelVariables").children("ScalarVariable")) {
    const std::string name = node.attribute("name").value();
    const std::string causality = node.attribute("causality").as_string("local");
    const std::string variability = node.attribute("variability").as_string("continuous");
    const std::string initial = node.attribute("initial").value();
    causalities.push_back(causality);
    if (name.empty() || !names.insert(name).second)
      problems.push_back(fmt::format("variable name '{}' is empty or not unique", name));
    std::string type;
    int types = 0;
    for (const auto& child : node.children()) {
      if (one_of(child.name(), {"Real", "Integer", "Boolean", "String", "Enumeration"})) {
        type = child.name();
        ++types;
      }
    }
    if (types != 1) problems.push_back(fmt::format("'{}' has {} type elements", name, types));
    if (node.attribute("valueReference").empty() ||
        !references[type].insert(node.attribute("valueReference").as_uint()).second)
      problems.push_back(fmt::format("'{}': value reference missing or not unique", name));
    if (!one_of(causality,
                {"parameter", "calculatedParameter", "input", "output", "local", "independent"}))
      problems.push_back(fmt::format("'{}': causality '{}'", name, causality));
    if (!one_of(variability, {"constant", "fixed", "tunable", "discrete", "continuous"}))
      problems.push_back(fmt::format("'{}': variability '{}'", name, variability));
    // The combinations the standard allows (FMI 2.0, section 2.2.7, table of causality and
    // variability).
    const bool combination_ok =
        (causality == "parameter" && one_of(variability, {"fixed", "tunable"})) ||
        (causality == "calculatedParameter" && one_of(variability, {"fixed", "tunable"})) ||
        (causality == "input" && one_of(variability, {"discrete", "continuous"})) ||
        (causality == "output" && one_of(variability, {"constant", "discrete", "continuous"})) ||
        (causality == "local") || (causality == "independent" && variability == "continuous");
    if (!combination_ok)
      problems.push_back(fmt::format("'{}': causality {} with variability {} is not allowed", name,
                                     causality, variability));
    if (variability == "continuous" && type != "Real")
      problems.push_back(fmt::format("'{}': only a Real can be continuous", name));
    const auto typed = node.child(type.c_str());
    const bool has_start = !typed.attribute("start").empty();
    if ((causality == "parameter" || causality == "input") && !has_start)
      problems.push_back(fmt::format("'{}': a {} needs a start value", name, causality));
    if (causality == "parameter" && !one_of(initial, {"", "exact", "approx"}))
      problems.push_back(fmt::format("'{}': a parameter's initial must be exact", name));
    if (causality == "input" && !initial.empty())
      problems.push_back(fmt::format("'{}': an input has no initial attribute", name));
    if (initial == "calculated" && has_start)
      problems.push_back(fmt::format("'{}': a calculated variable has no start value", name));
    if (type == "Real") {
      for (const char* attribute : {"start", "min", "max", "nominal"}) {
        const auto value = typed.attribute(attribute);
        if (!value.empty() && !is_xs_double(value.value()))
          problems.push_back(
              fmt::format("'{}': {} '{}' is not an xs:double", name, attribute, value.value()));
      }
    }
    const std::string unit = typed.attribute("unit").value();
    if (!unit.empty() && units.count(unit) == 0)
      problems.push_back(fmt::format("'{}': unit '{}' is not in UnitDefinitions", name, unit));
  }

  // Outputs: exactly the variables of causality output, by their 1-based index.
  const auto structure = root.child("ModelStructure");
  std::set<std::size_t> listed;
  for (const auto& unknown : structure.child("Outputs").children("Unknown")) {
    const std::size_t index = unknown.attribute("index").as_uint();
    if (index == 0 || index > causalities.size() || causalities[index - 1] != "output")
      problems.push_back(fmt::format("Outputs lists index {}, not an output", index));
    listed.insert(index);
    std::istringstream dependencies(unknown.attribute("dependencies").value());
    std::size_t dependency = 0;
    while (dependencies >> dependency) {
      if (dependency == 0 || dependency > causalities.size())
        problems.push_back(fmt::format("dependency {} is not a variable", dependency));
    }
  }
  for (std::size_t i = 0; i < causalities.size(); ++i) {
    if (causalities[i] == "output" && listed.count(i + 1) == 0)
      problems.push_back(fmt::format("output {} missing from ModelStructure/Outputs", i + 1));
  }
  for (const auto& unknown : structure.child("InitialUnknowns").children("Unknown")) {
    const std::size_t index = unknown.attribute("index").as_uint();
    if (index == 0 || index > causalities.size())
      problems.push_back(fmt::format("InitialUnknowns lists index {}", index));
  }
  return problems;
}

void FmuInstance::log_to(fmi2::ComponentEnvironment environment, fmi2::String instance,
                         fmi2::Status status, fmi2::String category, fmi2::String message, ...) {
  auto* log = static_cast<Log*>(environment);
  char buffer[2048];
  va_list arguments;
  va_start(arguments, message);
  std::vsnprintf(buffer, sizeof buffer, message, arguments);
  va_end(arguments);
  log->text += fmt::format("[{}] status {} ({}): {}\n", instance, static_cast<int>(status),
                           category, buffer);
}

FmuInstance::FmuInstance(const Fmu& fmu, const std::string& guid,
                         const std::vector<std::pair<fmi2::ValueReference, double>>& parameters)
    : fmu_(fmu), callbacks_{&FmuInstance::log_to, std::calloc, std::free, nullptr, &log_} {
  const auto& f = fmu.functions();
  component_ =
      f.instantiate("test", fmi2::CoSimulation, guid.empty() ? fmu.guid().c_str() : guid.c_str(),
                    "", &callbacks_, 0, 0);
  if (component_ == nullptr) throw std::runtime_error("fmi2Instantiate failed: " + log_.text);
  bool ok = f.setup_experiment(component_, 0, 0.0, 0.0, 0, 0.0) == fmi2::OK &&
            f.enter_initialization_mode(component_) == fmi2::OK;
  for (const auto& [reference, value] : parameters)
    ok = ok && f.set_real(component_, &reference, 1, &value) == fmi2::OK;
  ok = ok && f.exit_initialization_mode(component_) == fmi2::OK;
  if (!ok) {
    f.free_instance(component_);
    throw std::runtime_error("initialisation failed: " + log_.text);
  }
}

FmuInstance::~FmuInstance() {
  fmu_.functions().terminate(component_);
  fmu_.functions().free_instance(component_);
}

double FmuInstance::sample(double input, double h) {
  const fmi2::ValueReference in = 0;
  const fmi2::ValueReference out = 1;
  double output = 0.0;
  const auto& f = fmu_.functions();
  if (f.set_real(component_, &in, 1, &input) != fmi2::OK ||
      f.get_real(component_, &out, 1, &output) != fmi2::OK ||
      f.do_step(component_, time_, h, 1) != fmi2::OK) {
    throw std::runtime_error("a sample failed: " + log_.text);
  }
  time_ += h;
  return output;
}

double FmuInstance::get(fmi2::ValueReference reference) const {
  double value = 0.0;
  if (fmu_.functions().get_real(component_, &reference, 1, &value) != fmi2::OK)
    throw std::runtime_error("fmi2GetReal failed: " + log_.text);
  return value;
}

fmi2::Status FmuInstance::set(fmi2::ValueReference reference, double value) {
  return fmu_.functions().set_real(component_, &reference, 1, &value);
}

fmi2::Status FmuInstance::step(double h) {
  const fmi2::Status status = fmu_.functions().do_step(component_, time_, h, 1);
  if (status == fmi2::OK) time_ += h;
  return status;
}

}  // namespace hyst::test
