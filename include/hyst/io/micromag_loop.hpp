#pragma once
//! \file
//! Reader for hysteresis loop files of Princeton Measurements MicroMag 2900/3900 magnetometers
//! (VSM/AGM), "Direct moment vs. field; Hysteresis loop", as the instrument software exports them
//! (extensions .hys, .hyst, .loop or a running number .000, .001, ...).
//!
//! Layout (text, CRLF or LF line ends):
//!
//!     MicroMag 2900/3900 Data File (Series 0016.002)   <- first line, identifies the format
//!     Direct moment vs. field; Hysteresis loop         <- title
//!                                                      <- sections of "key   value" lines
//!     INSTRUMENT                                          (key and value apart by 2+ blanks)
//!     Units of measure                Hybrid SI
//!     ...
//!     Number of segments              2
//!     Number of data                  402              <- (newer series) the point count
//!
//!     Segment   Averaging      Initial  ...            <- segment table: title lines and one
//!      Number      Time         Field   ...               comma row per field sweep segment
//!     0000001,+100.0000E-03,+500.0000E-03,...
//!     0000002,+100.0000E-03,-500.0000E-03,...
//!
//!          Raw           Raw         Adjusted      Adjusted    <- column titles, stacked and
//!         Field         Moment        Field         Moment        aligned over the columns;
//!          (T)          (Am2)          (T)          (Am2)         a units line is optional
//!     +7.997968E-01,+2.921634E-05,+7.997968E-01,+1.899436E-05  <- data: one row per point
//!     ...                                                      <- a blank line between
//!                                                                 field sweep segments
//!     MicroMag 2900/3900 Data File ends                <- end marker
//!
//! Keys may come in any order and also as "key = value" or "key : value". The segment table is
//! known by its titles ("Segment ... Number") or its numbered rows ("0000001,..."); a file
//! may have "Number of segments" without a table (then `segments` is 0) or a table without the
//! count. Older exports have only the format line ("MicroMag 2900/3900 Data File") and the
//! title, then the data from line 3: columns "Field" and "Moment", units unknown.
//!
//! The data are the last block of comma rows; the first two columns are always the field and the
//! moment as measured, further ones are e.g. a temperature or the "Adjusted" field and moment
//! after the software's slope and offset correction. Columns are named from their title lines
//! ("Field", "Moment", "Adjusted Moment", ...; "Column 3" when the titles cannot be matched).
//! Units follow "Units of measure": "Hybrid SI" = field mu0 H in T, moment in A m^2 ("cgs": Oe,
//! emu); a units line under the titles ("(T)  (Am²)", the "²" a Latin-1 byte) gives them per
//! column. Header text and units are converted from Latin-1 to UTF-8 where they are not UTF-8.
//!
//! The reader checks the first line and the title (a FORC file is pointed to
//! read_micromag_forc()), that every data row has the same number of fields and that each is a
//! finite number (std::from_chars, locale independent, a leading '+' accepted), that the number of
//! segment table rows equals "Number of segments" when the file has both, that the number of
//! points equals "Number of data" when the header has it, and that the end marker is present (a
//! truncated file fails). Errors throw hyst::Error naming the file, the 1-based line and the
//! column:
//!     CP4Q.hyst:95: column 2 ('Raw Moment'): '+2.9x-05' is not a finite number
//!
//! Source of the format: the HystLab example data (../shared/data/hystlab_vsm_hysteresis_loops,
//! series 0015, 0016.000 and 0016.002; see its PROVENANCE.md).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hyst/io/csv.hpp"

namespace hyst::io {

struct MicromagLoopFile {
  std::string source;  //!< file name as given (for messages)
  std::string format;  //!< the first line
  std::string title;   //!< the second line, "Direct moment vs. field; Hysteresis loop"
  //! "key   value" header lines, trimmed, in file order (section names such as "INSTRUMENT" are
  //! not entries; a key used in two sections, e.g. "Averaging time", appears twice).
  std::vector<std::pair<std::string, std::string>> header;
  std::size_t segments = 0;  //!< rows of the segment table (0 without one, whatever the count)
  std::vector<std::string> columns;  //!< data column names, unique, in file order
  //! Unit of each column: from the units line under the titles ("T", "Am²"; Latin-1 converted to
  //! UTF-8), else implied by "Units of measure" and the name ("Hybrid SI": Field T, Moment A m²);
  //! "" when unknown.
  std::vector<std::string> units;
  std::vector<std::vector<double>> values;  //!< values[j] belongs to columns[j]; equal lengths
  //! Index of the first point of each segment (the data's blank-line separated blocks); [0] = 0.
  std::vector<std::size_t> segment_starts;
  std::size_t first_data_line = 0;  //!< 1-based line of the first point
  //! Points of the initial (virgin) curve at the start of the data, measured from the
  //! demagnetised state when the header says "Initial magnetization? Yes": the first data block,
  //! or (without blank lines) the points before the field first turns back. 0 without one. The
  //! loop cycles start after it.
  std::size_t initial_curve_points = 0;

  //! The text of the first header entry with this key, or nullopt.
  std::optional<std::string> header_text(std::string_view key) const;
  //! A numeric header entry ("Field increment" -> 0.005); nullopt if absent or not a number.
  std::optional<double> header_number(std::string_view key) const;
  //! Number of points.
  std::size_t points() const { return values.empty() ? 0 : values.front().size(); }
  //! The column with this name; throws hyst::Error naming the file and listing the columns.
  const std::vector<double>& column(std::string_view name) const;
  //! The measured field and moment: the first two columns.
  const std::vector<double>& field() const { return values.at(0); }
  const std::vector<double>& moment() const { return values.at(1); }
  //! The data as a table named by the columns (as io::DataFile offers it).
  Table to_table() const;
};

//! True when `text` starts like a MicroMag hysteresis loop file (its first two lines).
bool looks_like_micromag_loop(std::string_view text);
//! Parses the text of a loop file; `source_name` prefixes error messages.
MicromagLoopFile parse_micromag_loop(std::string_view text, std::string_view source_name);
//! Reads and parses a file; errors name the path as given ("cannot read ...", "file:line: ...").
MicromagLoopFile read_micromag_loop(const std::filesystem::path& path);

}  // namespace hyst::io
