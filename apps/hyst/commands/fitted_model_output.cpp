#include "fitted_model_output.hpp"

#include <utility>

#include <fmt/format.h>

#include "commands.hpp"
#include "hyst/registry/fitted_domain_file.hpp"
#include "hyst/registry/model_file.hpp"

namespace hyst::cli {
namespace {

nlohmann::json metrics_json(const ErrorMetrics& metrics) {
  return {{"samples", metrics.samples},
          {"rmse", metrics.rmse},
          {"nrmse_percent", metrics.nrmse_percent},
          {"max_error", metrics.max_error}};
}

}  // namespace

nlohmann::json fit_info_json(const FitReport& report, nlohmann::json data, nlohmann::json options) {
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
                         {"data", std::move(data)},
                         {"options", std::move(options)}};
  if (report.validation) info["validation"] = metrics_json(*report.validation);
  if (!report.quality_note.empty()) info["simulation"] = report.quality_note;
  if (!report.references.empty()) {
    nlohmann::json references = nlohmann::json::array();
    for (const auto& reference : report.references) {
      references.push_back(
          reference.validation
              ? nlohmann::json{{"name", reference.name},
                               {"validation", metrics_json(*reference.validation)}}
              : nlohmann::json{{"name", reference.name}, {"error", reference.error}});
    }
    info["references"] = references;
    if (const auto beats = report.beats_yardstick()) info["beats_yardstick"] = *beats;
  }
  if (!report.preprocessing.empty()) info["preprocessing"] = report.preprocessing;
  if (report.domain) info["domain"] = fitted_domain_json(*report.domain);
  return info;
}

void write_fitted_model(const DynamicModel& model, const nlohmann::json& info,
                        const FitReport& report, const std::string& out,
                        const std::string& report_path) {
  // The model file and its report are replaced together (see write_text_outputs()).
  const std::string model_text = model_to_json(model, info).dump(2) + "\n";
  if (report_path.empty()) {
    write_text_outputs({{out, model_text}});
  } else {
    write_text_outputs({{out, model_text}, {report_path, report.full()}});
  }
  auto* messages = message_stream(is_stdout(out) || is_stdout(report_path));
  fmt::print(messages, "{}\n", report.brief());
  fmt::print(messages, "wrote {}{}\n", out,
             report_path.empty() ? "" : fmt::format(" and {}", report_path));
  if (report.status() != "converged") {
    warn(fmt::format("the fit is not converged ({}): {}", report.status(),
                     report.quality_note.empty() ? report.message : report.quality_note));
  }
}

}  // namespace hyst::cli
