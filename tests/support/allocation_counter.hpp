#pragma once
// Counts heap allocations. A test program that links allocation_counter.cpp has the global
// operator new replaced by a counting one, and (with glibc, outside AddressSanitizer) malloc,
// calloc and realloc too, which Eigen allocates with; so a test can prove that a hot path
// allocates nothing.

namespace hyst::test {

// Number of allocations since the program started: calls to operator new (all forms), and to
// malloc, calloc and realloc where counts_malloc().
long allocation_count();
// Whether malloc, calloc and realloc are counted (not under AddressSanitizer).
bool counts_malloc();

}  // namespace hyst::test
