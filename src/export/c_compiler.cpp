// The shared library of an FMU, built by the C compiler of this machine (fmu_parts.hpp).

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
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

// Removes the flat folder `path` (the scratch folder: files only) with async-signal-safe calls
// alone, for the guard process below.
void remove_flat_folder(const char* path) {
  const int folder = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder >= 0) {
    alignas(8) char buffer[4096];
    long bytes = 0;
    while ((bytes = ::syscall(SYS_getdents64, folder, buffer, sizeof buffer)) > 0) {
      for (long at = 0; at < bytes;) {
        // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name.
        unsigned short length = 0;
        std::memcpy(&length, buffer + at + 16, sizeof length);
        const char* name = buffer + at + 19;
        const bool dot = name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'));
        if (!dot) ::unlinkat(folder, name, 0);
        at += length;
      }
    }
    ::close(folder);
  }
  ::rmdir(path);
}

// Everything the processes after fork() need, prepared before it: they may call only
// async-signal-safe functions (the exporter may have other threads).
struct CompilerRun {
  std::vector<char*> argv;
  std::vector<std::string> environment;  // the exporter's, TMPDIR = the scratch folder
  std::vector<char*> envp;
  const char* folder = nullptr;
  const char* log = nullptr;
};

// The compiler's process: its own process group (so that the guard can end it with everything it
// started), killed if the guard dies, output to the log, then exec. On failure it reports errno
// through `report` and exits with 127.
[[noreturn]] void exec_compiler(const CompilerRun& run, const sigset_t& mask, int report) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  for (const int number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
    ::signal(number, SIG_DFL);
  ::sigprocmask(SIG_SETMASK, &mask, nullptr);
  int error = 0;
  if (::chdir(run.folder) != 0) error = errno;
  const int log = error == 0 ? ::open(run.log, O_WRONLY | O_CREAT | O_TRUNC, 0600) : -1;
  const int input = ::open("/dev/null", O_RDONLY);
  if (error == 0 && (log < 0 || input < 0)) error = errno;
  if (error == 0) {
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    ::dup2(input, STDIN_FILENO);
    ::execvpe(run.argv[0], run.argv.data(), run.envp.data());
    error = errno;
  }
  [[maybe_unused]] const auto written = ::write(report, &error, sizeof error);
  ::_exit(127);
}

// The guard, a child of the exporter that outlives it: it starts the compiler and waits for it;
// when the exporter dies (any signal, SIGKILL included: PR_SET_PDEATHSIG), it kills the
// compiler's process group and removes the scratch folder, so that a killed export leaves
// neither a running compiler nor a hyst-fmu-* folder. It ignores the terminal's SIGINT, which
// reaches the whole foreground group, so that it lives to clean up. Exits with the compiler's
// status (128 + signal when killed).
[[noreturn]] void guard_compiler(const CompilerRun& run, pid_t exporter, int report) {
  sigset_t waited;
  sigset_t previous;
  sigemptyset(&waited);
  sigaddset(&waited, SIGCHLD);
  sigaddset(&waited, SIGUSR1);
  ::sigprocmask(SIG_BLOCK, &waited, &previous);
  for (const int number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
    ::signal(number, SIG_IGN);
  ::signal(SIGCHLD, SIG_DFL);  // an inherited SIG_IGN would reap the compiler unseen
  ::prctl(PR_SET_PDEATHSIG, SIGUSR1);
  pid_t compiler = -1;
  if (::getppid() == exporter) {
    compiler = ::fork();
    if (compiler == 0) exec_compiler(run, previous, report);
    if (compiler < 0) {
      const int error = errno;
      [[maybe_unused]] const auto written = ::write(report, &error, sizeof error);
      ::_exit(127);
    }
    ::setpgid(compiler, compiler);  // as the compiler does: whichever runs first
  }
  ::close(report);
  for (;;) {
    if (compiler > 0) {
      int status = 0;
      const pid_t ended = ::waitpid(compiler, &status, WNOHANG);
      if (ended == compiler) {
        if (WIFEXITED(status)) ::_exit(WEXITSTATUS(status));
        ::_exit(WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 255);
      }
      if (ended < 0 && errno != EINTR) ::_exit(255);
    }
    if (compiler < 0 || ::getppid() != exporter) break;  // the exporter is gone
    siginfo_t info;
    ::sigwaitinfo(&waited, &info);
  }
  if (compiler > 0) {
    ::kill(-compiler, SIGKILL);
    int status = 0;
    ::waitpid(compiler, &status, 0);
  }
  remove_flat_folder(run.folder);
  ::_exit(255);
}

// Runs `argv` in `folder` with its standard output and error going to `log`, under a guard (see
// guard_compiler); returns the exit status (128 + signal when killed).
int run(std::vector<std::string> argv, const std::filesystem::path& folder,
        const std::filesystem::path& log) {
  CompilerRun prepared;
  for (auto& arg : argv)
    prepared.argv.push_back(arg.data());
  prepared.argv.push_back(nullptr);
  for (char** variable = environ; *variable != nullptr; ++variable) {
    if (std::string_view(*variable).starts_with("TMPDIR=")) continue;
    prepared.environment.emplace_back(*variable);
  }
  // The compiler's own temporary files go into the scratch folder too, so that they go with it.
  prepared.environment.push_back("TMPDIR=" + folder.string());
  for (auto& variable : prepared.environment)
    prepared.envp.push_back(variable.data());
  prepared.envp.push_back(nullptr);
  prepared.folder = folder.c_str();
  prepared.log = log.c_str();

  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    throw Error(fmt::format("FMU export: cannot start the C compiler '{}': {}", argv[0],
                            std::strerror(errno)));
  }
  const pid_t exporter = ::getpid();
  const pid_t guard = ::fork();
  if (guard == 0) guard_compiler(prepared, exporter, report[1]);
  ::close(report[1]);
  int start_error = 0;
  ssize_t got = 0;
  do {
    got = ::read(report[0], &start_error, sizeof start_error);
  } while (got < 0 && errno == EINTR);
  ::close(report[0]);
  if (guard < 0) start_error = errno;
  int status = 0;
  while (guard > 0 && ::waitpid(guard, &status, 0) < 0) {
    if (errno != EINTR) {
      status = -1;
      break;
    }
  }
  if (guard < 0 || got == static_cast<ssize_t>(sizeof start_error)) {
    throw Error(fmt::format("FMU export: cannot start the C compiler '{}': {} (set --cc or $CC)",
                            argv[0], std::strerror(start_error)));
  }
  if (status < 0) return 255;
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
