#include "fit_forc.hpp"

#include <fmt/format.h>

#include "commands.hpp"
#include "fitted_model_output.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/registry/forc_fit.hpp"

namespace hyst::cli {
namespace {

std::string ordinal(std::size_t n) {
  const auto tens = n % 100;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : n % 10 == 1              ? "st"
                       : n % 10 == 2              ? "nd"
                       : n % 10 == 3              ? "rd"
                                                  : "th";
  return fmt::format("{}{}", n, suffix);
}

}  // namespace

void run_forc_fit(const ForcFitArguments& arguments) {
  if (arguments.model != "preisach" && arguments.model != "tabulated_preisach") {
    throw Error(fmt::format(
        "--forc identifies the Preisach model ('hyst fit preisach --forc FILE'); the model '{}' "
        "is not fitted from first-order reversal curves",
        arguments.model));
  }
  std::vector<io::NamedPath> outputs{{arguments.out, "--out"}};
  if (!arguments.report.empty()) outputs.push_back({arguments.report, "--report"});
  io::check_outputs({{arguments.forc, "--forc"}}, outputs);

  ForcFitRequest request;
  request.drift = io::forc_drift_correction_from_string(arguments.drift);
  request.hold_out_every = arguments.hold_out_every;
  request.options = arguments.options;
  const auto file = io::read_micromag_forc(arguments.forc);
  auto fit = fit_forc_file(file, request);
  auto& report = fit.report;

  std::size_t held_points = 0;
  for (const auto index : fit.held_out)
    held_points += file.curves[index].field.size();
  report.preprocessing.push_back(
      request.drift == io::ForcDriftCorrection::none
          ? std::string("moments as measured (no drift correction)")
          : fmt::format("moments corrected for the drift of the calibration points ({})",
                        io::to_string(request.drift)));
  if (!fit.held_out.empty()) {
    report.validation_rule = fmt::format(
        "held-out curves: every {} of {} FORCs ({} curves, {} points), each predicted from "
        "saturation",
        ordinal(request.hold_out_every), file.curves.size(), fit.held_out.size(), held_points);
  }
  if (report.termination == Termination::failed) {
    throw Error(fmt::format("fitting '{}' to the FORCs of {} failed: {}", report.model,
                            arguments.forc, report.message));
  }

  nlohmann::json data = {{"file", arguments.forc},
                         {"kind", "MicroMag FORC file"},
                         {"format", file.format},
                         {"curves", file.curves.size()},
                         {"points", file.points()},
                         {"drift", std::string(io::to_string(request.drift))},
                         {"hold_out_every", request.hold_out_every},
                         {"held_out_curves", fit.held_out.size()},
                         {"held_out_points", held_points}};
  auto options = arguments.options;
  options["lower"] = *fit.options.lower;
  options["upper"] = *fit.options.upper;
  options["intervals"] = fit.options.intervals;
  write_fitted_model(*fit.model, fit_info_json(report, data, options), report, arguments.out,
                     arguments.report);
}

}  // namespace hyst::cli
