#pragma once
//! \file
//! The Preisach model identified from first-order reversal curves (fit_preisach_forcs,
//! hyst/identify/fit_preisach.hpp) as a registered model, 'tabulated_preisach', that model files,
//! the command line ('hyst fit preisach --forc FILE') and Python (hyst.fit_preisach_forcs) share:
//! the curves of a MicroMag FORC file (io/micromag_forc.hpp), its drift correction, curves held
//! out for validation, and the fit options by name.
//!
//! Table range: options "lower" and "upper" when given; otherwise, for a file, the lowest to the
//! largest field of all its curves (held-out ones included, so that they lie inside the table).
//! The levels are uniform, so a range beyond the curves (e.g. up to the saturating field HSat far
//! above them) spends cells where no curve is measured; set "upper" to HSat when relays may
//! switch up between the largest measured field and HSat (docs/results.md).

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "hyst/identify/fit_preisach.hpp"
#include "hyst/identify/fit_report.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/registry/dynamic_model.hpp"
#include "hyst/registry/model_registry.hpp"

namespace hyst {

struct ForcFitRequest {
  io::ForcDriftCorrection drift = io::ForcDriftCorrection::none;
  //! 0: every curve is fitted; N >= 2: curves N, 2N, 3N, ... (1-based) are held out and
  //! predicted (report.validation).
  std::size_t hold_out_every = 0;
  //! Fit options by name (forc_fit_options()): intervals, lower, upper, saturation, smoothness,
  //! fit_offset.
  nlohmann::json options = nlohmann::json::object();
};

struct ForcModelFit {
  std::unique_ptr<DynamicModel> model;  //!< 'tabulated_preisach', in its initial state
  FitReport report;
  std::vector<std::size_t> held_out;  //!< 0-based indices of the held-out curves
  PreisachForcFitOptions options;     //!< as used, lower and upper set
};

//! The fit options of a FORC fit, for 'hyst models' and help texts.
std::vector<ParameterInfo> forc_fit_options();

//! The options by name; hyst::Error names the field ("fit options.intervals: ...") and refuses
//! unknown names.
PreisachForcFitOptions forc_fit_options_from_json(const nlohmann::json& options);

//! The 0-based indices N-1, 2N-1, ... below `curves`; hyst::Error for n = 1 (nothing left to fit).
//! n = 0: none.
std::vector<std::size_t> every_nth_curve(std::size_t curves, std::size_t n);

//! One reversal curve per FORC of the file: input = field, output = moment, viewed (the file
//! must outlive them).
std::vector<ReversalCurve> reversal_curves(const io::MicromagForcFile& file);

//! fit_preisach_forcs() with the model wrapped as a registered model.
ForcModelFit fit_forc_curves(std::span<const ReversalCurve> curves,
                             const PreisachForcFitOptions& options);

//! Drift correction, held-out curves and the table range of the file comment, then
//! fit_forc_curves(). Throws hyst::Error as the reader and the fit do.
ForcModelFit fit_forc_file(const io::MicromagForcFile& file, const ForcFitRequest& request);

}  // namespace hyst
