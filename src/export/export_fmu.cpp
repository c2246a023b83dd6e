#include "hyst/export/export_fmu.hpp"

#include <cctype>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "c_writer.hpp"
#include "fmu_parts.hpp"
#include "hyst/core/error.hpp"
#include "hyst/export/export_c.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst {
namespace {

void check_name(const std::string& name, std::string_view option) {
  bool valid = !name.empty() &&
               (std::isalpha(static_cast<unsigned char>(name.front())) != 0 || name.front() == '_');
  for (const char c : name)
    valid = valid && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_');
  if (!valid) {
    throw Error(fmt::format("FMU export: the variable name '{}' must start with a letter or '_' "
                            "and hold only letters, digits and '_'",
                            name),
                std::string(option));
  }
}

void check_unit(const std::string& unit, std::string_view option) {
  for (const char c : unit) {
    if (std::isprint(static_cast<unsigned char>(c)) == 0 || c == ' ') {
      throw Error(fmt::format("FMU export: the unit '{}' must be printable characters without "
                              "spaces, e.g. 'V' or 'um'",
                              unit),
                  std::string(option));
    }
  }
}

void check_options(const FmuExportOptions& options, const CCode& code) {
  check_name(options.input_name, "input_name");
  check_name(options.output_name, "output_name");
  if (options.input_name == options.output_name) {
    throw Error(
        fmt::format("FMU export: the input and the output are both named '{}'", options.input_name),
        "output_name");
  }
  for (const auto* fields : {&code.parameters, &code.inverse_parameters}) {
    for (const auto& field : *fields) {
      if (field.name == options.input_name || field.name == options.output_name) {
        throw Error(fmt::format("FMU export: '{}' is a parameter's name; name the input and the "
                                "output otherwise",
                                field.name),
                    field.name == options.input_name ? "input_name" : "output_name");
      }
    }
  }
  check_unit(options.input_unit, "input_unit");
  check_unit(options.output_unit, "output_unit");
}

// "{xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx}" from two digests of the export.
std::string guid_of(std::uint64_t first, std::uint64_t second) {
  const std::string hex = fmt::format("{:016x}{:016x}", first, second);
  return fmt::format("{{{}-{}-{}-{}-{}}}", hex.substr(0, 8), hex.substr(8, 4), hex.substr(12, 4),
                     hex.substr(16, 4), hex.substr(20, 12));
}

// The archive of one FMU.
std::string build_fmu(detail::FmuUnit unit, const FmuExportOptions& options) {
  // The GUID and the saved-state mark change with everything the binary is built from.
  const std::string names =
      fmt::format("{}|{}|{}|{}|{}", unit.identifier, unit.input_name, unit.output_name,
                  unit.model_input_unit, unit.model_output_unit);
  unit.digest = detail::text_digest({unit.code->header, unit.code->source, names});
  unit.guid = guid_of(unit.digest, detail::text_digest({names, unit.code->source}));
  const std::string wrapper = detail::fmu_wrapper(unit);
  const std::string description = detail::fmu_model_description(unit);
  const detail::SourceFile sources[] = {
      {std::string(detail::kFmi2DeclarationsName), detail::fmi2_declarations()},
      {unit.code->header_name, unit.code->header},
      {unit.code->source_name, unit.code->source},
      {unit.wrapper_name(), wrapper}};
  const std::string binary = detail::compile_shared_library(options.compiler, sources);
  std::vector<detail::ArchiveMember> members{
      {"modelDescription.xml", description},
      {fmt::format("binaries/linux64/{}.so", unit.identifier), binary}};
  for (const auto& source : sources)
    members.push_back({"sources/" + source.name, source.text});
  return detail::zip_archive(members);
}

}  // namespace

FmuFiles export_fmu(const DynamicModel& model, const std::filesystem::path& folder,
                    const FmuExportOptions& options) {
  const CCode code = generate_c(model, options.code);
  check_options(options, code);
  if (options.inverse && !code.has_inverse) {
    throw Error(fmt::format("FMU export: the {} model has no inverse to export (its parameters "
                            "are not invertible, or the library has none for it)",
                            model.name()),
                "inverse");
  }
  const std::string prefix = c_export_prefix(model, options.code);
  detail::FmuUnit unit;
  unit.identifier = prefix;
  unit.code = &code;
  unit.c_prefix = prefix;
  unit.input_name = options.input_name;
  unit.output_name = options.output_name;
  unit.model_input_unit = options.input_unit;
  unit.model_output_unit = options.output_unit;
  unit.model_name = model.name();
  unit.source = options.code.source;
  unit.single = options.code.scalar == CScalar::single_precision;

  FmuFiles files;
  files.model = folder / (prefix + ".fmu");
  const std::string model_archive = build_fmu(unit, options);
  std::string inverse_archive;
  if (options.inverse) {
    unit.identifier = prefix + "_inverse";
    unit.inverse = true;
    // The inverse maps the model's output to its input: the names follow the signals.
    unit.input_name = options.output_name;
    unit.output_name = options.input_name;
    files.inverse = folder / (unit.identifier + ".fmu");
    inverse_archive = build_fmu(unit, options);
  }
  try {
    io::create_output_folder(folder);
  } catch (const Error& error) {
    throw Error(fmt::format("FMU export: {}", error.what()), "out");
  }
  std::vector<io::FileContent> contents{{files.model, model_archive}};
  if (options.inverse) contents.push_back({files.inverse, inverse_archive});
  io::write_files_atomically(contents);
  return files;
}

}  // namespace hyst
