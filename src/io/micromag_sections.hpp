#pragma once
// The sectioned layout of MicroMag 2900/3900 exports, shared by the loop reader (Series 0015 and
// 0016 loop files) and the FORC reader (Series 0016 FORC files): after the format and title
// lines, "key   value" header entries in sections (a section name such as "INSTRUMENT" alone on
// its line), an optional segment table ("Number of segments N": N comma rows), then the stacked
// column titles right above the first data row:
//
//     Units of measure                Hybrid SI       <- key and value apart by 2+ blanks or a tab
//     Number of segments              2
//
//     Segment   Averaging ...                         <- segment table titles and rows
//     0000001,+100.0000E-03,...
//
//                                   Normalized        <- column titles (text lines after the last
//          Field         Moment       Moment             blank line before the data)
//     +7.997968E-01,+2.921634E-05,+1.000000E+00       <- the first data row (left pending)

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "line_reader.hpp"
#include "text_fields.hpp"

namespace hyst::io::detail {

//! Segment and data rows start with a number and hold a comma; header lines start with a letter.
bool is_comma_row(std::string_view content);

class MicromagSectionReader {
 public:
  //! `lines` has returned the format and the title lines; the reader continues from there.
  MicromagSectionReader(LineReader& lines, std::string_view source)
      : lines_(lines), source_(source) {}

  //! Reads the header entries (values converted from Latin-1 to UTF-8 where needed) and, when the
  //! header declares "Number of segments", the segment table, up to the first data row. Returns
  //! the number of segment rows (0 without a table). Throws hyst::Error naming the file and line
  //! for a header that does not end, a malformed segment table or a table without data.
  std::size_t read_head(HeaderEntries& header);

  //! The first data row (trimmed), after read_head().
  std::string_view first_row() const { return first_row_; }
  //! The column title lines above it, untrimmed (their alignment names the columns).
  const std::vector<std::string_view>& titles() const { return titles_; }

  //! The next line, trimmed; false after the last one.
  bool next_content(std::string_view& line);
  //! The 1-based number of the line read last.
  std::size_t line_number() const { return lines_.number(); }

  //! "FILE:LINE: the file ends without the line 'MicroMag 2900/3900 Data File ends' (truncated?)".
  [[noreturn]] void throw_truncated() const;

 private:
  void read_segment_table(std::optional<double> declared, std::size_t& rows);

  LineReader& lines_;
  std::string_view source_;
  std::string_view raw_line_;
  std::string_view first_row_;
  std::vector<std::string_view> titles_;
};

}  // namespace hyst::io::detail
