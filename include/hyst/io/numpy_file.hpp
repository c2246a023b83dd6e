#pragma once
//! \file
//! NumPy's array files as users have them: `.npy` (format versions 1.0, 2.0 and 3.0) and `.npz`
//! (a zip of `.npy` members, stored or deflated, as numpy.savez and numpy.savez_compressed write
//! them). Arrays of float64 or float32, little- or big-endian, C or Fortran order, any number of
//! dimensions; the values come back as doubles in C (row-major) order.
//!
//! Every error is a hyst::Error naming the file (and the array of an .npz, as "file.npz:name"):
//! a bad magic string, an unknown version, a header that is not the dictionary NumPy writes (the
//! message says what is wrong, at which byte), a dtype other than float64/float32 (the message
//! names it; object arrays are refused: they would need pickle), a shape whose product overflows
//! or exceeds limits::kMaxNumpyValues, a header longer than limits::kMaxNpyHeaderBytes, a data
//! part shorter or longer than the shape says, a NaN or Inf (its index and flat index). Files are
//! read whole with read_file() (at most limits::kMaxInputBytes); an .npz member may inflate to at
//! most limits::kMaxNpzMemberBytes.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/dynamics/periodic_signals.hpp"

namespace hyst::io {

struct NumpyArray {
  std::vector<std::size_t> shape;  //!< one entry per dimension (empty for a 0-d array)
  std::vector<double> values;      //!< product of shape values, C (row-major) order
};

//! Parses the bytes of one .npy file; `source` (a file name, or "file.npz:name") prefixes every
//! message. The header is parsed as the Python literal it is (keys in any order, either quotes,
//! any blanks, trailing commas, Python 2's "3L"), but must hold exactly the keys 'descr',
//! 'fortran_order' and 'shape'; descr is one of '<f8', '>f8', '<f4', '>f4'.
NumpyArray parse_npy(std::string_view bytes, std::string_view source);
//! Reads a .npy file.
NumpyArray read_npy(const std::filesystem::path& path);
//! Names of the arrays of an .npz file (the names of its members "*.npy" without ".npy"), in
//! archive order; other members are not arrays.
std::vector<std::string> npz_array_names(const std::filesystem::path& path);
//! Reads one array of an .npz file by name (with or without ".npy").
NumpyArray read_npz_array(const std::filesystem::path& path, std::string_view name);
//! "file.npy", "file.npz" (which must hold exactly one array) or "file.npz:name". The kind of a
//! whole file is taken from its content (\x93NUMPY or a zip archive), not its name; a spec that
//! names an existing file is that file, even with ':' in its name.
NumpyArray read_numpy_array(std::string_view spec);

//! The axes of an array as a layout names them: a comma-separated permutation of "N" (samples of
//! one period), "channel", "realisation" and "period" (also "realization"), one per dimension
//! (blanks around a name are ignored);
//! axes the layout leaves out have size 1 (a (N, channel) array is one realisation of one
//! period). Throws hyst::Error (prefixed with `source`) for an unknown or repeated axis name, a
//! layout with another number of axes than the array has, or an empty axis.
PeriodicSignals arrange_periodic(const NumpyArray& array, std::string_view layout,
                                 std::string_view source);

}  // namespace hyst::io
