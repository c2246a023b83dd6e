#include "hyst/models/ikuta_sma.hpp"

#include <fmt/format.h>

#include "../core/detail/enum_names.hpp"
#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

// In the order of the parser's message, which lists the resting branch first.

void require_finite_parameter(double value, std::string_view field, std::string_view symbol) {
  if (!std::isfinite(value)) {
    throw Error(fmt::format("Ikuta {} {} = {} is not finite", field, symbol, value),
                std::string(field));
  }
}

void validate(const IkutaSma::Params& p) {
  require_finite_parameter(p.martensite_finish, "martensite_finish", "M_f");
  require_finite_parameter(p.martensite_start, "martensite_start", "M_s");
  require_finite_parameter(p.austenite_start, "austenite_start", "A_s");
  require_finite_parameter(p.austenite_finish, "austenite_finish", "A_f");
  require_finite_parameter(p.output_austenite, "output_austenite", "y_A");
  require_finite_parameter(p.output_martensite, "output_martensite", "y_M");
  require_finite_parameter(p.initial_input, "initial_input", "v0");
  if (!(p.martensite_start > p.martensite_finish)) {
    throw Error(fmt::format("Ikuta martensite_start M_s = {} must be > martensite_finish M_f = {}",
                            p.martensite_start, p.martensite_finish),
                "martensite_start");
  }
  if (!(p.austenite_finish > p.austenite_start)) {
    throw Error(fmt::format("Ikuta austenite_finish A_f = {} must be > austenite_start A_s = {}",
                            p.austenite_finish, p.austenite_start),
                "austenite_finish");
  }
  // The heating window must not lie below the cooling window, or the loop would run the wrong
  // way round (the fraction would transform back before it was transformed).
  if (p.austenite_start < p.martensite_finish) {
    throw Error(fmt::format("Ikuta austenite_start A_s = {} must be >= martensite_finish M_f = {}",
                            p.austenite_start, p.martensite_finish),
                "austenite_start");
  }
  if (p.austenite_finish < p.martensite_start) {
    throw Error(fmt::format("Ikuta austenite_finish A_f = {} must be >= martensite_start M_s = {}",
                            p.austenite_finish, p.martensite_start),
                "austenite_finish");
  }
  if (!(p.initial_fraction >= 0.0 && p.initial_fraction <= 1.0)) {
    throw Error(fmt::format("Ikuta initial_fraction = {} must be in [0, 1]", p.initial_fraction),
                "initial_fraction");
  }
}

}  // namespace

IkutaSma::IkutaSma(const Params& params) : params_(params) {
  validate(params_);
  heating_scale_ = 1.0 / (params_.austenite_finish - params_.austenite_start);
  cooling_scale_ = 1.0 / (params_.martensite_start - params_.martensite_finish);
}

IkutaSma::State IkutaSma::initial_state() const {
  return State{params_.initial_fraction, params_.initial_input, Branch::rest, -1.0};
}

IkutaSma::State IkutaSma::make_state(double fraction, double input) const {
  require_finite(input, "Ikuta state input");
  if (!(fraction >= 0.0 && fraction <= 1.0)) {
    throw Error(fmt::format("Ikuta state fraction = {} must be in [0, 1]", fraction), "fraction");
  }
  return State{fraction, input, Branch::rest, -1.0};
}

IkutaSma::State IkutaSma::make_state(double fraction, double input, Branch branch,
                                     double scale) const {
  State state = make_state(fraction, input);
  require_finite(scale, "Ikuta state scale");
  state.branch = branch;
  state.scale = branch == Branch::rest ? -1.0 : scale;
  return state;
}

IkutaSma::Branch ikuta_branch_from_string(std::string_view text) {
  return detail::value_named(text, enum_names<IkutaSma::Branch>, "Ikuta branch", "branch");
}

}  // namespace hyst
