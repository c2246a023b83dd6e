#pragma once
// Named columns of a measured data file, as the command line and hyst.data read them: a CSV table
// (hyst/io/csv.hpp), the vector variables of a MATLAB .mat file (hyst/io/mat_file.hpp), or one
// table of an aixACCT export (hyst/io/aixacct.hpp), or the data columns of a MicroMag hysteresis
// loop file (hyst/io/micromag_loop.hpp: "Field", "Moment", "Adjusted Moment", ...). A ".mat"
// extension (any case) means a MAT file; other files are aixACCT exports or MicroMag loop files
// when their text starts like one (io::looks_like_aixacct, io::looks_like_micromag_loop), CSV
// otherwise. A MicroMag FORC file is refused with a pointer to 'hyst fit preisach --forc': its
// curves, each measured after saturation, are not one input/output record.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hyst/io/aixacct.hpp"
#include "hyst/io/csv.hpp"

namespace hyst::io {

class DataFile {
 public:
  //! Reads a CSV file or an aixACCT export completely, or lists the variables of a MAT file;
  //! throws hyst::Error naming the file (and line and column for syntax errors). `table` chooses
  //! the measurement table of an aixACCT export (1-based as in the file); it may be omitted when
  //! the export has only one, and must be omitted for other files.
  explicit DataFile(std::filesystem::path path, std::optional<std::size_t> table = {});

  const std::filesystem::path& path() const { return path_; }
  bool is_mat() const { return mat_; }
  bool is_micromag_loop() const { return micromag_loop_; }
  //! The whole export when the file is an aixACCT export, else nullptr.
  const AixacctFile* aixacct() const { return aixacct_ ? &*aixacct_ : nullptr; }
  //! Column (variable) names in file order.
  const std::vector<std::string>& columns() const { return names_; }
  bool has_column(std::string_view name) const;

  //! The values of one column; throws hyst::Error "d.csv: no column 'x' (columns: t, v, y)", or
  //! for MAT files the reader's message naming the variable (not a vector, not finite, ...).
  //! An aixACCT column is found by its name ("V+") or its header ("V+ [V]").
  std::vector<double> column(std::string_view name) const;

  //! The column to use for an option: `given` when not empty (it must exist); otherwise the only
  //! column of the file, or `preferred` when the file has a column of that name. Throws
  //! hyst::Error listing the columns and naming `option` when neither applies.
  std::string choose(std::string_view given, std::string_view preferred,
                     std::string_view option) const;

  //! The unit of a column where the file states it (aixACCT: "V" of "V+ [V]"; MicroMag loop
  //! files: "T", "Am²", "Oe", "emu" from the units line or "Units of measure"), else "".
  std::string unit(std::string_view name) const;

  //! "t, v, y".
  std::string column_list() const;

  //! The columns `names` (every column when empty) as a table named by `names`; throws
  //! hyst::Error when a column is missing or the columns differ in length.
  Table columns_table(const std::vector<std::string>& names) const;

 private:
  std::filesystem::path path_;
  bool mat_ = false;
  bool micromag_loop_ = false;
  Table table_;  //!< CSV, MicroMag and aixACCT (the chosen table, named by headers)
  std::optional<AixacctFile> aixacct_;
  std::size_t aixacct_table_ = 0;  //!< index into aixacct_->measurements
  std::vector<std::string> names_;
  std::vector<std::string> units_;  //!< per column of names_ (MicroMag loop files), else empty
};

//! True for a ".mat" extension in any case (read as a MAT file).
bool has_mat_extension(const std::filesystem::path& path);

//! The aixACCT export in `path` when the file is one (by its content, see io::looks_like_aixacct),
//! else nullopt (also for .mat files, which are not read). Throws hyst::Error when the file cannot
//! be read or the export is malformed.
std::optional<AixacctFile> read_if_aixacct(const std::filesystem::path& path);

}  // namespace hyst::io
