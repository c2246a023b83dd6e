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
//!  - a missing folder is created, with its missing parents, when the output is written;
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

//! Follows `path` through its symbolic links (at most 40) to what will be written. A target
//! whose folder is missing is fine: the writer creates the folder (create_output_folder()).
//! Throws hyst::Error "cannot write 'PATH': WHY" when the target is a folder or a socket, when
//! the first existing parent of its folder is not a folder (a file), or on a link loop.
OutputTarget resolve_output(const std::filesystem::path& path);

//! Creates `folder` and its missing parents, as `mkdir -p` does; an existing folder is left as it
//! is. Throws hyst::Error "cannot create the folder 'a/b/c': 'a/b' is not a folder" (or the
//! system's reason, e.g. "Permission denied").
void create_output_folder(const std::filesystem::path& folder);

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
