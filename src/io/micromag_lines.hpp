#pragma once
// The first and the last line of every MicroMag 2900/3900 export, for the loop and FORC readers:
//     MicroMag 2900/3900 Data File (Series 0015)
//     ...
//     MicroMag 2900/3900 Data File ends

#include <string_view>

#include "text_fields.hpp"

namespace hyst::io::detail {

inline constexpr std::string_view kMicromagEndMarker = "Data File ends";

//! The end marker; only a line starting with "MicroMag" is one (a data row holding the words is
//! not).
inline bool is_micromag_end_marker(std::string_view line) {
  line = trim(line);
  return line.starts_with("MicroMag") && line.find(kMicromagEndMarker) != std::string_view::npos;
}

//! The first line of an export.
inline bool is_micromag_format_line(std::string_view line) {
  line = trim(line);
  return line.starts_with("MicroMag") && line.find("Data File") != std::string_view::npos &&
         !is_micromag_end_marker(line);
}

}  // namespace hyst::io::detail
