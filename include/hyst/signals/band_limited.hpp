#pragma once
//! \file
//! Band-limited interpolation (upsampling) of sampled signals.
//!
//! A continuous-time system driven by a band-limited input (a multisine, a sine sweep) must be
//! simulated with the input's course between the samples, not with a held or linear input: on
//! the Bouc-Wen benchmark the held input alone costs ~1e-4 m of simulation error (see
//! docs/results.md). Both functions return factor * N samples; sample factor * k is input sample k.
//!
//! - upsample_periodic: exact for a periodic signal whose record is one period (zero padding of
//!   the discrete Fourier transform; the Nyquist bin is split evenly between both halves).
//! - upsample_band_limited: any record, Kaiser-windowed sinc (half-width `half_width` input
//!   samples, Kaiser beta 10), the signal taken as zero outside the record; each of the `factor`
//!   polyphase kernels is normalised to unit DC gain.

#include <cstddef>
#include <span>
#include <vector>

namespace hyst {

//! Throws hyst::Error unless 1 <= factor <= 1000, the record is not empty and every sample is
//! finite.
std::vector<double> upsample_periodic(std::span<const double> one_period, std::size_t factor);

//! Throws hyst::Error unless 1 <= factor <= 1000, 1 <= half_width <= 1000, the record is not empty
//! and every sample is finite.
std::vector<double> upsample_band_limited(std::span<const double> input, std::size_t factor,
                                          std::size_t half_width = 64);

}  // namespace hyst
