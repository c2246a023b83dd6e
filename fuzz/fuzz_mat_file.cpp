// Fuzz target: the MATLAB .mat reader (hyst::io::list_mat_variables, read_mat_vector) through
// matio. The input is written to a scratch file (the reader takes a path); every variable it lists
// is then read as a vector.
//
// Inputs whose header says v7.3 are skipped: matio hands those to HDF5 (1.10.8 on Debian 12),
// whose parser is not hardened against corrupt files and which hyst cannot pre-check (it found an
// allocation of 2^64 - 136 bytes in H5MM_realloc and a 2.5 GB memory growth within a minute).
// v7.3 reading is tested on valid files in tests/io; docs/reliability.md has the details.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/mat_file.hpp"

namespace {

//! The v7.3 mark: version 0x0200 at byte 124 of the 128-byte header, in either byte order.
bool declares_v7_3(const std::uint8_t* data, std::size_t size) {
  if (size < 128) return false;
  return (data[124] == 0x00 && data[125] == 0x02) || (data[124] == 0x02 && data[125] == 0x00);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (declares_v7_3(data, size)) return 0;
  const auto path = hyst::fuzz::scratch_file("fuzz.mat", hyst::fuzz::as_text(data, size));
  try {
    for (const auto& name : hyst::io::list_mat_variables(path)) {
      try {
        for (const double value : hyst::io::read_mat_vector(path, name)) {
          if (!std::isfinite(value)) std::abort();  // the reader promises finite samples
        }
      } catch (const hyst::Error&) {
        // one bad variable: the others are still read
      }
    }
  } catch (const hyst::Error&) {
    // not a MAT file, unreadable: rejected with a message
  }
  return 0;
}
