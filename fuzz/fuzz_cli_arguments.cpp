// Fuzz target: the argument handling of `hyst simulate` and `hyst fit`, through the same
// hyst::cli::run_cli() as the program (no process exit; every failure must come back as an exit
// status, never as an escaping exception or a crash).
//
// The input is the argument list, one argument per line; the first byte chooses the command
// (even: simulate, odd: fit). The target works in a scratch folder holding a model file for every
// registered model ("<name>.json"), a CSV file "d.csv" (columns t, v, y) and a MAT file "d.mat"
// (v, y), so that arguments can name real files. Arguments with a '/' are refused, so that
// nothing is ever written outside the scratch folder. Give libFuzzer absolute corpus paths: the
// target changes the working folder.

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../apps/hyst/cli_app.hpp"
#include "fuzz_support.hpp"
#include "hyst/io/csv.hpp"
#include "hyst/io/mat_file.hpp"
#include "hyst/registry/model_file.hpp"
#include "hyst/registry/model_registry.hpp"

namespace {

constexpr std::size_t kMaxArguments = 24;

void write_scratch_files() {
  const auto& folder = hyst::fuzz::scratch_folder();
  for (const auto& entry : hyst::ModelRegistry::builtin().entries()) {
    hyst::save_model(folder / (entry.name + ".json"), *entry.create(entry.example_params, nullptr));
  }
  // A short hysteretic record: a decaying sine through a PI-like delay, enough for every fitter.
  hyst::io::Table table;
  std::vector<double> t, v, y;
  for (int k = 0; k < 60; ++k) {
    t.push_back(0.01 * k);
    v.push_back(std::sin(0.3 * k) * (1.0 - k / 80.0));
    y.push_back(0.8 * v.back() + 0.2 * std::sin(0.3 * k - 0.4));
  }
  table.add_column("t", t);
  table.add_column("v", v);
  table.add_column("y", y);
  hyst::io::write_csv(folder / "d.csv", table);
  hyst::io::write_mat_vectors(folder / "d.mat", {{"v", v}, {"y", y}});
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  write_scratch_files();
  if (::chdir(hyst::fuzz::scratch_folder().c_str()) != 0) std::abort();
  // Help texts and "wrote ..." lines would flood the fuzzer's log.
  if (!std::freopen("/dev/null", "w", stdout)) std::abort();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::vector<std::string> arguments = {"hyst", data[0] % 2 == 0 ? "simulate" : "fit"};
  std::string current;
  for (std::size_t i = 1; i <= size; ++i) {
    if (i == size || data[i] == '\n') {
      if (current.find('/') != std::string::npos) return 0;
      arguments.push_back(current);
      current.clear();
      if (arguments.size() > kMaxArguments) return 0;
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  std::vector<const char*> argv;
  for (const auto& argument : arguments)
    argv.push_back(argument.c_str());
  argv.push_back(nullptr);
  const int status = hyst::cli::run_cli(static_cast<int>(arguments.size()), argv.data());
  if (status != hyst::cli::kSuccess && status != hyst::cli::kFailure &&
      status != hyst::cli::kUsage) {
    std::abort();
  }
  return 0;
}
