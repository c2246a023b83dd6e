#include "fit_forc.hpp"

#include <fmt/format.h>

#include "commands.hpp"
#include "hyst/io/micromag_forc.hpp"
#include "hyst/registry/forc_fit.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

nlohmann::json metrics_json(const ErrorMetrics& metrics) {
  return {{"samples", metrics.samples},
          {"rmse", metrics.rmse},
          {"nrmse_percent", metrics.nrmse_percent},
          {"max_error", metrics.max_error}};
}

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
  nlohmann::json info = {{"created_by", "hyst fit"},
                         {"model", report.model},
                         {"method", report.method},
                         {"status", std::string(report.status())},
                         {"termination", std::string(to_string(report.termination))},
                         {"message", report.message},
                         {"iterations", report.iterations},
                         {"initial_cost", report.initial_cost},
                         {"final_cost", report.final_cost},
                         {"parameters", report.parameters},
                         {"fit", metrics_json(report.fit)},
                         {"seconds", report.seconds},
                         {"data", data},
                         {"options", options},
                         {"preprocessing", report.preprocessing}};
  if (report.validation) info["validation"] = metrics_json(*report.validation);

  const std::string model_text = model_to_json(*fit.model, info).dump(2) + "\n";
  const std::string report_text = report.full();
  if (arguments.report.empty()) {
    write_text_outputs({{arguments.out, model_text}});
  } else {
    write_text_outputs({{arguments.out, model_text}, {arguments.report, report_text}});
  }
  auto* messages = message_stream(is_stdout(arguments.out) || is_stdout(arguments.report));
  fmt::print(messages, "{}\n", report.brief());
  fmt::print(messages, "wrote {}{}\n", arguments.out,
             arguments.report.empty() ? "" : fmt::format(" and {}", arguments.report));
  if (report.status() != "converged") {
    warn(fmt::format("the fit is not converged ({}): {}", report.status(), report.message));
  }
}

}  // namespace hyst::cli
