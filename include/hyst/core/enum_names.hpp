#pragma once
// The names of an enumeration, declared once next to it: the header of an enumeration E defines
//
//   constexpr EnumNames<E, N> enumerator_names(E) { return {{{E::a, "a"}, {E::b, "b"}}}; }
//
// in E's namespace, and to_string(E), the parsers and the name lists of their error messages are
// all derived from that table, so a value added to it is spelled, parsed and listed alike.

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

namespace hyst {

//! Each value of an enumeration with its name, in the order error messages list them.
template <class E, std::size_t N>
using EnumNames = std::array<std::pair<E, std::string_view>, N>;

//! An enumeration whose namespace defines `enumerator_names(E)` (found by argument-dependent
//! lookup).
template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E value) {
  enumerator_names(value);
};

//! The name table of a named enumeration.
template <NamedEnum E>
inline constexpr auto enum_names = enumerator_names(E{});

//! The name of `value` in `names`; "unknown" for a value that is not in the table.
template <class E, std::size_t N>
constexpr std::string_view name_of(E value, const EnumNames<E, N>& names) {
  for (const auto& [known, name] : names) {
    if (known == value) return name;
  }
  return "unknown";
}

//! The name of `value` as model files, the CLI and Python spell it.
template <NamedEnum E>
constexpr std::string_view to_string(E value) {
  return name_of(value, enum_names<E>);
}

}  // namespace hyst
