#include "hyst/export/export_c.hpp"

#include <cctype>
#include <system_error>

#include <fmt/format.h>

#include "c_emitters.hpp"
#include "c_writer.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"

namespace hyst {
namespace {

using Emitter = detail::CModelCode (*)(const DynamicModel&, const detail::CWriter&,
                                       const CExportOptions&);

struct Supported {
  std::string_view name;
  Emitter emit;
};

constexpr Supported kSupported[] = {
    {"pi", &detail::emit_prandtl_ishlinskii_c},
    {"gpi", &detail::emit_generalized_prandtl_ishlinskii_c},
    {"modified_pi", &detail::emit_modified_prandtl_ishlinskii_c},
    {"preisach", &detail::emit_preisach_c},
    {"bouc_wen", &detail::emit_bouc_wen_c},
};

std::string checked_prefix(const CExportOptions& options, std::string_view model) {
  const std::string prefix =
      options.prefix.empty() ? fmt::format("hyst_{}", model) : options.prefix;
  const bool starts_well =
      std::isalpha(static_cast<unsigned char>(prefix.front())) != 0 || prefix.front() == '_';
  bool identifier = starts_well;
  for (const char c : prefix)
    identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_');
  if (!identifier) {
    throw Error(fmt::format("C export prefix '{}' must be a C identifier (letters, digits and '_', "
                            "not starting with a digit)",
                            prefix),
                "prefix");
  }
  return prefix;
}

}  // namespace

CCode generate_c(const DynamicModel& model, const CExportOptions& options) {
  for (const auto& supported : kSupported) {
    if (supported.name != model.name()) continue;
    const detail::CWriter writer(checked_prefix(options, model.name()), options.scalar);
    return detail::assemble_c_files(writer, supported.emit(model, writer, options), options.source);
  }
  std::string names;
  for (const auto& supported : kSupported)
    names += fmt::format("{}{}", names.empty() ? "" : ", ", supported.name);
  throw Error(
      fmt::format("C export: the model '{}' is not supported (supported: {})", model.name(), names),
      "model");
}

void write_c(const CCode& code, const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw Error(fmt::format("C export: the output folder '{}' does not exist or is not a folder",
                            folder.string()),
                "out");
  }
  const io::FileContent files[] = {{folder / code.header_name, code.header},
                                   {folder / code.source_name, code.source}};
  io::write_files_atomically(files);
}

CCode export_c(const DynamicModel& model, const std::filesystem::path& folder,
               const CExportOptions& options) {
  CCode code = generate_c(model, options);
  write_c(code, folder);
  return code;
}

}  // namespace hyst
