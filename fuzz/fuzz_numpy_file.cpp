// Fuzz target: the NumPy readers (hyst::io::parse_npy, npz_array_names, read_npz_array,
// read_numpy_array) and arrange_periodic. The input is parsed as a .npy file, and it is also
// written to a scratch file that is read as an .npz archive (every array it lists, through libzip)
// and as a file of either kind (read_numpy_array decides by the content).
//
// Beyond "no crash, no leak, no UB": every array returned has product(shape) values, at most
// limits::kMaxNumpyValues, all finite, and arranges into PeriodicSignals of the same size.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz_support.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/io/numpy_file.hpp"

namespace {

//! A layout for an array of 1 to 4 axes.
constexpr std::string_view kLayouts[] = {"N", "N,channel", "N,channel,realisation",
                                         "period,realization,channel,N"};

void check(const hyst::io::NumpyArray& array) {
  std::size_t count = 1;
  for (const std::size_t length : array.shape) {
    if (__builtin_mul_overflow(count, length, &count)) std::abort();  // the reader checks it
  }
  if (array.values.size() != count || count > hyst::io::limits::kMaxNumpyValues) std::abort();
  for (const double value : array.values) {
    if (!std::isfinite(value)) std::abort();  // the reader promises finite values
  }
  if (array.shape.empty() || array.shape.size() > 4) return;
  try {
    const auto signals =
        hyst::io::arrange_periodic(array, kLayouts[array.shape.size() - 1], "fuzz.npy");
    if (signals.values.size() != count ||
        signals.record_length() * signals.channels * signals.realisations != count) {
      std::abort();
    }
  } catch (const hyst::Error&) {
    // an empty axis: refused with a message
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = hyst::fuzz::as_text(data, size);
  try {
    check(hyst::io::parse_npy(bytes, "fuzz.npy"));
  } catch (const hyst::Error&) {
    // not a valid .npy file: rejected with a message
  }
  const auto path = hyst::fuzz::scratch_file("fuzz.npz", bytes);
  try {
    for (const auto& name : hyst::io::npz_array_names(path)) {
      try {
        check(hyst::io::read_npz_array(path, name));
      } catch (const hyst::Error&) {
        // one bad member: the others are still read
      }
    }
  } catch (const hyst::Error&) {
    // not a zip archive: rejected with a message
  }
  try {
    check(hyst::io::read_numpy_array(path.string()));
  } catch (const hyst::Error&) {
    // neither kind, or an archive without exactly one array
  }
  return 0;
}
