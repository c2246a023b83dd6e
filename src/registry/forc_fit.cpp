#include "hyst/registry/forc_fit.hpp"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "field_table.hpp"
#include "hyst/core/error.hpp"
#include "hyst/identify/fitted_domain.hpp"
#include "tabulated_preisach_model.hpp"

namespace hyst {

namespace {

detail::FieldTable<PreisachForcFitOptions> forc_fit_option_table() {
  using O = PreisachForcFitOptions;
  using detail::Presence;
  return detail::FieldTable<O>(Presence::optional)
      .add("intervals", &O::intervals, "",
           "K: uniform table levels x_0 .. x_K, K(K+1)/2 cell weights")
      .add("lower", &O::lower, "input units",
           "lower end of the table (default: the lowest field of all curves)")
      .add("upper", &O::upper, "input units",
           "upper end of the table (default: the largest field of all curves; set it to HSat "
           "when relays may switch up above the largest measured field)")
      .add("saturation", &O::saturation, preisach_initial_state_from_string,
           "where every curve starts: positive_saturation (magnetometers) or "
           "negative_saturation")
      .add("smoothness", &O::smoothness, "", "Tikhonov weight on neighbouring cell weights")
      .add("fit_offset", &O::fit_offset, "", "fit the output offset");
}

}  // namespace

std::vector<ParameterInfo> forc_fit_options() {
  return forc_fit_option_table().schema();
}

PreisachForcFitOptions forc_fit_options_from_json(const nlohmann::json& options) {
  return forc_fit_option_table().read(options, "fit options");
}

std::vector<std::size_t> every_nth_curve(std::size_t curves, std::size_t n) {
  if (n == 1) {
    throw Error("holding out every 1st curve leaves none to fit; use N >= 2", "hold_out_every");
  }
  std::vector<std::size_t> indices;
  if (n == 0) return indices;
  for (std::size_t k = n - 1; k < curves; k += n)
    indices.push_back(k);
  return indices;
}

std::vector<ReversalCurve> reversal_curves(const io::MicromagForcFile& file) {
  std::vector<ReversalCurve> curves;
  curves.reserve(file.curves.size());
  for (const auto& curve : file.curves)
    curves.push_back({.input = curve.field, .output = curve.moment});
  return curves;
}

ForcModelFit fit_forc_curves(std::span<const ReversalCurve> curves,
                             const PreisachForcFitOptions& options) {
  auto fit = fit_preisach_forcs(curves, options);
  // The domain of the curves fitted (the held-out ones are not); FORCs have no time axis.
  std::vector<FittedDomain> parts;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (std::find(options.held_out.begin(), options.held_out.end(), k) == options.held_out.end())
      parts.push_back(fitted_domain(curves[k].input, curves[k].output));
  }
  if (!parts.empty()) fit.report.domain = merged_domain(parts);
  ForcModelFit result{detail::tabulated_preisach_model(fit.model), std::move(fit.report),
                      options.held_out, options};
  result.options.lower = fit.model.lower();
  result.options.upper = fit.model.upper();
  return result;
}

ForcModelFit fit_forc_file(const io::MicromagForcFile& file, const ForcFitRequest& request) {
  auto options = forc_fit_options_from_json(request.options);
  const auto corrected = io::correct_drift(file, request.drift);
  const auto curves = reversal_curves(corrected);
  options.held_out = every_nth_curve(curves.size(), request.hold_out_every);
  if (request.hold_out_every > 0 && options.held_out.empty()) {
    throw Error(fmt::format("{}: holding out every {}th curve holds out none of its {} curves",
                            file.source, request.hold_out_every, curves.size()),
                "hold_out_every");
  }
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (const auto& curve : curves) {
    const auto [low, high] = std::minmax_element(curve.input.begin(), curve.input.end());
    lowest = std::min(lowest, *low);
    highest = std::max(highest, *high);
  }
  if (!options.lower) options.lower = lowest;
  if (!options.upper) options.upper = highest;
  try {
    return fit_forc_curves(curves, options);
  } catch (const Error& error) {
    throw Error(fmt::format("{}: {}", file.source, error.what()), error.field());
  }
}

}  // namespace hyst
