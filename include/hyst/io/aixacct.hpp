#pragma once
//! \file
//! Reader for the text export of aixACCT "aixPlorer" ferroelectric/piezo analysers (TF Analyzer),
//! the format of ../shared/data/piezo_pzt_aixacct_butterfly/RMN_TRAP_SLOW.dat.
//!
//! Layout (tab separated, LF or CRLF line ends, every table line may end with a tab):
//!
//!     PiezoResult                           <- first line: the kind of export ("...Result")
//!
//!     Table 1                               <- the summary table: one row per measurement
//!     Table No [#]  Vc+ [V]  Vc- [V] ...       (header of "name [unit]" fields, then rows)
//!     1.000000e+000 1.119650e+003 ...
//!
//!     Piezo                                 <- a title line, then the file header:
//!     Program: aixPlorer Software ...          "key: value" lines
//!
//!     Table 1                               <- measurement table 1: "key: value" metadata ...
//!     SampleName: TEST_0.1Hz
//!     Hysteresis Amplitude [V]: 1400
//!     Time [s]  V+ [V]  V- [V]  I1 [A] ...  <- ... up to the first line with a tab: the column
//!     0.000000e+000 7.904505e+001 ...          header; then data rows up to a blank line
//!
//! Tables before the first title line form the summary (at most one); the others are the
//! measurement tables, numbered as in the file. A column header field "V+ [V]" gives the column
//! name "V+" and unit "V" ("Averages []": unit ""; a field without brackets has no unit). Numbers
//! are parsed exactly (std::from_chars, locale independent, 3-digit exponents and a leading '+'
//! accepted) and must be finite. The reader checks that every row has as many fields as the
//! header, that column names are unique in a table, that every metadata line is "key: value",
//! that table numbers are unique, and that every table has a header and at least one row.
//!
//! Errors throw hyst::Error naming the file, the 1-based physical line, the table and the column:
//!     RMN_TRAP_SLOW.dat:1010: table 3: column 5 ('P1 [uC/cm2]'): 'x' is not a number

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hyst/io/csv.hpp"

namespace hyst::io {

//! One column of an aixACCT table.
struct AixacctColumn {
  std::string name;  //!< e.g. "V+"
  std::string unit;  //!< e.g. "V"; empty for "[]" or no brackets
  std::vector<double> values;

  //! The header field as in the file: "V+ [V]", or the name alone without a unit.
  std::string header() const;
};

//! One table: metadata (measurement tables only) and named columns of equal length.
struct AixacctTable {
  std::size_t number = 0;      //!< N of the "Table N" line
  std::size_t first_line = 0;  //!< 1-based line of "Table N"
  //! "key: value" lines in file order, trimmed; the key keeps its unit ("DOffset [nm]").
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<AixacctColumn> columns;

  std::size_t rows() const { return columns.empty() ? 0 : columns.front().values.size(); }
  //! The column whose name ("V+") or header ("V+ [V]") is `name`, or nullptr.
  const AixacctColumn* find(std::string_view name) const;
  //! As find(), but throws hyst::Error "file: table 3: no column 'x' (columns: Time [s], ...)".
  const AixacctColumn& column(std::string_view name, std::string_view source = {}) const;
  //! The text of a metadata entry (exact key, e.g. "SampleName"), or nullopt.
  std::optional<std::string> metadata_text(std::string_view key) const;
  //! A numeric metadata entry ("Hysteresis Amplitude [V]" -> 1400); nullopt if absent or not a
  //! number.
  std::optional<double> metadata_number(std::string_view key) const;
  //! The columns as a Table whose names are the headers ("V+ [V]"); `source` names it.
  Table to_table(std::string source = {}) const;
};

struct AixacctFile {
  std::string source;  //!< file name as given (for messages)
  std::string kind;    //!< the first line, e.g. "PiezoResult"
  //! Title lines (e.g. "Piezo") and the "key: value" lines of the file header, in file order.
  std::vector<std::string> titles;
  std::vector<std::pair<std::string, std::string>> header;
  std::optional<AixacctTable> summary;     //!< the summary table, when the file has one
  std::vector<AixacctTable> measurements;  //!< in file order

  //! The measurement table numbered `number` ("Table 3" -> 3); throws hyst::Error listing the
  //! numbers there are.
  const AixacctTable& measurement(std::size_t number) const;
};

//! True when the text starts like an aixACCT export: its first line is a single word ending in
//! "Result" and a "Table N" line follows. Used to tell such files from CSV by their content.
bool looks_like_aixacct(std::string_view text);

//! Parses the text of an export; `source_name` prefixes error messages.
AixacctFile parse_aixacct(std::string_view text, std::string_view source_name);
//! Reads and parses a file; errors name the path as given.
AixacctFile read_aixacct(const std::filesystem::path& path);

}  // namespace hyst::io
