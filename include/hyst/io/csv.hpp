#pragma once
//! \file
//! Time series as delimited text: one header line of column names, then one row of numbers per
//! line.
//!
//! Reading accepts what measurement software writes: ',', ';', tab or runs of spaces between
//! fields (detected from the header line), spaces around fields, CRLF line ends, a UTF-8 byte
//! order mark, blank lines and whole-line comments starting with '#'. Every number is parsed
//! exactly (std::from_chars, locale independent; a leading '+' is accepted) and must be finite.
//! Not supported: quoted fields, decimal commas, comments after data on the same line.
//!
//! Errors throw hyst::Error naming the file, the physical line (1-based, counting every line,
//! comments and blank ones too) and the column (1-based field index and header name):
//!     data.csv:7: column 2 ('y'): 'abc' is not a number
//!
//! Writing uses 17 significant digits by default, so a write -> read round trip gives back every
//! double exactly, and replaces the file atomically (see atomic_file.hpp).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hyst::io {

//! Named columns of equal length.
struct Table {
  std::vector<std::string> names;            //!< column headers, unique and not empty
  std::vector<std::vector<double>> columns;  //!< columns[j] belongs to names[j]; equal lengths
  std::string source;                        //!< file name for error messages; may be empty

  //! Number of rows (the length of the columns; 0 without columns).
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  //! Number of columns.
  std::size_t cols() const { return names.size(); }

  bool has_column(std::string_view name) const;
  //! The column with this name; throws hyst::Error "data.csv: no column 'x' (columns: t, v, y)".
  const std::vector<double>& column(std::string_view name) const;
  //! Appends a column. Throws hyst::Error if the name is empty, has surrounding spaces or a line
  //! break, is already taken, or the length differs from rows() of a table that has columns.
  void add_column(std::string name, std::vector<double> values);
};

struct CsvReadOptions {
  //! Field separator; 0 = detect from the header line: tab if it has one, else ';', else ',',
  //! else runs of spaces/tabs. ' ' also means runs of spaces/tabs.
  char separator = 0;
  //! Lines whose first non-blank character is this are skipped; 0 = no comments.
  char comment = '#';
};

//! Parses delimited text; `source_name` (e.g. the file name) prefixes error messages and becomes
//! Table::source. Throws hyst::Error (see the file comment).
Table parse_csv(std::string_view text, std::string_view source_name,
                const CsvReadOptions& options = {});

//! Reads and parses a file; error messages name the path as given.
Table read_csv(const std::filesystem::path& path, const CsvReadOptions& options = {});

struct CsvWriteOptions {
  //! ',', ';', '\t' or ' '. Column names must not contain the separator, nor a separator that
  //! automatic detection would prefer to it (so that read_csv() finds the same columns).
  char separator = ',';
  //! Significant digits of each number, 1..17; 17 round-trips every double exactly.
  int significant_digits = 17;
};

//! The table as text: a header line, then one line per row, each ending in '\n'. Throws
//! hyst::Error unless the table has columns and rows, is rectangular, its names are valid and
//! unique, and every value is finite (naming column and row).
std::string format_csv(const Table& table, const CsvWriteOptions& options = {});

//! format_csv() written atomically to `path` (write_file_atomically()).
void write_csv(const std::filesystem::path& path, const Table& table,
               const CsvWriteOptions& options = {});

}  // namespace hyst::io
