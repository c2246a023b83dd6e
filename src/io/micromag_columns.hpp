#pragma once
// Names and units of the data columns of a MicroMag export from the title lines stacked above
// the data (the loop reader and the FORC reader of Series 0016 files):
//
//          Raw           Raw         Normalized     <- qualifiers over the name they stand above
//         Field         Moment         Moment       <- the line with one word per column
//          (T)          (Am2)           (-)         <- an optional units line, "(...)" per column

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hyst::io::detail {

//! Column names: "Field", "Raw Moment", "Normalized Moment"; "Column 3" for every column when no
//! title line has one word per column ("Field", "Moment", "Column 3", ... when there is no title
//! line at all); a name used twice gets its column number.
std::vector<std::string> column_names(const std::vector<std::string_view>& titles,
                                      std::size_t count);

//! The units of the units line ("T", "Am²": Latin-1 converted to UTF-8), one per column; all
//! empty when no title line has one "(...)" word per column.
std::vector<std::string> column_units(const std::vector<std::string_view>& titles,
                                      std::size_t count);

}  // namespace hyst::io::detail
