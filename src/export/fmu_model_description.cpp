// modelDescription.xml of an FMU (fmu_parts.hpp), as the FMI 2.0 standard's schema
// (fmi2ModelDescription.xsd) describes it.

#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>

#include "fmu_parts.hpp"
#include "hyst/io/xml_text.hpp"

namespace hyst::detail {
namespace {

std::string unit_attribute(const std::string& unit) {
  return unit.empty() ? std::string() : fmt::format(" unit=\"{}\"", io::xml_escaped(unit));
}

// An xs:double in its lexical form: INF and -INF for the infinities (the schema's spelling;
// "inf" is no xs:double and a validating importer refuses the file).
std::string number(double value) {
  if (std::isinf(value)) return value > 0.0 ? "INF" : "-INF";
  return fmt::format("{:.17g}", value);
}

}  // namespace

std::string fmu_variable_name(const CParameterField& field, std::size_t k) {
  return field.array ? fmt::format("{}[{}]", field.name, k + 1) : field.name;
}

std::string FmuUnit::unit_name(CUnit unit) const {
  const bool both = !model_input_unit.empty() && !model_output_unit.empty();
  switch (unit) {
    case CUnit::input:
      return model_input_unit;
    case CUnit::output:
      return model_output_unit;
    case CUnit::output_per_input:
      return both ? fmt::format("{}/{}", model_output_unit, model_input_unit) : std::string();
    case CUnit::input_per_output:
      return both ? fmt::format("{}/{}", model_input_unit, model_output_unit) : std::string();
    case CUnit::seconds:
      return "s";
    case CUnit::none:
      break;
  }
  return {};
}

std::string fmu_model_description(const FmuUnit& unit) {
  std::set<std::string> units;
  const auto use = [&](const std::string& name) {
    if (!name.empty()) units.insert(name);
    return unit_attribute(name);
  };

  // One <ScalarVariable>: `attributes` after the causality, `real` inside <Real .../>.
  const auto variable = [](std::string_view name, unsigned reference, std::string_view causality,
                           std::string_view attributes, std::string_view description,
                           std::string_view real) {
    return fmt::format(
        "    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"{}\" {} "
        "description=\"{}\">\n      <Real{}/>\n    </ScalarVariable>\n",
        io::xml_escaped(name), reference, causality, attributes, io::xml_escaped(description),
        real);
  };
  std::string variables =
      variable(unit.input_name, 0, "input", "variability=\"continuous\"",
               unit.inverse ? "the model's output to reach (the target)" : "the model's input",
               " start=\"0\"" + use(unit.input_unit())) +
      variable(
          unit.output_name, 1, "output", "variability=\"continuous\" initial=\"calculated\"",
          unit.inverse ? "the input that makes the model produce the target" : "the model's output",
          use(unit.output_unit()));
  unsigned reference = 2;
  for (const auto& field : unit.parameters()) {
    const std::string unit_text = use(unit.unit_name(field.unit));
    for (std::size_t k = 0; k < field.values.size(); ++k, ++reference) {
      variables += variable(fmu_variable_name(field, k), reference, "parameter",
                            "variability=\"fixed\" initial=\"exact\"", field.description,
                            fmt::format(" start=\"{}\"{}", number(field.values[k]), unit_text));
    }
  }

  std::string unit_definitions;
  if (!units.empty()) {
    unit_definitions = "  <UnitDefinitions>\n";
    for (const auto& name : units)
      unit_definitions += fmt::format("    <Unit name=\"{}\"/>\n", io::xml_escaped(name));
    unit_definitions += "  </UnitDefinitions>\n";
  }
  const double sample_time = unit.code->sample_time;
  const std::string description =
      fmt::format("hyst {} model{}{}", unit.model_name, unit.inverse ? ", inverse compensator" : "",
                  unit.source.empty() ? std::string() : fmt::format(" (from {})", unit.source));
  return fmt::format(
      R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="{id}" guid="{guid}" description="{description}"
  generationTool="hyst" variableNamingConvention="structured" numberOfEventIndicators="0">
  <CoSimulation modelIdentifier="{id}" canHandleVariableCommunicationStepSize="{variable}"
    canInterpolateInputs="false" maxOutputDerivativeOrder="0" canRunAsynchronuously="false"
    canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="false"
    canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="true">
    <SourceFiles>
      <File name="{c_source}"/>
      <File name="{wrapper}"/>
    </SourceFiles>
  </CoSimulation>
{units}  <LogCategories>
    <Category name="logStatusError" description="the reason of every fmi2Error"/>
  </LogCategories>
  <DefaultExperiment startTime="0"{step}/>
  <ModelVariables>
{variables}  </ModelVariables>
  <ModelStructure>
    <Outputs>
      <Unknown index="2" dependencies="1" dependenciesKind="dependent"/>
    </Outputs>
    <InitialUnknowns>
      <Unknown index="2" dependencies="1"/>
    </InitialUnknowns>
  </ModelStructure>
</fmiModelDescription>
)",
      fmt::arg("id", unit.identifier), fmt::arg("guid", unit.guid),
      fmt::arg("description", io::xml_escaped(description)),
      fmt::arg("variable", unit.variable_step() ? "true" : "false"),
      fmt::arg("c_source", unit.code->source_name), fmt::arg("wrapper", unit.wrapper_name()),
      fmt::arg("units", unit_definitions),
      fmt::arg("step", sample_time > 0.0 ? fmt::format(" stepSize=\"{}\"", number(sample_time))
                                         : std::string()),
      fmt::arg("variables", variables));
}

}  // namespace hyst::detail
