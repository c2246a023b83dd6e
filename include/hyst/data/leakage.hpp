#pragma once
//! \file
//! The charge of a leakage current in a measured polarisation. A ferroelectric tester integrates
//! the current through the sample; a lossy ceramic conducts i = v / R besides its switching and
//! displacement currents, so the measured polarisation carries the leakage charge
//!
//!     P_meas(t) = P(t) + g Q(t),   Q(t) = integral_0^t v dt'  [V s],   g = 1 / (R A)
//!
//! (A the electrode area): a drift during a voltage hold, proportional to the voltage, that turns
//! a slow loop into a fat, tilted one. Q is integrated by the trapezoidal rule from Q(0) = 0 at a
//! uniform sample time. g comes from a known resistance (an aixACCT summary's `Rav` column and the
//! table's `Area [mm2]`: leakage_conductance()) or is fitted together with a model of P (the
//! butterfly strain fit's `fit_leakage`: g >= 0 is one more non-negative weight of its NNLS).
//!
//! A loss that is not a DC conduction (dielectric relaxation) also looks like a g, but one that
//! changes with the rate of the drive: fit g on records at several rates, or per record and
//! compare (docs/results.md, "Butterfly strain").

#include <span>
#include <vector>

namespace hyst::data {

//! g = 1 / (R A) in uC/cm^2 per V s (the unit of an aixACCT P column per volt-second), for a
//! resistance R [Ohm] and an electrode area A [mm^2]: 1e8 / (R A). Throws hyst::Error unless both
//! are finite and > 0.
double leakage_conductance(double resistance, double area_mm2);

//! Q[k] = integral of v from sample 0 to k [input units s], trapezoidal, Q[0] = 0. Throws
//! hyst::Error for a sample time that is not finite and > 0 or a non-finite sample.
std::vector<double> leakage_charge(std::span<const double> voltage, double sample_time);

//! P[k] - g Q[k]: the polarisation without the leakage charge. Throws hyst::Error as
//! leakage_charge() does, for lengths that differ and for a non-finite g.
std::vector<double> remove_leakage_charge(std::span<const double> voltage,
                                          std::span<const double> polarisation, double sample_time,
                                          double conductance);

}  // namespace hyst::data
