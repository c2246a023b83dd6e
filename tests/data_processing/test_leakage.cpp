// The leakage charge of a measured polarisation: the conductance from a resistance and an area by
// hand, the trapezoidal charge against closed forms, and its removal.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "hyst/data/leakage.hpp"

namespace hyst::data {
namespace {

TEST(Leakage, ConductanceByHand) {
  // 1 V across 100 MOhm: 10 nA, 10 nC per second on 100 mm^2 = 1 cm^2: 0.01 uC/cm^2 per V s.
  EXPECT_NEAR(leakage_conductance(1e8, 100.0), 0.01, 1e-17);
  // The aixACCT export's 0.01 Hz table: Rav = 1.18578e9 Ohm, 60 mm^2.
  EXPECT_NEAR(leakage_conductance(1.18578e9, 60.0), 1e8 / (1.18578e9 * 60.0), 1e-18);
  EXPECT_HYST_ERROR(leakage_conductance(0.0, 60.0), "leakage resistance = 0 Ohm");
  EXPECT_HYST_ERROR(leakage_conductance(1e9, NAN), "electrode area = nan mm^2");
}

TEST(Leakage, ChargeIsTheIntegralOfTheVoltage) {
  // A constant voltage: Q = V t; a ramp v = a t: Q = a t^2 / 2 (the trapezoidal rule is exact on
  // both).
  const std::vector<double> constant(11, 3.0);
  const auto q_constant = leakage_charge(constant, 0.1);
  for (std::size_t k = 0; k < constant.size(); ++k)
    EXPECT_NEAR(q_constant[k], 3.0 * 0.1 * static_cast<double>(k), 1e-14);
  std::vector<double> ramp;
  for (int k = 0; k <= 20; ++k)
    ramp.push_back(2.0 * 0.05 * k);
  const auto q_ramp = leakage_charge(ramp, 0.05);
  for (std::size_t k = 0; k < ramp.size(); ++k) {
    const double t = 0.05 * static_cast<double>(k);
    EXPECT_NEAR(q_ramp[k], t * t, 1e-14);
  }
  EXPECT_HYST_ERROR(leakage_charge(ramp, 0.0), "sample_time = 0 must be finite and > 0");
  ramp[3] = NAN;
  EXPECT_HYST_ERROR(leakage_charge(ramp, 0.1), "voltage[3] = nan is not finite");
}

TEST(Leakage, RemovalSubtractsTheCharge) {
  const std::vector<double> v = {1.0, 1.0, -1.0, -1.0};
  const std::vector<double> p = {0.5, 0.6, 0.7, 0.8};
  // Q = 0, 1, 1, 0 (Ts = 1): P - 0.2 Q.
  const auto corrected = remove_leakage_charge(v, p, 1.0, 0.2);
  const std::vector<double> expected = {0.5, 0.4, 0.5, 0.8};
  for (std::size_t k = 0; k < v.size(); ++k)
    EXPECT_NEAR(corrected[k], expected[k], 1e-15);
  EXPECT_HYST_ERROR(remove_leakage_charge(v, std::vector<double>(3), 1.0, 0.2),
                    "4 voltage samples but 3 polarisation samples");
  EXPECT_HYST_ERROR(remove_leakage_charge(v, p, 1.0, INFINITY), "conductance = inf");
}

}  // namespace
}  // namespace hyst::data
