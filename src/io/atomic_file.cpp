#include "hyst/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hyst/core/error.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail_write(const fs::path& path, int error_number, std::string_view step) {
  throw Error(
      fmt::format("cannot write '{}': {} ({})", path.string(), errno_message(error_number), step));
}

//! A unique name in the target's folder: unique across processes (pid) and within one (counter).
fs::path temporary_path_for(const fs::path& path) {
  static std::atomic<unsigned long long> counter{0};
  // Shortened so that the name stays within the usual 255-byte limit of a file name.
  const std::string target = path.filename().string().substr(0, 200);
  const auto name = fmt::format(".{}.tmp.{}.{}", target, static_cast<long long>(::getpid()),
                                counter.fetch_add(1));
  return path.parent_path() / name;
}

//! Owns the temporary file: closes it and removes it unless the write was committed.
class TemporaryFile {
 public:
  TemporaryFile(fs::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
  }

  int fd() const { return fd_; }
  const fs::path& path() const { return path_; }

  //! Closes the descriptor; returns errno, or 0 on success.
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }
  void commit() { committed_ = true; }

 private:
  fs::path path_;
  int fd_;
  bool committed_ = false;
};

//! Writes everything, retrying after interrupts and partial writes; returns errno or 0.
int write_all(int fd, std::string_view content) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

//! Makes the rename itself durable. Best effort: not every file system supports it.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  static_cast<void>(::fsync(fd));
  ::close(fd);
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

//! A device or FIFO is written through: there is no file to replace, and renaming over it would
//! replace the node itself (e.g. /dev/null by a regular file).
void write_through(const fs::path& path, const fs::path& target, std::string_view content) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail_write(path, errno, fmt::format("opening '{}' for writing", target.string()));
  const int error = write_all(fd, content);
  // fsync only matters for block devices; character devices and FIFOs answer EINVAL.
  if (!error && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS && errno != ENOTSUP) {
    const int sync_error = errno;
    ::close(fd);
    fail_write(path, sync_error, "flushing to disk");
  }
  if (::close(fd) != 0 && !error) fail_write(path, errno, "closing");
  if (error) fail_write(path, error, "writing");
}

//! One output on its way: the content staged in a flushed temporary file beside the target (or,
//! for a device or FIFO, kept to be written through), then committed by one rename.
class StagedOutput {
 public:
  StagedOutput(const fs::path& path, std::string_view content)
      : path_(path), resolved_(resolve_output(path)) {
    // A symbolic link is followed: its target is replaced and the link kept.
    if (resolved_.kind == OutputKind::special) {
      through_content_ = content;
      return;
    }
    create_output_folder(resolved_.path.parent_path());
    const fs::path temporary = temporary_path_for(resolved_.path);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      fail_write(path, errno, fmt::format("creating the temporary file '{}'", temporary.string()));
    }
    file_ = std::make_unique<TemporaryFile>(temporary, fd);

    // Keep the permission bits of a file being replaced (the new one would get the umask default).
    struct stat target_status {};
    if (::stat(resolved_.path.c_str(), &target_status) == 0 && S_ISREG(target_status.st_mode)) {
      static_cast<void>(::fchmod(file_->fd(), target_status.st_mode & 07777));  // best effort
    }
    if (const int error = write_all(file_->fd(), content)) fail_write(path, error, "writing");
    while (::fsync(file_->fd()) != 0) {
      if (errno != EINTR) fail_write(path, errno, "flushing to disk");
    }
    if (const int error = file_->close()) fail_write(path, error, "closing");
  }

  void commit() {
    if (!file_) {
      write_through(path_, resolved_.path, through_content_);
      return;
    }
    std::error_code rename_error;
    fs::rename(file_->path(), resolved_.path, rename_error);
    if (rename_error) {
      throw Error(fmt::format("cannot write '{}': {} (renaming '{}' over it)", path_.string(),
                              rename_error.message(), file_->path().string()));
    }
    file_->commit();
  }

  void sync() const {
    if (file_) sync_folder(resolved_.path.parent_path());
  }

 private:
  fs::path path_;
  OutputTarget resolved_;
  std::unique_ptr<TemporaryFile> file_;  // null for a device or FIFO
  std::string_view through_content_;
};

}  // namespace

void write_file_atomically(const fs::path& path, std::string_view content) {
  StagedOutput output(path, content);
  output.commit();
  output.sync();
}

void write_files_atomically(std::span<const FileContent> files) {
  std::vector<StagedOutput> staged;
  staged.reserve(files.size());
  for (const auto& file : files)
    staged.emplace_back(file.path, file.content);
  // Nothing but the renames between the first and the last commit.
  for (auto& output : staged)
    output.commit();
  for (const auto& output : staged)
    output.sync();
}

std::string read_file(const fs::path& path) {
  errno = 0;
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    throw Error(fmt::format("cannot open '{}': {}", path.string(), errno_message(errno)));
  }
  std::string content;
  char buffer[65536];
  while (true) {
    const std::size_t count = std::fread(buffer, 1, sizeof buffer, file.get());
    const int error_number = errno;
    // A FIFO or device may never end: stop at the stated limit.
    if (count > limits::kMaxInputBytes - content.size()) {
      throw Error(fmt::format(
          "cannot read '{}': it holds more than {} bytes, the limit of one input (an endless "
          "stream?)",
          path.string(), limits::kMaxInputBytes));
    }
    try {
      content.append(buffer, count);
    } catch (const std::bad_alloc&) {
      throw Error(fmt::format("cannot read '{}': out of memory holding {} bytes", path.string(),
                              content.size() + count));
    }
    if (count == sizeof buffer) continue;
    if (std::ferror(file.get())) {
      throw Error(fmt::format("cannot read '{}': {}", path.string(), errno_message(error_number)));
    }
    return content;
  }
}

}  // namespace hyst::io
