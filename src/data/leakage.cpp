#include "hyst/data/leakage.hpp"

#include <cmath>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

namespace hyst::data {

double leakage_conductance(double resistance, double area_mm2) {
  if (!std::isfinite(resistance) || !(resistance > 0.0)) {
    throw Error(fmt::format("leakage resistance = {} Ohm must be finite and > 0", resistance),
                "resistance");
  }
  if (!std::isfinite(area_mm2) || !(area_mm2 > 0.0)) {
    throw Error(fmt::format("electrode area = {} mm^2 must be finite and > 0", area_mm2), "area");
  }
  // C / mm^2 -> uC / cm^2: 1e6 uC per C, 100 mm^2 per cm^2.
  return 1e8 / (resistance * area_mm2);
}

std::vector<double> leakage_charge(std::span<const double> voltage, double sample_time) {
  if (!std::isfinite(sample_time) || !(sample_time > 0.0)) {
    throw Error(fmt::format("leakage charge: sample_time = {} must be finite and > 0", sample_time),
                "sample_time");
  }
  std::vector<double> charge(voltage.size(), 0.0);
  for (std::size_t k = 0; k < voltage.size(); ++k) {
    if (!std::isfinite(voltage[k])) {
      throw Error(fmt::format("leakage charge: voltage[{}] = {} is not finite", k, voltage[k]),
                  "voltage");
    }
    if (k > 0) charge[k] = charge[k - 1] + 0.5 * sample_time * (voltage[k - 1] + voltage[k]);
  }
  return charge;
}

std::vector<double> remove_leakage_charge(std::span<const double> voltage,
                                          std::span<const double> polarisation, double sample_time,
                                          double conductance) {
  if (voltage.size() != polarisation.size()) {
    throw Error(fmt::format("leakage correction: {} voltage samples but {} polarisation samples",
                            voltage.size(), polarisation.size()),
                "polarisation");
  }
  if (!std::isfinite(conductance)) {
    throw Error(fmt::format("leakage conductance = {} is not finite", conductance), "conductance");
  }
  auto corrected = leakage_charge(voltage, sample_time);
  for (std::size_t k = 0; k < corrected.size(); ++k)
    corrected[k] = polarisation[k] - conductance * corrected[k];
  return corrected;
}

}  // namespace hyst::data
