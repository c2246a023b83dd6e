// hyst batch: many records, one fit each, on a Dask distributed cluster. The work is Python's
// (python/hyst/batch.py): this command becomes `python3 -m hyst.batch ARGS...` (execv, no shell)
// with the hyst package on PYTHONPATH, so the output and the exit status are that program's.
// HYST_BATCH_PYTHON and HYST_BATCH_PYTHONPATH come from apps/CMakeLists.txt.

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"

namespace hyst::cli {
namespace {

bool holds_package(const std::filesystem::path& folder) {
  std::error_code error;
  return std::filesystem::is_regular_file(folder / "hyst" / "__init__.py", error);
}

//! The folders to put before PYTHONPATH: $HYST_PYTHONPATH when set, else this build's package.
//! Throws hyst::Error naming what is missing.
std::string package_path() {
  if (const char* given = std::getenv("HYST_PYTHONPATH"); given != nullptr && *given != '\0') {
    const std::string folders = given;
    for (std::size_t begin = 0; begin <= folders.size();) {
      const auto end = std::min(folders.find(':', begin), folders.size());
      if (holds_package(folders.substr(begin, end - begin))) return folders;
      begin = end + 1;
    }
    throw Error(
        fmt::format("hyst batch: no folder of HYST_PYTHONPATH='{}' holds the Python package hyst "
                    "(hyst/__init__.py)",
                    folders));
  }
  const std::filesystem::path built = HYST_BATCH_PYTHONPATH;
  if (!holds_package(built)) {
    throw Error(fmt::format(
        "hyst batch needs the Python package hyst, which is missing: no {} (build the target "
        "hyst_python, or set HYST_PYTHONPATH to the folder that holds the package)",
        (built / "hyst" / "__init__.py").string()));
  }
  return built.string();
}

[[noreturn]] void run_python_batch(const std::vector<std::string>& arguments) {
  const char* python = HYST_BATCH_PYTHON;
  if (::access(python, X_OK) != 0) {
    throw Error(
        fmt::format("hyst batch runs {}, which is missing: {} (Debian: apt-get install python3)",
                    python, std::strerror(errno)));
  }
  std::string path = package_path();
  if (const char* old = std::getenv("PYTHONPATH"); old != nullptr && *old != '\0') {
    path += fmt::format(":{}", old);
  }
  if (::setenv("PYTHONPATH", path.c_str(), 1) != 0) {
    throw Error(fmt::format("hyst batch: cannot set PYTHONPATH: {}", std::strerror(errno)));
  }
  std::vector<const char*> argv{python, "-m", "hyst.batch"};
  for (const auto& argument : arguments)
    argv.push_back(argument.c_str());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  ::execv(python, const_cast<char* const*>(argv.data()));
  throw Error(fmt::format("hyst batch: cannot run {}: {}", python, std::strerror(errno)));
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto* command = app.add_subcommand(
      "batch",
      "Fit many records, one fit each, on a Dask distributed cluster (a local one by default).");
  // Everything after `batch` goes to hyst.batch, which parses it (`hyst batch fit --help`).
  command->prefix_command();
  command->footer(fmt::format(
      R"(Commands:
  fit    fit a model to every record: a model file per record and the tables batch.csv and
         batch.md (record, status, NRMSE, parameters, time, reason); 'hyst batch fit --help'
Examples:
  hyst batch fit --model pi --data 'records/*.csv' --input v --output y --out fits/
  hyst batch fit --model pi --data 'records/*.csv' --input v --output y --out fits/ \
      --scheduler tcp://head:8786 --option operators=12
Without --scheduler it starts a local cluster of --workers processes (default 2) on this
machine and closes it at the end. The workers read the records and write the model files, so
both must be on a file system every worker sees at the same path (docs/scaling.md). The
model files and tables are published as one set (each name a link into .hyst-current), so a
run that is stopped or fails leaves the previous set.
It runs '{} -m hyst.batch ...', which needs Dask distributed (apt-get install
python3-distributed), with the folders of HYST_PYTHONPATH on PYTHONPATH when it is set, else
the package of this build:
  {}
The output and the exit status are that program's.)",
      HYST_BATCH_PYTHON, HYST_BATCH_PYTHONPATH));
  command->callback([command] { run_python_batch(command->remaining()); });
}

}  // namespace hyst::cli
