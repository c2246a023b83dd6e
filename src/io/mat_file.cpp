#include "hyst/io/mat_file.hpp"

#include <fcntl.h>
#include <matio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <set>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/limits.hpp"
#include "hyst/io/output_paths.hpp"
#include "mat_sizes.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;
using detail::check_mat_sizes;

struct MatCloser {
  void operator()(mat_t* mat) const { Mat_Close(mat); }
};
struct VarFreer {
  void operator()(matvar_t* variable) const { Mat_VarFree(variable); }
};
using MatHandle = std::unique_ptr<mat_t, MatCloser>;
using VarHandle = std::unique_ptr<matvar_t, VarFreer>;

MatHandle open_for_reading(const fs::path& path) {
  // Tell "cannot open" from "not a MAT file": matio reports both as a null handle.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(fmt::format("cannot open '{}': {}", path.string(), errno_message(errno)));
  struct stat status {};
  const int stat_result = ::fstat(fd, &status);
  ::close(fd);
  if (stat_result == 0 && S_ISDIR(status.st_mode)) {
    throw Error(fmt::format("cannot open '{}': it is a folder", path.string()));
  }
  if (stat_result == 0 && status.st_size == 0) {
    throw Error(fmt::format("{}: not a MAT file (the file is empty)", path.string()));
  }
  check_mat_sizes(path);
  MatHandle mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!mat) {
    throw Error(fmt::format("{}: not a MAT file (MATLAB v4, v5 or v7.3 expected)", path.string()));
  }
  return mat;
}

std::vector<std::string> variable_names(mat_t* mat) {
  std::vector<std::string> names;
  Mat_Rewind(mat);
  while (VarHandle info{Mat_VarReadNextInfo(mat)}) {
    names.emplace_back(info->name != nullptr ? info->name : "");
  }
  return names;
}

std::string_view class_description(matio_classes class_type) {
  switch (class_type) {
    case MAT_C_CELL:
      return "a cell array";
    case MAT_C_STRUCT:
      return "a struct";
    case MAT_C_CHAR:
      return "a char array";
    case MAT_C_SPARSE:
      return "a sparse matrix";
    case MAT_C_OBJECT:
    case MAT_C_OPAQUE:
      return "an object";
    case MAT_C_FUNCTION:
      return "a function handle";
    default:
      return "";
  }
}

std::string dimensions(const matvar_t& variable) {
  std::string text;
  for (int d = 0; d < variable.rank; ++d) {
    text += fmt::format("{}{}", d == 0 ? "" : "x", variable.dims[d]);
  }
  return text;
}

template <class T>
void convert(const void* data, std::vector<double>& out) {
  for (std::size_t k = 0; k < out.size(); ++k) {
    T value;
    std::memcpy(&value, static_cast<const unsigned char*>(data) + k * sizeof(T), sizeof(T));
    out[k] = static_cast<double>(value);
  }
}

// False for a class that is not real numeric.
bool convert_numeric(const matvar_t& variable, std::vector<double>& out) {
  switch (variable.class_type) {
    case MAT_C_DOUBLE:
      convert<double>(variable.data, out);
      return true;
    case MAT_C_SINGLE:
      convert<float>(variable.data, out);
      return true;
    case MAT_C_INT8:
      convert<std::int8_t>(variable.data, out);
      return true;
    case MAT_C_UINT8:
      convert<std::uint8_t>(variable.data, out);
      return true;
    case MAT_C_INT16:
      convert<std::int16_t>(variable.data, out);
      return true;
    case MAT_C_UINT16:
      convert<std::uint16_t>(variable.data, out);
      return true;
    case MAT_C_INT32:
      convert<std::int32_t>(variable.data, out);
      return true;
    case MAT_C_UINT32:
      convert<std::uint32_t>(variable.data, out);
      return true;
    case MAT_C_INT64:
      convert<std::int64_t>(variable.data, out);
      return true;
    case MAT_C_UINT64:
      convert<std::uint64_t>(variable.data, out);
      return true;
    default:
      return false;
  }
}

bool is_valid_matlab_name(std::string_view name) {
  if (name.empty() || name.size() > 63) return false;
  const auto is_letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (!is_letter(name.front())) return false;
  for (char c : name) {
    if (!is_letter(c) && !(c >= '0' && c <= '9') && c != '_') return false;
  }
  return true;
}

//! The reserved temporary file: removed on destruction unless committed.
class ReservedMatFile {
 public:
  explicit ReservedMatFile(fs::path path) : path_(std::move(path)) {}
  ReservedMatFile(const ReservedMatFile&) = delete;
  ReservedMatFile& operator=(const ReservedMatFile&) = delete;
  ~ReservedMatFile() {
    if (!committed_) ::unlink(path_.c_str());
  }
  const fs::path& path() const { return path_; }
  void commit() { committed_ = true; }

 private:
  fs::path path_;
  bool committed_ = false;
};

fs::path reserved_mat_path(const fs::path& path) {
  static std::atomic<unsigned long long> counter{0};
  const std::string target = path.filename().string().substr(0, 200);
  return path.parent_path() / fmt::format(".{}.tmp.{}.{}", target,
                                          static_cast<long long>(::getpid()), counter.fetch_add(1));
}

[[noreturn]] void fail_write(const fs::path& path, std::string_view why) {
  throw Error(fmt::format("cannot write '{}': {}", path.string(), why));
}

void validate_variables(const fs::path& path,
                        const std::vector<std::pair<std::string, std::vector<double>>>& variables) {
  if (variables.empty()) fail_write(path, "no variables given");
  std::set<std::string_view> seen;
  for (const auto& [name, values] : variables) {
    if (!is_valid_matlab_name(name)) {
      fail_write(path, fmt::format("variable name '{}' is not a valid MATLAB name (a letter, then "
                                   "letters, digits or '_', at most 63 characters)",
                                   name));
    }
    if (!seen.insert(name).second) {
      fail_write(path, fmt::format("variable name '{}' is given twice", name));
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (!std::isfinite(values[k])) {
        fail_write(path, fmt::format("variable '{}': {}[{}] = {} is not finite", name, name, k,
                                     values[k]));
      }
    }
  }
}

}  // namespace

MatVersion mat_version_from_string(std::string_view text) {
  return hyst::detail::value_named(text, enum_names<MatVersion>, "MAT file version");
}

std::vector<std::string> list_mat_variables(const fs::path& path) {
  const MatHandle mat = open_for_reading(path);
  return variable_names(mat.get());
}

namespace {

// The values of a real numeric variable in column-major order, with its rows and columns; a
// matrix is accepted only when `matrix_allowed`.
struct NumericVariable {
  std::vector<double> values;
  std::size_t rows = 0;
};

NumericVariable read_numeric(const fs::path& path, std::string_view variable, bool matrix_allowed) {
  const MatHandle mat = open_for_reading(path);
  const auto names = variable_names(mat.get());
  if (std::find(names.begin(), names.end(), variable) == names.end()) {
    throw Error(fmt::format(
        "{}: no variable '{}' (variables: {})", path.string(), variable,
        names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))));
  }
  const std::string name(variable);
  const auto prefix = fmt::format("{}: variable '{}'", path.string(), name);
  const VarHandle info(Mat_VarReadInfo(mat.get(), name.c_str()));
  if (!info) throw Error(fmt::format("{} cannot be read", prefix));

  if (const auto what = class_description(info->class_type); !what.empty()) {
    throw Error(fmt::format("{} is {}, expected a real numeric vector", prefix, what));
  }
  if (info->isComplex) throw Error(fmt::format("{} is complex, expected a real vector", prefix));
  if (info->rank > 2) {
    throw Error(fmt::format("{} is a {} array, expected a vector", prefix, dimensions(*info)));
  }
  if (!matrix_allowed && info->rank == 2 && info->dims[0] > 1 && info->dims[1] > 1) {
    throw Error(fmt::format("{} is a {} matrix, expected a vector", prefix, dimensions(*info)));
  }
  // As a double first: the product of the dimensions may overflow std::size_t.
  double claimed = 1.0;
  for (int d = 0; d < info->rank; ++d)
    claimed *= static_cast<double>(info->dims[d]);
  if (info->class_type == MAT_C_EMPTY || claimed == 0.0) return {};
  if (claimed * sizeof(double) > static_cast<double>(limits::kMaxMatVariableBytes)) {
    throw Error(
        fmt::format("{} claims {} samples ({:.0f} bytes as doubles), more than the limit "
                    "of {} bytes ({} samples) for one variable",
                    prefix, dimensions(*info), claimed * sizeof(double),
                    limits::kMaxMatVariableBytes, limits::kMaxMatVariableBytes / sizeof(double)));
  }
  const auto count = static_cast<std::size_t>(claimed);
  // matio allocates what the dimensions claim before it reads the data; a corrupt file may claim
  // billions of samples (found by fuzz/fuzz_mat_file). No file holds more samples than bytes,
  // times the best compression ratio of zlib (1032:1) - allow 2048.
  if (const auto bytes = fs::file_size(path); count / 2048 > bytes) {
    throw Error(fmt::format("{} claims {} samples, more than a file of {} bytes can hold", prefix,
                            dimensions(*info), bytes));
  }

  VarHandle data;
  std::vector<double> values;
  try {
    data.reset(Mat_VarRead(mat.get(), name.c_str()));
    if (!data || data->data == nullptr) throw Error(fmt::format("{} cannot be read", prefix));
    values.resize(count);
  } catch (const std::bad_alloc&) {
    throw Error(fmt::format("{}: out of memory reading {} samples ({} bytes)", prefix, count,
                            count * sizeof(double)));
  }
  if (!convert_numeric(*data, values)) {
    throw Error(fmt::format("{} has MATLAB class number {}, expected a real numeric vector", prefix,
                            static_cast<int>(data->class_type)));
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k])) {
      throw Error(fmt::format("{}: {}[{}] = {} is not finite", prefix, name, k, values[k]));
    }
  }
  return {std::move(values), info->rank >= 1 ? static_cast<std::size_t>(info->dims[0]) : 1};
}

}  // namespace

std::vector<double> read_mat_vector(const fs::path& path, std::string_view variable) {
  return read_numeric(path, variable, false).values;
}

std::vector<std::vector<double>> read_mat_columns(const fs::path& path, std::string_view variable) {
  auto variable_data = read_numeric(path, variable, true);
  std::vector<std::vector<double>> columns;
  const std::size_t rows = variable_data.rows;
  if (rows == 0) return columns;
  for (std::size_t start = 0; start < variable_data.values.size(); start += rows) {
    columns.emplace_back(variable_data.values.begin() + static_cast<std::ptrdiff_t>(start),
                         variable_data.values.begin() + static_cast<std::ptrdiff_t>(start + rows));
  }
  return columns;
}

void write_mat_vectors(const fs::path& path,
                       const std::vector<std::pair<std::string, std::vector<double>>>& variables,
                       MatVersion version) {
  if (path.filename().empty() || path.filename() == "." || path.filename() == "..") {
    fail_write(path, "the path does not name a file");
  }
  validate_variables(path, variables);
  // A link is followed (its target replaced); a device or FIFO is written through, from a
  // temporary file in the temporary folder (matio writes files only).
  const OutputTarget target = resolve_output(path);
  const bool special = target.kind == OutputKind::special;

  // Reserve a unique temporary name (O_EXCL), then let matio write it.
  const fs::path temporary_path =
      reserved_mat_path(special ? fs::temp_directory_path() / target.path.filename() : target.path);
  const int reserved =
      ::open(temporary_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (reserved < 0) {
    fail_write(path, fmt::format("{} (creating the temporary file '{}')", errno_message(errno),
                                 temporary_path.string()));
  }
  ::close(reserved);
  ReservedMatFile temporary(temporary_path);

  {
    MatHandle mat(Mat_CreateVer(temporary.path().c_str(), nullptr,
                                version == MatVersion::v7_3 ? MAT_FT_MAT73 : MAT_FT_MAT5));
    if (!mat) {
      fail_write(path, fmt::format("matio cannot create the {} file '{}'", to_string(version),
                                   temporary.path().string()));
    }
    for (const auto& [name, values] : variables) {
      std::size_t dims[2] = {values.size(), 1};
      // MAT_F_DONT_COPY_DATA: matio only reads the samples and does not free them.
      const VarHandle variable(Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                             const_cast<double*>(values.data()),
                                             MAT_F_DONT_COPY_DATA));
      if (!variable) fail_write(path, fmt::format("matio cannot create variable '{}'", name));
      if (const int error = Mat_VarWrite(mat.get(), variable.get(), MAT_COMPRESSION_NONE)) {
        fail_write(
            path, fmt::format("matio failed to write variable '{}' (matio error {})", name, error));
      }
    }
    if (const int error = Mat_Close(mat.release())) {
      fail_write(path, fmt::format("matio failed to close '{}' (matio error {})",
                                   temporary.path().string(), error));
    }
  }

  if (special) {
    write_file_atomically(target.path, read_file(temporary.path()));
    return;
  }

  // Flush to disk, keep the permission bits of a file being replaced, rename over the target.
  const int fd = ::open(temporary.path().c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0)
    fail_write(path, fmt::format("{} (reopening the temporary file)", errno_message(errno)));
  struct stat target_status {};
  if (::stat(target.path.c_str(), &target_status) == 0 && S_ISREG(target_status.st_mode)) {
    static_cast<void>(::fchmod(fd, target_status.st_mode & 07777));  // best effort
  }
  int sync_result;
  while ((sync_result = ::fsync(fd)) != 0 && errno == EINTR) {
  }
  const int sync_error = errno;
  ::close(fd);
  if (sync_result != 0)
    fail_write(path, fmt::format("{} (flushing to disk)", errno_message(sync_error)));

  std::error_code rename_error;
  fs::rename(temporary.path(), target.path, rename_error);
  if (rename_error) {
    fail_write(path, fmt::format("{} (renaming '{}' over it)", rename_error.message(),
                                 temporary.path().string()));
  }
  temporary.commit();
  const int folder =
      ::open(target.path.parent_path().empty() ? "." : target.path.parent_path().c_str(),
             O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder >= 0) {
    static_cast<void>(::fsync(folder));  // best effort: makes the rename durable
    ::close(folder);
  }
}

}  // namespace hyst::io
