#include "hyst/core/inverse_status.hpp"

namespace hyst {

std::string_view to_string(InverseStatus status) {
  switch (status) {
    case InverseStatus::ok:
      return "ok";
    case InverseStatus::below_range:
      return "below_range";
    case InverseStatus::above_range:
      return "above_range";
  }
  return "unknown";
}

}  // namespace hyst
