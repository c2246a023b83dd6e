#pragma once
//! \file
//! HYST_ASSERT(condition, message): a precondition of a hot path (a finite input, a state of the
//! right size), checked in debug builds only. A failed check prints the condition, the message and
//! where it stands, then aborts: `step()` is noexcept and its caller broke a documented contract,
//! so there is nothing to recover. With NDEBUG (Release) the check compiles to nothing and the
//! condition is not evaluated, so a hot path costs the same as without it.
//!
//! User input is validated with hyst::Error at construction or in simulate(); HYST_ASSERT is for
//! the unchecked per-sample calls (`step`) that trust their caller.

#include <cstdio>
#include <cstdlib>

namespace hyst::detail {

[[noreturn]] inline void assertion_failed(const char* condition, const char* message,
                                          const char* file, int line) noexcept {
  std::fprintf(stderr, "%s:%d: hyst precondition failed: %s (%s)\n", file, line, message,
               condition);
  std::abort();
}

}  // namespace hyst::detail

#ifdef NDEBUG
#define HYST_ASSERT(condition, message) static_cast<void>(0)
#else
#define HYST_ASSERT(condition, message) \
  ((condition) ? static_cast<void>(0)   \
               : ::hyst::detail::assertion_failed(#condition, message, __FILE__, __LINE__))
#endif
