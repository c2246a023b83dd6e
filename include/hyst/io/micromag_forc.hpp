#pragma once
//! \file
//! Reader for first-order reversal curve (FORC) files of Princeton Measurements MicroMag 2900/3900
//! magnetometers (AGM/VSM), format "MicroMag 2900/3900 Data File (Series 0015)", "First-order
//! reversal curves", as exported by the instrument software.
//!
//! Layout (text, CRLF or LF line ends):
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
//! Blocks separated by blank lines alternate: one drift-calibration measurement at HCal (near
//! saturation), then one FORC; a trailing calibration block is allowed. Units follow "Units of
//! measure": "Hybrid SI" = field mu0 H in T, moment in A m^2 (cgs: Oe, emu). The reader checks the
//! first line, that every data line is "field,moment" with two finite numbers (std::from_chars,
//! locale independent, a leading '+' accepted), that calibration blocks have one point, that the
//! point count equals NData when the header has it, and that the end marker is present (a
//! truncated file fails). Errors throw hyst::Error naming the file and the 1-based line:
//!     conventional_example.forc:57: 'x.2,+5e-7' is not 'field,moment' with two numbers
//!
//! Drift: the calibration moment m_cal drifts during a run (here by 1.3 % over 120 curves).
//! correct_drift() rescales (multiplicative: sensitivity drift) or shifts (additive: offset
//! drift) every moment by the drift interpolated linearly between the calibration measured before
//! and after its curve, relative to the first calibration.
//! Source of the format: the example file shipped with PmagPy
//! (../shared/data/pmagpy_forc_micromag_agm, see its PROVENANCE.md). PmagPy's own forc_diagram.py
//! reads such files by splitting at the maximum field and ignores the calibration points; this
//! reader follows the block structure.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hyst::io {

struct MicromagForcFile {
  struct Curve {
    double calibration_field = 0.0;   //!< of the calibration point measured before the curve
    double calibration_moment = 0.0;  //!< [moment units]
    std::vector<double> field;        //!< field[0] is the reversal field H_r [field units]
    std::vector<double> moment;       //!< [moment units], same length
    std::size_t first_line = 0;       //!< 1-based line of field[0] in the file
  };

  std::string source;  //!< file name as given (for messages)
  std::string format;  //!< the first line
  std::string title;   //!< the second line, e.g. "First-order reversal curves"
  //! "key = value" and "key : value" header lines, trimmed, in file order.
  std::vector<std::pair<std::string, std::string>> header;
  std::vector<Curve> curves;
  //! A calibration point after the last curve, if the file has one: {field, moment}.
  std::optional<std::pair<double, double>> final_calibration;

  //! The text of a header entry, or nullopt.
  std::optional<std::string> header_text(std::string_view key) const;
  //! A numeric header entry ("HCal" -> 0.2350512); nullopt if absent or not a number.
  std::optional<double> header_number(std::string_view key) const;
  //! Number of data points of all curves.
  std::size_t points() const;
};

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
std::string_view to_string(ForcDriftCorrection correction);
ForcDriftCorrection forc_drift_correction_from_string(std::string_view text);

//! The file with every moment corrected for drift: m_cal(t) for point i of an n-point curve is
//! interpolated between the calibration before it (k) and the one after it (k + 1, or the final
//! calibration; none: the one before) at (i + 1) / (n + 1); m_cal,0 is the first calibration.
//! Calibration moments are corrected too (they become m_cal,0). Throws hyst::Error if a
//! calibration moment needed for the multiplicative form is 0.
MicromagForcFile correct_drift(MicromagForcFile file, ForcDriftCorrection correction);

}  // namespace hyst::io
