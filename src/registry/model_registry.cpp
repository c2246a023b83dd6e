#include "hyst/registry/model_registry.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "model_entries.hpp"

namespace hyst {

const ModelRegistry& ModelRegistry::builtin() {
  // Built explicitly rather than by self-registering statics, which a static library's linker
  // would drop.
  static const ModelRegistry registry = [] {
    ModelRegistry r;
    r.add(detail::prandtl_ishlinskii_entry());
    r.add(detail::generalized_prandtl_ishlinskii_entry());
    r.add(detail::preisach_entry());
    r.add(detail::tabulated_preisach_entry());
    r.add(detail::ikuta_sma_entry());
    r.add(detail::krasnoselskii_pokrovskii_entry());
    r.add(detail::maxwell_slip_entry());
    r.add(detail::modified_prandtl_ishlinskii_entry());
    r.add(detail::rate_dependent_prandtl_ishlinskii_entry());
    r.add(detail::prandtl_ishlinskii_creep_entry());
    r.add(detail::modified_prandtl_ishlinskii_creep_entry());
    r.add(detail::butterfly_strain_entry());
    r.add(detail::butterfly_strain_creep_entry());
    r.add(detail::bouc_wen_entry());
    r.add(detail::bouc_wen_oscillator_entry());
    r.add(detail::duhem_entry());
    r.add(detail::backlash_like_entry());
    r.add(detail::jiles_atherton_entry());
    r.add(detail::narx_entry());
    return r;
  }();
  return registry;
}

const ModelEntry* ModelRegistry::find_if_known(std::string_view name) const {
  for (const auto& entry : entries_) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

const ModelEntry& ModelRegistry::find(std::string_view name) const {
  if (const auto* entry = find_if_known(name)) return *entry;
  throw Error(fmt::format("unknown model '{}' (known: {})", name, names()));
}

std::string ModelRegistry::names() const {
  std::string list;
  for (const auto& entry : entries_)
    list += (list.empty() ? "" : ", ") + entry.name;
  return list;
}

void ModelRegistry::add(ModelEntry entry) {
  if (find_if_known(entry.name)) {
    throw Error(fmt::format("model '{}' is registered twice", entry.name));
  }
  entries_.push_back(std::move(entry));
}

bool fits_sample_time(const ModelEntry& entry) {
  return std::any_of(entry.fit_options.begin(), entry.fit_options.end(),
                     [](const ParameterInfo& option) { return option.name == "sample_time"; });
}

nlohmann::json with_sample_time(const ModelEntry& entry, nlohmann::json options,
                                std::optional<double> seconds) {
  if (seconds && fits_sample_time(entry) && !options.contains("sample_time"))
    options["sample_time"] = *seconds;
  return options;
}

}  // namespace hyst
