#pragma once
//! \file
//! Numeric vectors in MATLAB .mat files (v4, v5 and v7.3 to read; v5 and v7.3 to write), via matio.
//!
//! Reading converts any real numeric class (double, single, int8..uint64, logical) to double.
//! A vector is a 1 x N or N x 1 variable (an empty 0 x 0 variable reads as an empty vector); a
//! matrix, an N-d array, a complex number, a cell array, a struct, a char array, a sparse matrix or
//! an object is rejected. Every sample must be finite.
//!
//! Errors throw hyst::Error naming the file (as given) and the variable, e.g.
//!     data.mat: no variable 'x' (variables: a, b)
//!     data.mat: variable 'c' is a 3x4 matrix, expected a vector
//!     data.mat: variable 'z' is complex, expected a real vector
//!     data.mat: variable 'x': x[17] = nan is not finite
//!
//! Writing stores each vector as an N x 1 double column and replaces the file atomically: matio
//! writes a temporary file in the same folder (".<name>.tmp.<pid>.<counter>"), which is flushed to
//! disk and renamed over the target, so a reader never sees a partial file. v7.3 files are HDF5
//! files (MATLAB's format for variables over 2 GB); v5 is read by every MATLAB, Octave and SciPy.
//!
//! Reading checks every size a v4/v5 file states (compressed elements are inflated to check what
//! they hold) before matio trusts it. v7.3 files are parsed by HDF5, whose parser is not hardened
//! against corrupt files (a fuzzer makes it ask for 2^64 bytes within a minute) and which hyst
//! cannot check beforehand: read v7.3 files only from sources you trust.

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst::io {

using hyst::to_string;

enum class MatVersion {
  v5,    //!< MATLAB 5 (Level 5 MAT-file), uncompressed
  v7_3,  //!< MATLAB 7.3 (HDF5-based)
};

//! "v5" or "v7.3".
constexpr EnumNames<MatVersion, 2> enumerator_names(MatVersion) {
  return {{
      {MatVersion::v5, "v5"},
      {MatVersion::v7_3, "v7.3"},
  }};
}
//! The inverse of to_string(); throws hyst::Error for other text.
MatVersion mat_version_from_string(std::string_view text);

//! Names of the variables in a MAT file: in file order for v4/v5, sorted by name (HDF5's index)
//! for v7.3. Throws hyst::Error when the file cannot be opened or is not a MAT file.
std::vector<std::string> list_mat_variables(const std::filesystem::path& path);

//! The variable `variable` as a vector of doubles (see the file comment for what is accepted).
std::vector<double> read_mat_vector(const std::filesystem::path& path, std::string_view variable);

//! The columns of a 2-d real numeric variable (a vector gives one column for N x 1, N columns of
//! one sample for 1 x N), e.g. one measured loop per column; the same checks as read_mat_vector()
//! except that a matrix is accepted.
std::vector<std::vector<double>> read_mat_columns(const std::filesystem::path& path,
                                                  std::string_view variable);

//! Writes the named vectors as N x 1 double variables, replacing the file atomically. Throws
//! hyst::Error unless there is at least one variable, every name is a valid MATLAB name (a letter,
//! then letters, digits or '_', at most 63 characters) and unique, and every value is finite; or
//! when the file cannot be written (the folder must exist).
void write_mat_vectors(const std::filesystem::path& path,
                       const std::vector<std::pair<std::string, std::vector<double>>>& variables,
                       MatVersion version = MatVersion::v5);

}  // namespace hyst::io
