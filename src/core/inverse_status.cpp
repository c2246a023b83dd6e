#include "hyst/core/inverse_status.hpp"

#include "detail/enum_names.hpp"

namespace hyst {
namespace {

constexpr detail::EnumNames<InverseStatus, 3> kInverseStatusNames{{
    {InverseStatus::ok, "ok"},
    {InverseStatus::below_range, "below_range"},
    {InverseStatus::above_range, "above_range"},
}};

}  // namespace

std::string_view to_string(InverseStatus status) {
  return detail::name_of(status, kInverseStatusNames);
}

}  // namespace hyst
