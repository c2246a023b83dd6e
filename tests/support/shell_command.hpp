#pragma once
// Runs a shell command from a test (a compiler, nm, a generated program) and reads what it prints.

#include <cstdio>
#include <string>

namespace hyst::test {

// The command's exit status as pclose() returns it (0: success, -1: not started); its standard
// output into `output` when given.
inline int run_command(const std::string& command, std::string* output = nullptr) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return -1;
  std::string text;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
    text += buffer;
  const int status = ::pclose(pipe);
  if (output) *output = text;
  return status;
}

}  // namespace hyst::test
