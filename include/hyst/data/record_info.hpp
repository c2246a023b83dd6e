#pragma once
//! \file
//! What a measured data file holds, as 'hyst data info' and hyst.data.info() show it: its tables
//! (aixACCT summary and measurement tables, the one CSV table, or a MAT file's variables), each
//! column's unit, length and range, the reversal points and cycles of each column with a
//! hysteresis band of `band_fraction` x its range, and optionally the loop figures of every cycle
//! of an (input, output) pair of columns (loop_metrics.hpp). A MicroMag loop file also shows its
//! segments, the units of its columns and its initial (virgin) curve, which the loop cycles leave
//! out (they start after it); a MicroMag FORC file shows its curves (ForcInfo) instead of tables.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/data/loop_metrics.hpp"

namespace hyst::data {

struct RecordInfoOptions {
  std::optional<std::size_t> table;  //!< only this measurement table of an aixACCT export
  double band_fraction = 0.02;       //!< hysteresis band as a fraction of each column's range
  //! {input, output} columns (by name or "name [unit]" header): also the figures of each cycle.
  std::optional<std::pair<std::string, std::string>> loop;
  //! The time column [s] (by name or "name [unit]" header) of every table that has it; "": an
  //! aixACCT table's 'Time' column where there is one. With it, each table shows its time axis
  //! and each column its largest rate and its longest run between reversals.
  std::string time;
};

//! A table's time axis (sample_time.hpp's rules of uniformity).
struct TimeAxisInfo {
  std::string column;
  bool uniform = true;
  double sample_time = 0.0;  //!< the uniform step, or the median step of a non-uniform axis [s]
  double min_step = 0.0, max_step = 0.0;  //!< [s]
  double duration = 0.0;                  //!< last minus first time [s]
};

struct ColumnInfo {
  std::string name;
  std::string unit;  //!< "" without a unit
  std::size_t samples = 0;
  std::string problem;  //!< why a MAT variable has no values (a matrix, text ...); "" otherwise
  double min = 0.0, max = 0.0;  //!< 0 without samples
  //! Counts with the band; none for constant columns and columns of fewer than 2 samples.
  std::optional<std::size_t> reversals, cycles;
  //! With a time axis (not for the time column itself): the largest |x[k] - x[k-1]| / step
  //! [unit / s], and the longest time between neighbouring reversal points (or the record's ends)
  //! with the band [s]: the longest ramp or hold a model fitted on this column has seen.
  std::optional<double> largest_rate, longest_run;
};

struct TableInfo {
  std::string title;  //!< "table 3", "summary", "table" (CSV), "variables" (MAT)
  //! Metadata worth a glance (aixACCT: sample, waveform, frequency, amplitude), in file order.
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<ColumnInfo> columns;
  std::size_t rows = 0;              //!< samples of the first column
  std::vector<LoopMetrics> loops;    //!< one per cycle of the loop columns, when asked and present
  std::optional<TimeAxisInfo> time;  //!< when the table has the time column
};

//! The curves of a MicroMag FORC file (io/micromag_forc.hpp), as measured (no drift correction).
struct ForcInfo {
  std::string layout;  //!< "Series 0015" or "Series 0016"
  std::size_t curves = 0;
  std::size_t points = 0;              //!< of all curves, calibration points not counted
  std::size_t calibration_points = 0;  //!< one before each curve, and a final one if present
  std::size_t fewest_points = 0;       //!< of one curve
  std::size_t most_points = 0;
  double field_min = 0.0, field_max = 0.0;        //!< over every curve point
  double reversal_min = 0.0, reversal_max = 0.0;  //!< of the reversal fields H_r (first points)
  std::optional<double> calibration_field;        //!< HCal of the header
  //! Range of the fields at which the calibration points were measured.
  double calibration_field_min = 0.0, calibration_field_max = 0.0;
  //! 100 (m_cal,last / m_cal,first - 1): how far the calibration moment drifted over the run.
  double calibration_drift_percent = 0.0;
  std::string field_unit, moment_unit;  //!< "" when unknown
};

struct RecordInfo {
  std::string file;
  std::string format;  //!< e.g. "CSV, 3 columns", "aixACCT export (PiezoResult), ..."
  double band_fraction = 0.02;
  std::vector<TableInfo> tables;  //!< none for a FORC file
  std::optional<ForcInfo> forc;   //!< for a MicroMag FORC file
};

//! Reads the file (io::DataFile's rules for its kind) and describes it. Throws hyst::Error for an
//! unreadable file, a band_fraction outside (0, 1), a table that does not exist or a table asked
//! of a file other than an aixACCT export, a time column that no table has, and a time column
//! that is not finite and strictly increasing (naming the table, column and sample).
RecordInfo record_info(const std::filesystem::path& path, const RecordInfoOptions& options);

//! {"file", "format", "band_fraction", "tables": [{"table", "metadata"?, "columns": [{"name",
//! "unit", "samples", "problem"? | "min", "max", "reversals", "cycles", "largest_rate"?,
//! "longest_run"?}], "time"?: {"column", "uniform", "sample_time", "min_step", "max_step",
//! "duration"}, "loops"?: [{"first",
//! "last", "area", "closure_error", "input_mismatch", "coercive_inputs", "remanent_outputs"}]}]}
//! where counts are null when not defined and crossings are {"value", "index", "direction"};
//! for a FORC file "tables" is empty and "forc" holds ForcInfo by its member names.
nlohmann::json record_info_json(const RecordInfo& info);

}  // namespace hyst::data
