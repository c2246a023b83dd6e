#pragma once
// A check of the element sizes in a MATLAB v5 file before matio reads it. matio trusts the sizes
// a file states: a corrupt 250-byte file whose dimensions element claims 1.4 GB makes it allocate
// 2.8 GB (found by fuzz/fuzz_mat_file). Here every top-level element, and every sub-element of an
// uncompressed matrix (recursively), must fit inside what contains it.

#include <filesystem>

namespace hyst::io::detail {

//! Throws hyst::Error "<file>: not a valid MAT file: the element at byte 152 claims 1413565704
//! bytes but its container has 32 left" for a v5 file with an impossible size; does nothing for
//! other files (v4, v7.3/HDF5, not a MAT file at all: matio judges those).
void check_mat_v5_element_sizes(const std::filesystem::path& path);

}  // namespace hyst::io::detail
