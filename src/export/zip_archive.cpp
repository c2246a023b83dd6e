// The zip archive of an FMU, in memory, through libzip (fmu_parts.hpp).

#include <zip.h>

#include <memory>
#include <string>

#include <fmt/format.h>

#include "fmu_parts.hpp"
#include "hyst/core/error.hpp"

namespace hyst::detail {
namespace {

// 1980-01-01, the first time a zip entry can hold: the same members, the same bytes.
constexpr time_t kFixedTime = 315532800;

struct SourceFree {
  void operator()(zip_source_t* source) const { zip_source_free(source); }
};

[[noreturn]] void fail(std::string_view what, zip_error_t* error) {
  throw Error(
      fmt::format("FMU export: cannot {} the archive: {}", what, zip_error_strerror(error)));
}

}  // namespace

std::string zip_archive(std::span<const ArchiveMember> members) {
  zip_error_t error;
  zip_error_init(&error);
  std::unique_ptr<zip_source_t, SourceFree> buffer(zip_source_buffer_create(nullptr, 0, 0, &error));
  if (!buffer) fail("create", &error);
  zip_t* archive = zip_open_from_source(buffer.get(), ZIP_TRUNCATE, &error);
  if (archive == nullptr) fail("open", &error);
  zip_source_keep(buffer.get());  // the bytes are read after zip_close()
  for (const auto& member : members) {
    zip_source_t* source = zip_source_buffer(archive, member.bytes.data(), member.bytes.size(), 0);
    const zip_int64_t index =
        source == nullptr ? -1
                          : zip_file_add(archive, member.name.c_str(), source, ZIP_FL_ENC_UTF_8);
    if (index < 0) {
      zip_source_free(source);
      const std::string reason = zip_strerror(archive);
      zip_discard(archive);
      throw Error(
          fmt::format("FMU export: cannot add '{}' to the archive: {}", member.name, reason));
    }
    zip_file_set_mtime(archive, static_cast<zip_uint64_t>(index), kFixedTime, 0);
  }
  if (zip_close(archive) != 0) {
    const std::string reason = zip_strerror(archive);
    zip_discard(archive);
    throw Error(fmt::format("FMU export: cannot write the archive: {}", reason));
  }
  zip_stat_t stat;
  if (zip_source_open(buffer.get()) != 0 || zip_source_stat(buffer.get(), &stat) != 0) {
    fail("read", zip_source_error(buffer.get()));
  }
  std::string bytes(static_cast<std::size_t>(stat.size), '\0');
  const zip_int64_t read = zip_source_read(buffer.get(), bytes.data(), stat.size);
  zip_source_close(buffer.get());
  if (read < 0 || static_cast<zip_uint64_t>(read) != stat.size) {
    fail("read", zip_source_error(buffer.get()));
  }
  return bytes;
}

}  // namespace hyst::detail
