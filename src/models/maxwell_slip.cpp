#include "hyst/models/maxwell_slip.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

void validate(const MaxwellSlip::Params& p) {
  const auto& k = p.stiffness;
  const auto& f = p.break_away;
  if (k.empty()) throw Error("Maxwell-slip stiffness k is empty", "stiffness");
  require_same_length(k.size(), f.size(), "Maxwell-slip", {"stiffnesses", "k", "stiffness"},
                      {"break-away forces", "f", "break_away"});
  for (std::size_t i = 0; i < k.size(); ++i) {
    if (!std::isfinite(k[i]) || !(k[i] > 0.0)) {
      throw Error(fmt::format("Maxwell-slip stiffness k[{}] = {} must be finite and > 0", i, k[i]),
                  fmt::format("stiffness[{}]", i));
    }
    if (!std::isfinite(f[i]) || !(f[i] > 0.0)) {
      throw Error(fmt::format("Maxwell-slip break_away f[{}] = {} must be finite and > 0", i, f[i]),
                  fmt::format("break_away[{}]", i));
    }
    if (i > 0 && !(f[i] / k[i] > f[i - 1] / k[i - 1])) {
      throw Error(fmt::format("Maxwell-slip slip displacement f[{}]/k[{}] = {} must be > "
                              "f[{}]/k[{}] = {} (list the elements by increasing f/k)",
                              i, i, f[i] / k[i], i - 1, i - 1, f[i - 1] / k[i - 1]),
                  fmt::format("break_away[{}]", i));
    }
  }
  if (!std::isfinite(p.linear_stiffness) || p.linear_stiffness < 0.0) {
    throw Error(fmt::format("Maxwell-slip linear_stiffness = {} must be finite and >= 0",
                            p.linear_stiffness),
                "linear_stiffness");
  }
  if (!std::isfinite(p.offset)) {
    throw Error(fmt::format("Maxwell-slip offset = {} is not finite", p.offset), "offset");
  }
}

}  // namespace

MaxwellSlip::MaxwellSlip(Params params) : params_(std::move(params)) {
  validate(params_);
  sign_ = params_.orientation == Orientation::counter_clockwise ? -1.0 : 1.0;
  slip_.resize(size());
  for (std::size_t i = 0; i < size(); ++i)
    slip_[i] = params_.break_away[i] / params_.stiffness[i];
}

MaxwellSlip::State MaxwellSlip::state_at_rest(double input) const {
  require_finite(input, "Maxwell-slip rest position x0");
  return State{std::vector<double>(size(), 0.0), input};
}

MaxwellSlip::State MaxwellSlip::make_state(std::vector<double> deflection, double input) const {
  require_same_size(deflection.size(), "Maxwell-slip state deflection", size(),
                    "Maxwell-slip stiffness k");
  require_finite(input, "Maxwell-slip state input");
  for (std::size_t i = 0; i < deflection.size(); ++i) {
    if (!std::isfinite(deflection[i]) || std::abs(deflection[i]) > slip_[i]) {
      throw Error(
          fmt::format("Maxwell-slip state deflection[{}] = {} must be finite and within "
                      "+-f[{}]/k[{}] = +-{}",
                      i, deflection[i], i, i, slip_[i]));
    }
  }
  return State{std::move(deflection), input};
}

double MaxwellSlip::output(const State& state) const {
  require_same_size(state.deflection.size(), "Maxwell-slip state deflection", size(),
                    "Maxwell-slip stiffness k");
  double elements = 0.0;
  for (std::size_t i = 0; i < size(); ++i)
    elements += params_.stiffness[i] * state.deflection[i];
  return params_.offset + params_.linear_stiffness * state.input + sign_ * elements;
}

bool MaxwellSlip::is_invertible() const {
  double total = 0.0;
  for (double k : params_.stiffness)
    total += k;
  // Slopes just after a reversal (no element slips) and once every element slips.
  return params_.linear_stiffness + sign_ * total > 0.0 && params_.linear_stiffness > 0.0;
}

PrandtlIshlinskii MaxwellSlip::to_prandtl_ishlinskii() const {
  PrandtlIshlinskii::Params pi;
  pi.thresholds.push_back(0.0);
  pi.weights.push_back(params_.linear_stiffness);
  for (std::size_t i = 0; i < size(); ++i) {
    pi.thresholds.push_back(slip_[i]);
    pi.weights.push_back(-sign_ * params_.stiffness[i]);
    pi.weights[0] += sign_ * params_.stiffness[i];
  }
  pi.offset = params_.offset;
  return PrandtlIshlinskii(std::move(pi));
}

PrandtlIshlinskii::State MaxwellSlip::prandtl_ishlinskii_state(const State& state) const {
  require_same_size(state.deflection.size(), "Maxwell-slip state deflection", size(),
                    "Maxwell-slip stiffness k");
  std::vector<double> play;
  play.reserve(size() + 1);
  play.push_back(state.input);
  for (double delta : state.deflection)
    play.push_back(state.input - delta);
  return to_prandtl_ishlinskii().make_state(std::move(play));
}

std::string_view orientation_name(MaxwellSlip::Orientation orientation) {
  return orientation == MaxwellSlip::Orientation::clockwise ? "clockwise" : "counter-clockwise";
}

MaxwellSlip::Orientation parse_orientation(std::string_view text, std::string_view what) {
  if (text == "clockwise") return MaxwellSlip::Orientation::clockwise;
  if (text == "counter-clockwise") return MaxwellSlip::Orientation::counter_clockwise;
  throw Error(fmt::format("{} = \"{}\" must be \"clockwise\" or \"counter-clockwise\"", what, text),
              std::string(what));
}

}  // namespace hyst
