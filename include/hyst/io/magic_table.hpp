#pragma once
//! \file
//! Reader for tables in the MagIC format of the Magnetics Information Consortium (earthref.org),
//! the text format PmagPy reads and writes, and the hysteresis loops of a measurements table.
//!
//! Layout (text, tab-separated, CRLF or LF line ends):
//!
//!     tab \tmagic_measurements                    <- "tab" (or "tab delimited"), the table name
//!     er_specimen_name\tmagic_experiment_name\t...    <- column names
//!     IS06a-1\tIS06a-1:LP-HYS\t...                    <- one row per measurement, text cells
//!
//! A file holding several tables separates them by a line starting with ">>>>>"; this reader
//! reads the first. Every row must have as many cells as there are column names (trailing empty
//! cells may be left out). Errors throw hyst::Error naming the file, the 1-based line and the
//! column:
//!     hysteresis_magic_example.dat:7: column 'measurement_magn_moment': 'abc' is not a number
//!
//! magic_hysteresis_loops() collects the rows whose method codes contain "LP-HYS" (hysteresis
//! loop) by experiment, in file order. It knows the column names of MagIC 2.5
//! (measurement_lab_field_dc, measurement_magn_moment, magic_method_codes, magic_experiment_name,
//! er_specimen_name) and of MagIC 3 (meas_field_dc, magn_moment, method_codes, experiment,
//! specimen). Field in T, moment in A m^2 as MagIC defines them (the values of a file are what
//! its author stored; see the data set's provenance).
//! Source of the format: https://www.earthref.org/MagIC/data-models and the example file shipped
//! with PmagPy (../shared/data/pmagpy_forc_micromag_agm, see its PROVENANCE.md).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hyst::io {

struct MagicTable {
  std::string source;                          //!< file name as given (for messages)
  std::string name;                            //!< e.g. "magic_measurements", "measurements"
  std::vector<std::string> columns;            //!< column names, in file order
  std::vector<std::vector<std::string>> rows;  //!< rows[i][j] belongs to columns[j], trimmed
  std::vector<std::size_t> row_lines;          //!< 1-based line of rows[i]

  //! Index of a column, or nullopt.
  std::optional<std::size_t> find(std::string_view column) const;
};

//! Parses the text of a MagIC table; `source_name` prefixes error messages.
MagicTable parse_magic_table(std::string_view text, std::string_view source_name);
//! Reads and parses a file; errors name the path as given.
MagicTable read_magic_table(const std::filesystem::path& path);

struct MagicHysteresisLoop {
  std::string specimen;        //!< e.g. "IS06a-1"
  std::string experiment;      //!< e.g. "IS06a-1:LP-HYS"
  std::vector<double> field;   //!< applied field [T], in the order measured
  std::vector<double> moment;  //!< same length
  std::size_t first_line = 0;  //!< 1-based line of the first point
};

//! The hysteresis loops (method code LP-HYS) of a measurements table, one per experiment, in the
//! order their first rows appear. Throws hyst::Error when a needed column is missing (naming the
//! names it looked for) or a field or moment cell of a loop row is not a finite number (naming
//! file, line and column).
std::vector<MagicHysteresisLoop> magic_hysteresis_loops(const MagicTable& table);

}  // namespace hyst::io
