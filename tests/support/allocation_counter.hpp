#pragma once
// Counts heap allocations. A test program that links allocation_counter.cpp has the global
// operator new replaced by a counting one, so a test can prove that a hot path allocates nothing.

namespace hyst::test {

// Number of calls to operator new (all forms) since the program started.
long allocation_count();

}  // namespace hyst::test
