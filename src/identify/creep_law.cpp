#include "hyst/identify/creep_law.hpp"

#include <string>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst {

CreepLaw creep_law_from_string(std::string_view text) {
  if (text == "free") return CreepLaw::free;
  if (text == "logarithmic") return CreepLaw::logarithmic;
  throw Error(fmt::format("creep_law = '{}': expected free or logarithmic", text), "creep_law");
}

std::string_view to_string(CreepLaw law) {
  return law == CreepLaw::logarithmic ? "logarithmic" : "free";
}

}  // namespace hyst
