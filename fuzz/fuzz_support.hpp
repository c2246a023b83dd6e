#pragma once
// Helpers shared by the fuzz targets (one target per file in this folder).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace hyst::fuzz {

//! The fuzz input as text (it may contain any byte, including NUL).
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

//! A private scratch folder for this process, for readers that take a path (created once,
//! removed at exit).
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    const char* base = std::getenv("TMPDIR");
    auto path = std::filesystem::path(base && *base ? base : "/tmp") /
                ("hyst-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  // Registered after `folder` is complete, so it runs before `folder` is destroyed.
  [[maybe_unused]] static const bool removed_at_exit =
      std::atexit([] {
        std::error_code ignored;
        std::filesystem::remove_all(scratch_folder(), ignored);
      }) == 0;
  return folder;
}

//! Writes `content` to `name` in the scratch folder (plain write: the readers are under test, not
//! the writer) and returns the path.
inline std::filesystem::path scratch_file(std::string_view name, std::string_view content) {
  const auto path = scratch_folder() / std::string(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return path;
}

}  // namespace hyst::fuzz
