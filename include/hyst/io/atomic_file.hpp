#pragma once
//! \file
//! Whole-file reading and crash-safe writing (POSIX).
//!
//! write_file_atomically() never leaves a partial file under the final name: the content goes to a
//! temporary file in the same folder (".<name>.tmp.<pid>.<counter>"), which is flushed to disk
//! (fsync), closed and then renamed over the target in one step. A reader sees either the old
//! file or the complete new one. On failure the temporary file is removed and the target, if it
//! existed, is left as it was.
//!
//! The output path is resolved first (output_paths.hpp): a symbolic link is followed and its
//! target replaced (the temporary file goes into the target's folder; the link stays), and a
//! device or FIFO is written through (opened for writing, no temporary file, no rename).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "hyst/io/limits.hpp"

namespace hyst::io {

//! Replaces (or creates) the file at `path` with `content`, atomically. An existing file keeps its
//! permission bits. A missing folder is created (with its parents). A link is followed; a device or
//! FIFO is written through; a folder or socket is refused. Throws hyst::Error naming the path and
//! the reason, e.g. "cannot write 'out/fit.csv': No such file or directory (creating the temporary
//! file 'out/.fit.csv.tmp.4711.0')".
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

//! One file of a set written by write_files_atomically().
struct FileContent {
  std::filesystem::path path;
  std::string_view content;
};

//! Replaces several files that belong together (a C header and its source, a model file and its
//! report), each as write_file_atomically() does, but in two phases: every content is first
//! written to its temporary file and flushed to disk, then the temporary files are renamed over
//! their targets one right after the other, with no other work in between. An error or a kill
//! while the contents are written (the long part) leaves every target as it was; only a kill
//! between two renames, a window of microseconds, leaves some targets new and the rest old.
//! Files in one folder that must never be seen mixed go into an OutputSet (output_set.hpp).
void write_files_atomically(std::span<const FileContent> files);

//! The whole content of a file, byte for byte, at most limits::kMaxInputBytes (256 MiB; a longer
//! file or an endless stream is an error). Throws hyst::Error naming the path and the reason,
//! e.g. "cannot open 'x.csv': No such file or directory".
std::string read_file(const std::filesystem::path& path);

}  // namespace hyst::io
