// The shared library of an FMU, built by the C compiler of this machine (fmu_parts.hpp).

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fmu_parts.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"

extern char** environ;

namespace hyst::detail {
namespace {

// A private folder under the temporary directory, removed with everything in it.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "hyst-fmu-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw Error(fmt::format("FMU export: cannot make a scratch folder '{}': {}", pattern,
                              std::strerror(errno)));
    }
    path_ = std::filesystem::absolute(pattern);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Runs `argv` in `folder` with its standard output and error going to `log`; returns the exit
// status (128 + signal when killed).
int run(std::vector<std::string> argv, const std::filesystem::path& folder,
        const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // The compiler runs in the scratch folder: relative paths stay inside it.
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<char*> pointers;
  for (auto& arg : argv)
    pointers.push_back(arg.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned =
      ::posix_spawnp(&pid, pointers[0], &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw Error(fmt::format("FMU export: cannot start the C compiler '{}': {} (set --cc or $CC)",
                            argv[0], std::strerror(spawned)));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 255;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 255;
}

std::string chosen_compiler(const std::string& compiler) {
  if (!compiler.empty()) return compiler;
  const char* from_environment = std::getenv("CC");
  return from_environment != nullptr && *from_environment != '\0' ? from_environment : "cc";
}

}  // namespace

std::string compile_shared_library(const std::string& compiler,
                                   std::span<const SourceFile> sources) {
  const ScratchFolder scratch;
  std::vector<std::string> argv{chosen_compiler(compiler), "-std=c99", "-O2",   "-fPIC", "-shared",
                                "-fvisibility=hidden",     "-o",       "fmu.so"};
  for (const auto& source : sources) {
    io::write_file_atomically(scratch.path() / source.name, source.text);
    if (source.name.ends_with(".c")) argv.push_back(source.name);
  }
  argv.emplace_back("-lm");
  const auto log = scratch.path() / "compiler.log";
  const int status = run(argv, scratch.path(), log);
  if (status != 0) {
    std::string messages;
    std::error_code ignored;
    if (std::filesystem::exists(log, ignored)) messages = io::read_file(log);
    if (messages.size() > 4000) messages = messages.substr(0, 4000) + "\n...";
    std::string command;
    for (const auto& arg : argv)
      command += (command.empty() ? "" : " ") + arg;
    throw Error(fmt::format("FMU export: the C compiler failed (exit status {}{}): {}\n{}", status,
                            status == 127 ? ", not found: set --cc or $CC" : "", command,
                            messages));
  }
  return io::read_file(scratch.path() / "fmu.so");
}

}  // namespace hyst::detail
