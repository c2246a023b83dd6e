#pragma once
// A fitted tabulated Preisach model (fit_preisach_forcs) wrapped by the 'tabulated_preisach'
// registry entry (tabulated_preisach_entry.cpp), in its initial state.

#include <memory>

#include "hyst/models/preisach.hpp"
#include "hyst/registry/dynamic_model.hpp"

namespace hyst::detail {

std::unique_ptr<DynamicModel> tabulated_preisach_model(TabulatedPreisach model);

}  // namespace hyst::detail
