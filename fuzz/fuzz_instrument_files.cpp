// Fuzz target: the readers of instrument text exports - aixACCT, MicroMag hysteresis loop and
// FORC files (Series 0015 and 0016 layouts), MagIC tables with their hysteresis loops. The first
// byte chooses the reader, the rest is the file. What a reader accepts must hold together: columns
// of equal length, one value per row and column, block starts inside the data.

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/aixacct.hpp"
#include "hyst/io/magic_table.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/io/micromag_loop.hpp"

namespace {

void check_loop_file(std::string_view text) {
  const auto file = hyst::io::parse_micromag_loop(text, "fuzz.hys");
  if (file.columns.size() < 2 || file.values.size() != file.columns.size()) std::abort();
  for (const auto& column : file.values) {
    if (column.size() != file.points() || column.empty()) std::abort();
  }
  for (const auto start : file.segment_starts) {
    if (start >= file.points()) std::abort();
  }
  static_cast<void>(file.to_table());  // unique, valid names
}

void check_forc_file(std::string_view text) {
  const auto file = hyst::io::parse_micromag_forc(text, "fuzz.forc");
  if (file.columns.size() < 2 || file.units.size() != file.columns.size()) std::abort();
  for (const auto& curve : file.curves) {
    if (curve.field.size() != curve.moment.size() || curve.field.empty()) std::abort();
    if (curve.more_columns.size() + 2 != file.columns.size()) std::abort();
    for (const auto& column : curve.more_columns) {
      if (column.size() != curve.field.size()) std::abort();
    }
  }
  // Drift correction of whatever the reader accepts: an error (a zero calibration moment) or
  // moments of the same shape.
  const auto corrected =
      hyst::io::correct_drift(file, hyst::io::ForcDriftCorrection::multiplicative);
  if (corrected.curves.size() != file.curves.size()) std::abort();
}

void check_magic_table(std::string_view text) {
  const auto table = hyst::io::parse_magic_table(text, "fuzz.dat");
  if (table.rows.size() != table.row_lines.size()) std::abort();
  for (const auto& row : table.rows) {
    if (row.size() != table.columns.size()) std::abort();
  }
  for (const auto& loop : hyst::io::magic_hysteresis_loops(table)) {
    if (loop.field.size() != loop.moment.size() || loop.field.empty()) std::abort();
  }
}

void check_aixacct(std::string_view text) {
  const auto file = hyst::io::parse_aixacct(text, "fuzz.dat");
  for (const auto& table : file.measurements) {
    for (const auto& column : table.columns) {
      if (column.values.size() != table.rows()) std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto text = hyst::fuzz::as_text(data + 1, size - 1);
  try {
    switch (data[0] % 4) {
      case 0:
        check_loop_file(text);
        break;
      case 1:
        check_forc_file(text);
        break;
      case 2:
        check_magic_table(text);
        break;
      default:
        check_aixacct(text);
        break;
    }
  } catch (const hyst::Error&) {
    return 0;  // rejected with a message: the expected outcome for most inputs
  }
  return 0;
}
