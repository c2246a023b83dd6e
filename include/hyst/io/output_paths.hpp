#pragma once
//! \file
//! What an output path may be, checked before any work (POSIX).
//!
//! An output never replaces what it must not:
//!  - a symbolic link is followed to its final target; the target is written, the link is kept;
//!  - a character or block device or a FIFO is written through (opened for writing, no rename);
//!  - a socket or a folder is refused;
//!  - an output that is the same file as an input (same device and inode, also through links
//!    and hard links), or two outputs that are the same file, are refused, naming both;
//!  - "-" stands for standard output (of the command line's text outputs) and never names a file.

#include <filesystem>
#include <string>
#include <vector>

namespace hyst::io {

//! How an output is written once its links are followed.
enum class OutputKind {
  file,     //!< a regular file, or nothing yet: replaced atomically (write_file_atomically())
  special,  //!< a character or block device or a FIFO: opened for writing, written through
};

struct OutputTarget {
  std::filesystem::path path;  //!< the final target (the given path when it is not a link)
  OutputKind kind = OutputKind::file;
};

//! Follows `path` through its symbolic links (at most 40) to what will be written. Throws
//! hyst::Error "cannot write 'PATH': WHY" when the target is a folder or a socket, when the folder
//! of a target that does not exist yet is missing, or on a link loop.
OutputTarget resolve_output(const std::filesystem::path& path);

//! A path and how the user named it in messages, e.g. {"fit.json", "--out"}.
struct NamedPath {
  std::filesystem::path path;
  std::string name;
};

//! Refuses, before any work, outputs that would replace what they must not: every output is
//! resolved (resolve_output()), none may be the same file as an input, no two may be the same
//! file. An input that does not exist is skipped (its reader reports it). Throws hyst::Error
//! naming the option and the path, e.g. "--out 'x.csv' is the same file as the input --input
//! 'x.csv'; choose another output" or "--out 'a.json' and --report 'a.json' are the same file".
void check_outputs(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace hyst::io
