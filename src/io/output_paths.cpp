#include "hyst/io/output_paths.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <map>
#include <optional>
#include <system_error>
#include <tuple>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

// The limit of the Linux kernel for one path (MAXSYMLINKS).
constexpr int kMaxLinks = 40;

fs::path folder_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

//! `folder` or the nearest of its parents that exists (followed through links).
fs::path first_existing(fs::path folder) {
  std::error_code error;
  while (!fs::exists(fs::status(folder, error)) && folder_of(folder) != folder) {
    folder = folder_of(folder);
  }
  return folder;
}

//! Resolves `path`; on failure returns why (a message without the path) and leaves `target`.
std::string resolve(const fs::path& path, OutputTarget& target) {
  if (path.filename().empty() || path.filename() == "." || path.filename() == "..") {
    return "the path does not name a file";
  }
  fs::path current = path;
  for (int links = 0; links <= kMaxLinks; ++links) {
    struct stat status {};
    if (::lstat(current.c_str(), &status) != 0) {
      if (errno != ENOENT && errno != ENOTDIR) return errno_message(errno);
      // A missing folder is created when the output is written (create_output_folder()).
      if (const auto blocker = first_existing(folder_of(current));
          !fs::is_directory(fs::status(blocker))) {
        return fmt::format("'{}' is not a folder", blocker.string());
      }
      target = {current, OutputKind::file};
      return {};
    }
    if (S_ISLNK(status.st_mode)) {
      std::error_code error;
      const fs::path next = fs::read_symlink(current, error);
      if (error) return error.message();
      current = next.is_absolute() ? next : current.parent_path() / next;
      continue;
    }
    if (S_ISREG(status.st_mode)) {
      target = {current, OutputKind::file};
      return {};
    }
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) || S_ISFIFO(status.st_mode)) {
      target = {current, OutputKind::special};
      return {};
    }
    if (S_ISDIR(status.st_mode)) return "it is a folder, not a file";
    if (S_ISSOCK(status.st_mode)) return "it is a socket; hyst does not write to sockets";
    return "it is neither a file, a device nor a FIFO";
  }
  return "too many levels of symbolic links";
}

//! Identifies the file an output will be: (device, inode) of an existing file, else (device,
//! inode) of its folder and its name, so that "a/../x" and "x" compare equal before they exist.
using Identity = std::tuple<dev_t, ino_t, std::string>;

//! In a folder still to be created, (device, inode) of its first existing parent and the rest
//! of the path.
std::optional<Identity> identity_of(const fs::path& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) return Identity{status.st_dev, status.st_ino, ""};
  fs::path rest = path.filename();
  fs::path folder = folder_of(path);
  while (::stat(folder.c_str(), &status) != 0) {
    if (folder_of(folder) == folder) return std::nullopt;
    rest = folder.filename() / rest;
    folder = folder_of(folder);
  }
  return Identity{status.st_dev, status.st_ino, rest.lexically_normal().string()};
}

std::string named(const NamedPath& path) {
  return fmt::format("{} '{}'", path.name, path.path.string());
}

}  // namespace

OutputTarget resolve_output(const fs::path& path) {
  OutputTarget target;
  if (const auto why = resolve(path, target); !why.empty()) {
    throw Error(fmt::format("cannot write '{}': {}", path.string(), why));
  }
  return target;
}

void create_output_folder(const fs::path& folder) {
  if (folder.empty()) return;
  const auto blocker = first_existing(folder);
  if (!fs::is_directory(fs::status(blocker))) {
    throw Error(fmt::format("cannot create the folder '{}': '{}' is not a folder", folder.string(),
                            blocker.string()));
  }
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) {
    throw Error(fmt::format("cannot create the folder '{}': {}", folder.string(), error.message()));
  }
}

void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  // Each input is stat()ed once and each output looked up by its identity, so that a batch of
  // thousands of records and model files costs O(n log n), not O(n^2) system calls.
  std::map<Identity, std::size_t> input_of;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    struct stat status {};
    if (inputs[k].path == "-" || ::stat(inputs[k].path.c_str(), &status) != 0) continue;
    input_of.emplace(Identity{status.st_dev, status.st_ino, ""}, k);  // the first keeps its name
  }
  std::map<Identity, std::size_t> output_of;
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const auto& output = outputs[k];
    std::optional<Identity> identity;
    if (output.path == "-") {
      identity = Identity{0, 0, "-"};  // standard output: only equal to another "-"
    } else {
      OutputTarget target;
      if (const auto why = resolve(output.path, target); !why.empty()) {
        throw Error(fmt::format("{}: {}", named(output), why));
      }
      identity = identity_of(target.path);
      if (const auto input = identity ? input_of.find(*identity) : input_of.end();
          input != input_of.end()) {
        throw Error(fmt::format("{} is the same file as the input {}; choose another output",
                                named(output), named(inputs[input->second])));
      }
    }
    if (!identity) continue;
    if (const auto [earlier, fresh] = output_of.emplace(*identity, k); !fresh) {
      throw Error(fmt::format("{} and {} are the same file; choose two different outputs",
                              named(outputs[earlier->second]), named(output)));
    }
  }
}

}  // namespace hyst::io
