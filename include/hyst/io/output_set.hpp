#pragma once
//! \file
//! Several output files of one run published as a whole (POSIX), so that a reader, even after
//! the run was killed at any point (SIGKILL), finds either the complete old set or the complete
//! new one, never a mix.
//!
//! The scheme, in the output folder F:
//!
//!     F/ranking.md    -> .hyst-current/ranking.md     (one relative link per published name)
//!     F/.hyst-current -> .hyst-set.4711.0             (the one link that is switched)
//!     F/.hyst-set.4711.0/ranking.md ...               (the files of the published set)
//!
//! A run writes its files into a new staging folder F/.hyst-set.<pid>.<n>, then switches
//! F/.hyst-current to it with one rename(), which is atomic: every name changes at once. Names
//! new to the set get their link beforehand (it dangles, so the name reads as absent, until the
//! switch); names the new set lacks lose their link afterwards. Plain files left under a name by
//! an older hyst are first hard-linked into the current set and then replaced by the link, so
//! their content never changes under a reader. After the switch the old set folder is removed.
//! A name may also be a folder of files staged in the set (hyst batch's model files of records
//! in subfolders): its link then leads into the set like a file's.
//! Every temporary name lies inside a set folder; the set folders of runs that died are removed
//! by the next run. Two runs publishing into the same folder at the same time are not supported.

#include <filesystem>
#include <string>
#include <vector>

namespace hyst::io {

class OutputSet {
 public:
  //! Prepares publishing into `folder` (created when missing, with its parents): checks that none
  //! of `names` (the files the set will hold, as far as known) is something other than a file or a
  //! link of an earlier set (a folder, a device, a link elsewhere), removes set folders of dead
  //! runs and creates the staging folder. Throws hyst::Error naming the folder or the file.
  OutputSet(std::filesystem::path folder, const std::vector<std::string>& names);
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  //! Removes the staging folder unless the set was published.
  ~OutputSet();

  //! Where to write the file `name` of the set (inside the staging folder).
  std::filesystem::path staged(const std::string& name) const;
  //! The path a reader uses for `name` once the set is published: folder / name.
  std::filesystem::path published(const std::string& name) const { return folder_ / name; }

  //! Makes the staged files the published set, as a whole (see above).
  void publish();

 private:
  std::filesystem::path folder_;
  std::filesystem::path staging_;
  bool published_ = false;
};

}  // namespace hyst::io
