#pragma once
// Parsing by an enumeration's name table (hyst/core/enum_names.hpp), with the "expected a, b or c"
// list of the error messages. The header lives in src/core, the lowest layer, so that every layer
// can use it.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/enum_names.hpp"
#include "hyst/core/error.hpp"

namespace hyst::detail {

using hyst::EnumNames;
using hyst::name_of;

// The value named `text`, if the table has that name.
template <class E, std::size_t N>
constexpr std::optional<E> find_named(std::string_view text, const EnumNames<E, N>& names) {
  for (const auto& [value, name] : names) {
    if (name == text) return value;
  }
  return std::nullopt;
}

// The names in table order, "a, b or c": comma-separated, `last_separator` before the last one.
template <class E, std::size_t N>
std::string names_list(const EnumNames<E, N>& names, std::string_view last_separator = " or ") {
  std::string list;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) list += i + 1 == N ? last_separator : std::string_view(", ");
    list += names[i].second;
  }
  return list;
}

// The value named `text`; otherwise throws "unknown <what> '<text>' (expected a, b or c)" about
// `field` (empty: about no field).
template <class E, std::size_t N>
E value_named(std::string_view text, const EnumNames<E, N>& names, std::string_view what,
              std::string field = {}) {
  if (const auto value = find_named(text, names)) return *value;
  throw Error(fmt::format("unknown {} '{}' (expected {})", what, text, names_list(names)),
              std::move(field));
}

}  // namespace hyst::detail
