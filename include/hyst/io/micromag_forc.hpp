#pragma once
//! \file
//! Reader for first-order reversal curve (FORC) files of Princeton Measurements MicroMag 2900/3900
//! magnetometers (AGM/VSM), as exported by the instrument software, in every layout below; which
//! one a file has is read from its header (a "NData = N" entry: Series 0015; no header at all:
//! the older two-line exports; else Series 0016), not from a flag. One header reader serves all
//! of them: "key = value", "key : value" and "key   value" entries in any order and any section,
//! up to the first data row; a segment table (titled "Segment ... Number", or rows numbered
//! "0000001,...") is skipped. "Number of segments" is the script's count of field sweeps (a VSM
//! FORC file writes it, e.g. 100, with no table); it is checked against the table's rows only
//! where the file has a table.
//!
//! Series 0015 (AGM) layout (text, CRLF or LF line ends):
//!
//!     MicroMag 2900/3900 Data File (Series 0015)      <- first line, identifies the format
//!     First-order reversal curves                      <- title
//!     Configuration   :  AGM                           <- header: "key : value", "key = value",
//!     HCal           = +2.350512E-01                      and free text lines
//!     ...
//!     NData          = 8514                            <- last header line: number of data points
//!                                                      <- blank line
//!     +2.370455E-01,+7.842043E-07                      <- calibration point (field, moment)
//!                                                      <- blank line
//!     +1.154643E-01,+5.992140E-07                      <- FORC: starts at its reversal field H_r,
//!     +1.183070E-01,+6.057562E-07                         then sweeps up
//!     ...
//!     MicroMag 2900/3900 Data File ends                <- end marker
//!
//! Series 0016 (VSM) layout: the header of the Series 0016 loop files (micromag_loop.hpp):
//! sections of "key   value" entries (key and value apart by 2+ blanks or a tab; "HCal",
//! "NForc", "Number of data" ...), then column titles stacked over two or more lines above the
//! data, with a units line whose "Am²" is written in Latin-1 (converted to UTF-8 here), and a
//! third column "Normalized Moment":
//!
//!     MicroMag 2900/3900 Data File (Series 0016.002)
//!     First-order reversal curves
//!
//!     INSTRUMENT
//!     Configuration                   VSM
//!     ...
//!     HCal                           +500.0000E-03
//!     Number of data                  1234
//!
//!                                  Normalized
//!          Field         Moment      Moment
//!           (T)          (Am²)         ( )
//!     +5.000123E-01,+1.234567E-05,+1.000000E+00    <- calibration point
//!
//!     -1.000000E-01,-2.345678E-06,-1.900000E-01    <- FORC ...
//!
//! Older exports ("MicroMag 2900/3900 Data File" without a series) have no header: the format
//! line, the title ("First-order reversal curves" or "Direct moment vs. field; First-order
//! reversal curves"), then the data from line 3; columns "Field", "Moment", units unknown.
//!
//! In every layout the data are blocks apart by blank lines: one drift-calibration point measured
//! at HCal (near saturation) before every curve, then the curve; a trailing calibration block is
//! allowed. A calibration point may also open its curve's block (its field above the curve's
//! first, reversal field: the field falls from HCal to H_r). A file without calibration points
//! is refused with the block that breaks the alternation. Units follow the units line, else
//! "Units of measure": "Hybrid SI" = field mu0 H in T, moment in A m^2 ("Cgs": Oe, emu); a file
//! with neither leaves them "" (unknown).
//!
//! The reader checks the first line, that every data row is comma-separated finite numbers
//! (std::from_chars, locale independent, a leading '+' accepted; "field,moment" in Series 0015,
//! 2 or more columns, the same in every row, in Series 0016), that a curve has its calibration
//! point, that the point count equals NData / "Number of data" when the header has it (in Series
//! 0016 the count with or without the calibration points), and that the end marker is present
//! (a truncated file fails). Blank lines, CRLF line ends and extra header keys are fine. Errors
//! throw hyst::Error naming the file and the 1-based line:
//!     conventional_example.forc:57: 'x.2,+5e-7' is not 'field,moment' with two finite numbers
//! Cost: at most limits::kMaxInputBytes read, limits::kMaxForcCurves curves and
//! limits::kMaxForcPoints data points (hyst/io/limits.hpp); beyond them an error names the limit.
//!
//! Drift: the calibration moment m_cal drifts during a run (here by 1.3 % over 120 curves).
//! correct_drift() rescales (multiplicative: sensitivity drift) or shifts (additive: offset
//! drift) every moment by the drift interpolated linearly between the calibration measured before
//! and after its curve, relative to the first calibration.
//! Source of the formats: the example file shipped with PmagPy
//! (../shared/data/pmagpy_forc_micromag_agm, see its PROVENANCE.md) for Series 0015; the key
//! spellings, "Hybrid SI" / "Cgs" and the two-line older header as public FORC readers describe
//! them (FORCIT's and FORCsensei's descriptions of MicroMag files, RockPy's MicroMag titles and
//! numbered segment rows); a measured VSM FORC file refused for its "Number of segments 100"
//! (no table) for the segment rule; for Series
//! 0016 the header of the Series 0016 loop files (../shared/data/hystlab_vsm_hysteresis_loops)
//! and the description of VSM FORC files (the header keys FORC programs read: HCal, NForc,
//! "Number of data"); tests/data/micromag/series_0016.forc is a small file built from them.
//! PmagPy's own forc_diagram.py reads such files by splitting at the maximum field and ignores
//! the calibration points; this reader follows the block structure.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hyst/core/enum_names.hpp"

namespace hyst::io {

using hyst::to_string;

//! Which header a FORC file has (see the file comment).
enum class MicromagForcLayout : unsigned char {
  series_0015,  //!< "key = value" / "key : value" header ending with "NData = N" (AGM)
  series_0016,  //!< sections of "key   value" entries and stacked column titles (VSM)
  no_header,    //!< the format and title lines only, the data from line 3 (older exports)
};
//! "series_0015", "series_0016", "no_header" (Python's MicromagForcFile.layout).
constexpr EnumNames<MicromagForcLayout, 3> enumerator_names(MicromagForcLayout) {
  return {{
      {MicromagForcLayout::series_0015, "series_0015"},
      {MicromagForcLayout::series_0016, "series_0016"},
      {MicromagForcLayout::no_header, "no_header"},
  }};
}

struct MicromagForcFile {
  struct Curve {
    double calibration_field = 0.0;   //!< of the calibration point measured before the curve
    double calibration_moment = 0.0;  //!< [moment units]
    std::vector<double> field;        //!< field[0] is the reversal field H_r [field units]
    std::vector<double> moment;       //!< [moment units], same length
    //! The columns after field and moment (columns[2...], e.g. "Normalized Moment"), each as
    //! long as field; correct_drift() leaves them as measured.
    std::vector<std::vector<double>> more_columns;
    std::size_t first_line = 0;  //!< 1-based line of field[0] in the file
  };

  std::string source;  //!< file name as given (for messages)
  std::string format;  //!< the first line
  std::string title;   //!< the second line, e.g. "First-order reversal curves"
  MicromagForcLayout layout = MicromagForcLayout::series_0015;
  //! Header entries, trimmed, in file order: "key = value" and "key : value" lines (Series
  //! 0015), "key   value" lines (Series 0016; text converted from Latin-1 to UTF-8).
  std::vector<std::pair<std::string, std::string>> header;
  //! Data column names ("Field", "Moment", "Normalized Moment") and units ("T", "A m²" or, from
  //! a units line, "Am²"; "" when unknown), one each per column.
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::vector<Curve> curves;
  //! A calibration point after the last curve, if the file has one: {field, moment}.
  std::optional<std::pair<double, double>> final_calibration;

  //! The text of a header entry, or nullopt.
  std::optional<std::string> header_text(std::string_view key) const;
  //! A numeric header entry ("HCal" -> 0.2350512); nullopt if absent or not a number.
  std::optional<double> header_number(std::string_view key) const;
  //! Number of data points of all curves (calibration points not counted).
  std::size_t points() const;
  //! Calibration points: one per curve and the final one.
  std::size_t calibration_points() const { return curves.size() + (final_calibration ? 1 : 0); }
};

//! True when `text` starts like a MicroMag FORC file (its first two lines).
bool looks_like_micromag_forc(std::string_view text);
//! Parses the text of a FORC file; `source_name` prefixes error messages.
MicromagForcFile parse_micromag_forc(std::string_view text, std::string_view source_name);
//! Reads and parses a file; errors name the path as given ("cannot open ...", "file:line: ...").
MicromagForcFile read_micromag_forc(const std::filesystem::path& path);

enum class ForcDriftCorrection : unsigned char {
  none,
  multiplicative,  //!< m' = m * m_cal,0 / m_cal(t): a drifting sensitivity
  additive,        //!< m' = m - (m_cal(t) - m_cal,0): a drifting offset
};
//! "none", "multiplicative", "additive" and back (hyst::Error for other text).
constexpr EnumNames<ForcDriftCorrection, 3> enumerator_names(ForcDriftCorrection) {
  return {{
      {ForcDriftCorrection::none, "none"},
      {ForcDriftCorrection::multiplicative, "multiplicative"},
      {ForcDriftCorrection::additive, "additive"},
  }};
}
ForcDriftCorrection forc_drift_correction_from_string(std::string_view text);

//! The file with every moment corrected for drift: m_cal(t) for point i of an n-point curve is
//! interpolated between the calibration before it (k) and the one after it (k + 1, or the final
//! calibration; none: the one before) at (i + 1) / (n + 1); m_cal,0 is the first calibration.
//! Calibration moments are corrected too (they become m_cal,0). Throws hyst::Error if a
//! calibration moment needed for the multiplicative form is 0.
MicromagForcFile correct_drift(MicromagForcFile file, ForcDriftCorrection correction);

}  // namespace hyst::io
