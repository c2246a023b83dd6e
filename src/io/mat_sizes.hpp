#pragma once
// A check of the sizes a MATLAB file states, before matio reads it. matio trusts them: a corrupt
// 250-byte file whose dimensions element claims 1.4 GB makes it allocate 2.8 GB, and a file that
// is neither v5 nor HDF5 is tried as v4, whose first record may claim a 1.7 GB name (both found by
// fuzz/fuzz_mat_file). Here, in a v5 file every top-level element, every sub-element of a matrix
// (recursively) and every element inside a compressed one (inflated on the fly) must fit inside
// what contains it, and each matrix must start with array flags, dimensions and a name as the
// format defines; in a v4 file every record (header, name, data) must fit inside the file.

#include <filesystem>

namespace hyst::io::detail {

//! Throws hyst::Error "<file>: not a valid MAT file: the element at byte 152 claims 1413565704
//! bytes but its container has 32 left" (v5) or "<file>: not a MAT file (...)" (v4 with an
//! impossible first record); does nothing for v7.3 (HDF5) files, which HDF5 checks itself.
void check_mat_sizes(const std::filesystem::path& path);

}  // namespace hyst::io::detail
