#pragma once
//! \file
//! Deterministic test signals on a uniform time grid t_k = k dt [s], k = 0 .. samples-1.
//!
//! Every generator is a pure function of its parameter struct: the same parameters give the same
//! samples on every platform and standard library (the random walk uses std::mt19937_64 and its own
//! conversion to double, not std::uniform_real_distribution). Invalid parameters throw hyst::Error
//! naming the field, e.g. "decaying sine time_constant = -1 must be > 0"; every output sample is
//! finite (parameters so large that a sample would overflow are rejected the same way).
//!
//! Phase convention: sine, triangle, decaying/growing sine and chirp all start at 0 and rise when
//! phase = 0 and offset = 0; phase [rad] shifts them like sin(2 pi f t + phase).
//!
//! Which signals create internal (minor) loops in a hysteresis model, and why:
//! a rate-independent hysteresis model (play, relay, Preisach, Prandtl-Ishlinskii) only remembers
//! the sequence of the input's reversal points (its local extrema); the time between them does not
//! matter. A plain Sine or Triangle of constant amplitude reverses at the same two values every
//! cycle, so after the first half cycle it traces one major loop over and over. A DecayingSine
//! reverses at values that move inwards each half period (|v| shrinks by about e^{-1/(2 f tau)}),
//! so each new reversal lies inside the previous one: the output traces a spiral of nested inner
//! loops that converges to the offset - the classic demagnetisation (first-order reversal) test,
//! and the one that exposes wiping-out and congruency. A GrowingSine does the opposite: each
//! reversal exceeds all earlier ones, wipes out their memory and walks the output out along the
//! initial loading curve to the major loop. A Multisine (incommensurate components) and a
//! RandomWalk reverse at irregular levels and produce loops nested to several depths at once, as
//! measured data do. A Chirp keeps the amplitude and so the loop size; it tests rate independence
//! (and exposes rate dependence, e.g. of a dynamic model) by sweeping the frequency.
//!
//! Common mistakes: frequency is in [Hz], not [rad/s]; a grid must sample each period with many
//! points (dt << 1/f) or the extrema of the sampled signal are cut off and loops look smaller.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hyst::signals {

//! Uniform time grid t_k = k dt, k = 0 .. samples-1.
struct TimeGrid {
  std::size_t samples = 0;  //!< number of samples, >= 1
  double dt = 1.0;          //!< sample period [s], > 0
};

//! The sample times t_k = k dt [s]. Throws hyst::Error for an invalid grid.
std::vector<double> times(const TimeGrid& grid);

//! v(t) = A sin(2 pi f t + phase) + offset.
struct Sine {
  double amplitude = 1.0;  //!< A [signal units], any finite value
  double frequency = 1.0;  //!< f [Hz], >= 0
  double phase = 0.0;      //!< [rad]
  double offset = 0.0;     //!< [signal units]
};

//! Symmetric triangle wave with peaks +-A, the same phase convention as Sine: for phase = 0 it
//! starts at 0 rising, reaches +A at t = 1/(4f), 0 at 1/(2f) and -A at 3/(4f).
struct Triangle {
  double amplitude = 1.0;  //!< A [signal units]
  double frequency = 1.0;  //!< f [Hz], >= 0
  double phase = 0.0;      //!< [rad]; 2 pi is one period
  double offset = 0.0;     //!< [signal units]
};

//! v(t) = A e^{-t/tau} sin(2 pi f t + phase) + offset: a spiral of nested internal (minor) loops.
struct DecayingSine {
  double amplitude = 1.0;      //!< A [signal units]
  double frequency = 1.0;      //!< f [Hz], >= 0
  double time_constant = 1.0;  //!< tau [s], > 0
  double phase = 0.0;          //!< [rad]
  double offset = 0.0;         //!< [signal units]
};

//! v(t) = A (1 - e^{-t/tau}) sin(2 pi f t + phase) + offset: loops growing out to the major loop.
struct GrowingSine {
  double amplitude = 1.0;      //!< A [signal units]
  double frequency = 1.0;      //!< f [Hz], >= 0
  double time_constant = 1.0;  //!< tau [s], > 0
  double phase = 0.0;          //!< [rad]
  double offset = 0.0;         //!< [signal units]
};

//! v(t) = sum_k a_k sin(2 pi f_k t + phi_k) + offset, k = 1 .. K.
//! With `phases` empty, Schroeder phases phi_k = -pi k (k-1) / K are used, which keep the crest
//! factor (peak / RMS) low for flat amplitude spectra.
struct Multisine {
  std::vector<double> frequencies;  //!< f_k [Hz], >= 0; not empty
  std::vector<double> amplitudes;   //!< a_k [signal units]; same length as frequencies
  std::vector<double> phases;       //!< phi_k [rad]; empty (Schroeder) or same length
  double offset = 0.0;              //!< [signal units]
};

//! Linear frequency sweep over the whole grid: the instantaneous frequency rises (or falls)
//! linearly from start_frequency at t = 0 to end_frequency at the last sample t = (samples-1) dt:
//!     v(t) = A sin(2 pi (f0 t + (f1 - f0) t^2 / (2 T)) + phase) + offset,  T = (samples-1) dt.
struct Chirp {
  double amplitude = 1.0;        //!< A [signal units]
  double start_frequency = 1.0;  //!< f0 [Hz], >= 0
  double end_frequency = 10.0;   //!< f1 [Hz], >= 0
  double phase = 0.0;            //!< [rad]
  double offset = 0.0;           //!< [signal units]
};

//! Bounded random walk: v[0] = start, v[k+1] = v[k] + s_k with s_k uniform in
//! [-max_step, max_step), reflected at the bounds so that lower <= v[k] <= upper.
//! Reproducible across platforms for a given seed.
struct RandomWalk {
  double max_step = 0.1;   //!< [signal units], >= 0 and < upper - lower
  double lower = -1.0;     //!< [signal units], < upper
  double upper = 1.0;      //!< [signal units]
  double start = 0.0;      //!< v[0] [signal units], in [lower, upper]
  std::uint64_t seed = 1;  //!< seed of std::mt19937_64
};

//! The signal sampled on the grid. Each throws hyst::Error for invalid parameters or grid.
std::vector<double> generate(const TimeGrid& grid, const Sine& signal);
std::vector<double> generate(const TimeGrid& grid, const Triangle& signal);
std::vector<double> generate(const TimeGrid& grid, const DecayingSine& signal);
std::vector<double> generate(const TimeGrid& grid, const GrowingSine& signal);
std::vector<double> generate(const TimeGrid& grid, const Multisine& signal);
std::vector<double> generate(const TimeGrid& grid, const Chirp& signal);
std::vector<double> generate(const TimeGrid& grid, const RandomWalk& signal);

}  // namespace hyst::signals
