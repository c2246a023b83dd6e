#include "hyst/export/export_c.hpp"

#include <cctype>
#include <system_error>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/output_paths.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {
namespace {}  // namespace

bool is_c_identifier(std::string_view name) {
  bool identifier = !name.empty() && (std::isalpha(static_cast<unsigned char>(name.front())) != 0 ||
                                      name.front() == '_');
  for (const char c : name)
    identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_');
  return identifier;
}

std::string c_export_prefix(const DynamicModel& model, const CExportOptions& options) {
  const std::string prefix =
      options.prefix.empty() ? fmt::format("hyst_{}", model.name()) : options.prefix;
  if (!is_c_identifier(prefix)) {
    throw Error(fmt::format("C export prefix '{}' must be a C identifier (letters, digits and '_', "
                            "not starting with a digit)",
                            prefix),
                "prefix");
  }
  return prefix;
}

CCode generate_c(const DynamicModel& model, const CExportOptions& options) {
  // The model's entry provides its C code; the supported models are the entries that do.
  const auto& registry = ModelRegistry::builtin();
  if (const auto* entry = registry.find_if_known(model.name()); entry && entry->can_export_c()) {
    CExportOptions checked = options;
    checked.prefix = c_export_prefix(model, options);
    return entry->c_code(model, checked);
  }
  std::string names;
  for (const auto& entry : registry.entries()) {
    if (entry.can_export_c()) names += fmt::format("{}{}", names.empty() ? "" : ", ", entry.name);
  }
  throw Error(
      fmt::format("C export: the model '{}' is not supported (supported: {})", model.name(), names),
      "model");
}

void write_c(const CCode& code, const std::filesystem::path& folder) {
  try {
    io::create_output_folder(folder);
  } catch (const Error& error) {
    throw Error(fmt::format("C export: {}", error.what()), "out");
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
