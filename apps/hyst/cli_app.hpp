#pragma once
// The whole `hyst` command line as one function, so that the program (main.cpp) and the fuzz
// target of the argument handling (fuzz/fuzz_cli_arguments.cpp) run exactly the same code.

#include <cstddef>

namespace hyst::cli {

//! Exit status of run_cli(): success (also for --help and --version).
inline constexpr int kSuccess = 0;
//! Exit status of run_cli(): the work failed (invalid data or model files, unwritable output...).
inline constexpr int kFailure = 1;
//! Exit status of run_cli(): a usage error (unknown option, missing argument, unknown command).
inline constexpr int kUsage = 2;

//! Parses the command line, runs the chosen command and returns the exit status. Never throws
//! and never exits the process: every failure is printed as one line "hyst: error: ..." on
//! standard error.
int run_cli(int argc, const char* const* argv);

//! Records the size of an allocation that failed, for run_cli()'s "out of memory" line (called by
//! the program's operator new, failed_allocation.cpp; without it the line names no size).
void note_failed_allocation(std::size_t bytes) noexcept;

}  // namespace hyst::cli
