#pragma once
//! \file
//! Additive white Gaussian measurement noise with a seeded generator (std::mt19937_64), so that a
//! simulation with noise is reproducible. A standard deviation of 0 turns it off.

#include <cstdint>
#include <random>

namespace hyst {

class SensorNoise {
 public:
  struct Params {
    double standard_deviation = 0.0;  //!< sigma [measured units], >= 0
    std::uint64_t seed = 1;           //!< generator seed
  };
  struct State {
    std::mt19937_64 generator;
    std::normal_distribution<double> normal{0.0, 1.0};
  };

  //! hyst::Error unless sigma is finite and >= 0.
  explicit SensorNoise(const Params& params);

  const Params& params() const { return params_; }
  bool enabled() const { return params_.standard_deviation > 0.0; }
  State initial_state() const { return {std::mt19937_64(params_.seed), {}}; }
  //! The measurement plus noise. No allocation.
  double step(State& state, double value) const noexcept {
    if (params_.standard_deviation == 0.0) return value;
    return value + params_.standard_deviation * state.normal(state.generator);
  }

 private:
  Params params_;
};

}  // namespace hyst
