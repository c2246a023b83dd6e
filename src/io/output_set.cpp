#include "hyst/io/output_set.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <set>
#include <system_error>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kCurrent = ".hyst-current";
constexpr std::string_view kSetPrefix = ".hyst-set.";

std::string link_text(const std::string& name) {
  return fmt::format("{}/{}", kCurrent, name);
}

[[noreturn]] void fail(const fs::path& path, std::string_view why) {
  throw Error(fmt::format("cannot publish '{}': {}", path.string(), why));
}

void check(const std::error_code& error, const fs::path& path, std::string_view step) {
  if (error) fail(path, fmt::format("{} ({})", error.message(), step));
}

//! Makes the renames in `folder` durable. Best effort: not every file system supports it.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  static_cast<void>(::fsync(fd));
  ::close(fd);
}

//! Is `path` the link of a published name, ".hyst-current/<name>"?
bool is_set_link(const fs::path& path) {
  std::error_code error;
  if (!fs::is_symlink(fs::symlink_status(path, error))) return false;
  return fs::read_symlink(path, error).string() == link_text(path.filename().string());
}

//! The pid in a set folder's name ".hyst-set.<pid>.<n>", or 0.
pid_t owner_of(const std::string& name) {
  if (name.rfind(kSetPrefix, 0) != 0) return 0;
  try {
    return static_cast<pid_t>(std::stol(name.substr(kSetPrefix.size())));
  } catch (const std::exception&) {
    return 0;
  }
}

//! `name` must be free for a link of the set: absent, a regular file or already a set link.
void check_name(const fs::path& folder, const std::string& name) {
  if (name.empty() || name.front() == '.' || name.find('/') != std::string::npos) {
    fail(folder / name, "not a plain file name of the set");
  }
  const fs::path path = folder / name;
  std::error_code error;
  const auto status = fs::symlink_status(path, error);
  if (!fs::exists(status) || fs::is_regular_file(status) || is_set_link(path)) return;
  fail(path, fs::is_symlink(status)
                 ? "it is a link elsewhere; the files of a set are links hyst manages itself"
                 : "it is not a regular file; a set replaces regular files only");
}

//! Creates a link to `text` at `path` atomically: made in `scratch` (a set folder), then renamed.
void place_link(const fs::path& scratch, const std::string& text, const fs::path& path) {
  const fs::path temporary = scratch / fmt::format(".link.{}", path.filename().string());
  std::error_code error;
  fs::remove(temporary, error);
  fs::create_symlink(text, temporary, error);
  check(error, path, "creating the link");
  fs::rename(temporary, path, error);
  check(error, path, "renaming the link into place");
}

}  // namespace

OutputSet::OutputSet(fs::path folder, const std::vector<std::string>& names)
    : folder_(std::move(folder)) {
  if (folder_.empty()) folder_ = ".";
  create_output_folder(folder_);
  std::error_code error;
  for (const auto& name : names)
    check_name(folder_, name);

  // Set folders of runs that died: neither current nor owned by a living process.
  const auto current = fs::read_symlink(folder_ / kCurrent, error).string();
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    const auto name = entry.path().filename().string();
    const pid_t owner = owner_of(name);
    if (owner == 0 || name == current) continue;
    if (owner == ::getpid() || ::kill(owner, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }

  static std::atomic<unsigned long long> counter{0};
  staging_ = folder_ / fmt::format("{}{}.{}", kSetPrefix, static_cast<long long>(::getpid()),
                                   counter.fetch_add(1));
  fs::create_directory(staging_, error);
  if (error) {
    throw Error(fmt::format("cannot write into '{}': {} (creating the staging folder '{}')",
                            folder_.string(), error.message(), staging_.string()));
  }
}

OutputSet::~OutputSet() {
  if (published_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

fs::path OutputSet::staged(const std::string& name) const {
  return staging_ / name;
}

void OutputSet::publish() {
  std::error_code error;
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(staging_, error)) {
    const auto name = entry.path().filename().string();
    if (name.front() != '.') names.insert(name);
  }
  check(error, staging_, "listing the staged files");

  const fs::path current_link = folder_ / kCurrent;
  const std::string old_set = fs::read_symlink(current_link, error).string();
  const bool has_current = !error && !old_set.empty();
  std::set<std::string> old_names;
  if (has_current) {
    for (const auto& entry : fs::directory_iterator(folder_ / old_set, error)) {
      const auto name = entry.path().filename().string();
      if (name.front() != '.') old_names.insert(name);
    }
  }
  for (const auto& name : names)
    check_name(folder_, name);

  // Plain files of an older hyst under a name of the set: hard-linked into the current set (one
  // made for them if there is none), then replaced by the link; their content stays readable.
  fs::path migration = has_current ? folder_ / old_set : fs::path();
  for (const auto& name : names) {
    const fs::path path = folder_ / name;
    if (!fs::is_regular_file(fs::symlink_status(path, error))) continue;  // not a link either
    if (migration.empty()) {
      migration = staging_;
      migration += ".old";
      fs::create_directory(migration, error);
      check(error, migration, "creating the folder of the previous files");
      place_link(migration, migration.filename().string(), current_link);
    }
    const fs::path kept = migration / name;
    fs::remove(kept, error);
    fs::create_hard_link(path, kept, error);
    check(error, path, "keeping the previous file in the current set");
    place_link(migration, link_text(name), path);
    old_names.insert(name);
  }

  // Links for names new to the set: they dangle (read as absent) until the switch.
  for (const auto& name : names) {
    if (!is_set_link(folder_ / name)) place_link(staging_, link_text(name), folder_ / name);
  }
  sync_folder(staging_);
  sync_folder(folder_);

  // The switch: one rename replaces the set as a whole.
  place_link(staging_, staging_.filename().string(), current_link);
  published_ = true;
  sync_folder(folder_);

  // Afterwards: names the new set lacks, and the old set's folder.
  for (const auto& name : old_names) {
    if (names.count(name) == 0 && is_set_link(folder_ / name)) fs::remove(folder_ / name, error);
  }
  if (!migration.empty()) fs::remove_all(migration, error);
  if (has_current) fs::remove_all(folder_ / old_set, error);
}

}  // namespace hyst::io
