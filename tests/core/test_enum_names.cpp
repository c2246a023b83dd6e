// The name tables of enumerations (hyst/core/enum_names.hpp, src/core/detail/enum_names.hpp): the
// spelling of a value, to_string() derived from a table found by argument-dependent lookup, the
// list of names in parser messages, and the parser's error with its field.

#include <gtest/gtest.h>

#include <string>

#include "detail/enum_names.hpp"
#include "hyst/core/inverse_status.hpp"
#include "hyst/data/corrections.hpp"

namespace hyst {
namespace {

enum class Shade { light, medium, dark, unlisted };

constexpr EnumNames<Shade, 3> enumerator_names(Shade) {
  return {{{Shade::light, "light"}, {Shade::medium, "medium"}, {Shade::dark, "dark"}}};
}
constexpr const auto& kShadeNames = enum_names<Shade>;

TEST(EnumNames, NameOfAValueAndOfOneNotInTheTable) {
  EXPECT_EQ(detail::name_of(Shade::medium, kShadeNames), "medium");
  EXPECT_EQ(detail::name_of(Shade::unlisted, kShadeNames), "unknown");
}

TEST(EnumNames, NamesListWithOneTwoAndThreeNames) {
  constexpr detail::EnumNames<Shade, 1> one{{{Shade::light, "light"}}};
  constexpr detail::EnumNames<Shade, 2> two{{{Shade::light, "light"}, {Shade::dark, "dark"}}};
  EXPECT_EQ(detail::names_list(one), "light");
  EXPECT_EQ(detail::names_list(two), "light or dark");
  EXPECT_EQ(detail::names_list(kShadeNames), "light, medium or dark");
  EXPECT_EQ(detail::names_list(kShadeNames, ", "), "light, medium, dark");
}

TEST(EnumNames, ValueNamedParsesEveryName) {
  for (const auto& [value, name] : kShadeNames) {
    EXPECT_EQ(detail::value_named(name, kShadeNames, "shade"), value);
  }
  EXPECT_EQ(detail::find_named("dark", kShadeNames), Shade::dark);
  EXPECT_FALSE(detail::find_named("Dark", kShadeNames).has_value());
}

TEST(EnumNames, ValueNamedThrowsWithTheNamesAndTheField) {
  try {
    detail::value_named("pale", kShadeNames, "shade", "colour.shade");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "unknown shade 'pale' (expected light, medium or dark)");
    EXPECT_EQ(error.field(), "colour.shade");
  }
  try {
    detail::value_named("", kShadeNames, "shade");
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "unknown shade '' (expected light, medium or dark)");
    EXPECT_EQ(error.field(), "");
  }
}

enum class Unnamed { only };

TEST(EnumNames, ToStringIsDerivedFromTheTableInTheEnumerationsNamespace) {
  static_assert(NamedEnum<Shade>);
  static_assert(!NamedEnum<Unnamed>);
  static_assert(!NamedEnum<int>);
  static_assert(to_string(Shade::dark) == "dark");
  EXPECT_EQ(to_string(Shade::medium), "medium");
  EXPECT_EQ(to_string(Shade::unlisted), "unknown");
  // A library enumeration in hyst and one in a nested namespace, called unqualified and qualified.
  EXPECT_EQ(to_string(InverseStatus::below_range), "below_range");
  EXPECT_EQ(to_string(data::OffsetReference::midrange), "midrange");
  EXPECT_EQ(data::to_string(data::OffsetReference::first), "first");
}

}  // namespace
}  // namespace hyst
