// Fuzz target: the MATLAB .mat reader (hyst::io::list_mat_variables, read_mat_vector) through
// matio. The input is written to a scratch file (the reader takes a path); every variable it lists
// is then read as a vector.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/mat_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
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
