#include "hyst/dynamics/best_linear_approximation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include "hyst/core/checks.hpp"
#include "hyst/core/error.hpp"

namespace hyst {
namespace {

using Complex = std::complex<double>;

//! Spectra of one signal set at the kept lines: index [(r * P' + p) * lines + l] -> channel vector.
struct Spectra {
  std::vector<Eigen::VectorXcd> values;
  std::size_t periods = 0;
  std::size_t lines = 0;
  const Eigen::VectorXcd& at(std::size_t r, std::size_t p, std::size_t l) const {
    return values[(r * periods + p) * lines + l];
  }
};

void check_experiment(const PeriodicExperiment& e, std::size_t index,
                      const PeriodicExperiment& first, const BlaOptions& options) {
  const auto name = fmt::format("experiment {}", index + 1);
  const auto& u = e.input;
  const auto& y = e.output;
  if (u.samples < 4)
    throw Error(fmt::format("{}: {} samples per period (at least 4)", name, u.samples));
  if (u.channels == 0 || y.channels == 0)
    throw Error(fmt::format("{}: no input or no output channel", name));
  if (u.samples != y.samples || u.realisations != y.realisations || u.periods != y.periods)
    throw Error(fmt::format(
        "{}: inputs are {} samples x {} realisations x {} periods, outputs {} x {} x {}", name,
        u.samples, u.realisations, u.periods, y.samples, y.realisations, y.periods));
  if (u.values.size() != u.samples * u.channels * u.realisations * u.periods ||
      y.values.size() != y.samples * y.channels * y.realisations * y.periods)
    throw Error(fmt::format("{}: the values do not match the stated sizes", name));
  if (u.samples != first.input.samples || u.channels != first.input.channels ||
      y.channels != first.output.channels)
    throw Error(fmt::format("{}: {} samples, {} inputs, {} outputs; experiment 1 has {}, {}, {}",
                            name, u.samples, u.channels, y.channels, first.input.samples,
                            first.input.channels, first.output.channels));
  if (u.realisations == 0 || u.realisations % u.channels != 0)
    throw Error(
        fmt::format("{}: {} realisations are not a whole number of blocks of {} (one "
                    "realisation per input in each block)",
                    name, u.realisations, u.channels));
  if (u.periods <= options.transient_periods)
    throw Error(fmt::format("{}: {} periods, and {} are dropped as transient", name, u.periods,
                            options.transient_periods));
  require_finite(u.values, name + " input");
  require_finite(y.values, name + " output");
}

//! DFT of every channel of every (realisation, kept period), at the lines asked for.
Spectra spectra(const PeriodicSignals& s, std::size_t first_period,
                const std::vector<std::size_t>& lines) {
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  Spectra out;
  out.periods = s.periods - first_period;
  out.lines = lines.size();
  out.values.assign(s.realisations * out.periods * lines.size(),
                    Eigen::VectorXcd::Zero(Eigen::Index(s.channels)));
  std::vector<double> samples(s.samples);
  std::vector<Complex> spectrum;
  for (std::size_t r = 0; r < s.realisations; ++r)
    for (std::size_t p = first_period; p < s.periods; ++p)
      for (std::size_t c = 0; c < s.channels; ++c) {
        for (std::size_t n = 0; n < s.samples; ++n)
          samples[n] = s(n, c, r, p);
        fft.fwd(spectrum, samples);
        for (std::size_t l = 0; l < lines.size(); ++l)
          out.values[((r * out.periods) + (p - first_period)) * lines.size() + l][Eigen::Index(c)] =
              spectrum[lines[l]];
      }
  return out;
}

//! Lines whose mean input power reaches the threshold, DC and Nyquist excluded.
std::vector<std::size_t> excited_lines(std::span<const PeriodicExperiment> experiments,
                                       const BlaOptions& options) {
  const std::size_t n = experiments[0].input.samples;
  std::vector<std::size_t> all(n / 2 + 1);
  for (std::size_t k = 0; k < all.size(); ++k)
    all[k] = k;
  std::vector<double> power(all.size(), 0.0);
  for (const auto& e : experiments) {
    const auto s = spectra(e.input, options.transient_periods, all);
    for (std::size_t r = 0; r < e.input.realisations; ++r)
      for (std::size_t p = 0; p < s.periods; ++p)
        for (std::size_t k = 0; k < all.size(); ++k)
          power[k] += s.at(r, p, k).squaredNorm();
  }
  const std::size_t last = (n % 2 == 0) ? n / 2 - 1 : n / 2;  // no Nyquist line
  const double largest =
      *std::max_element(power.begin() + 1, power.begin() + Eigen::Index(last) + 1);
  std::vector<std::size_t> lines;
  for (std::size_t k = 1; k <= last; ++k)
    if (largest > 0.0 && power[k] >= options.excitation_threshold * largest) lines.push_back(k);
  if (lines.empty()) throw Error("BLA: no excited line (every input is constant)");
  return lines;
}

//! G = Y U^-1 for the m realisations of one block, one period, one line.
Eigen::MatrixXcd block_response(const Spectra& u, const Spectra& y, std::size_t first_realisation,
                                std::size_t m, std::size_t period, std::size_t line,
                                std::size_t experiment, double frequency) {
  const auto size = Eigen::Index(m);
  Eigen::MatrixXcd input(size, size);
  Eigen::MatrixXcd output(y.at(0, 0, 0).size(), size);
  for (std::size_t j = 0; j < m; ++j) {
    input.col(Eigen::Index(j)) = u.at(first_realisation + j, period, line);
    output.col(Eigen::Index(j)) = y.at(first_realisation + j, period, line);
  }
  // G U = Y, solved as U^T G^T = Y^T.
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(input.transpose());
  if (!(lu.rcond() > 1e-10))
    throw Error(fmt::format(
        "BLA: experiment {}, realisations {}-{}: the inputs' spectra at {:g} Hz are not "
        "independent (reciprocal condition {:.3g}); each block of {} realisations must excite "
        "every input independently",
        experiment + 1, first_realisation + 1, first_realisation + m, frequency, lu.rcond(), m));
  return lu.solve(output.transpose()).transpose();
}

}  // namespace

std::vector<double> BestLinearApproximation::frequencies() const {
  std::vector<double> f(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l)
    f[l] = double(lines[l]) / (double(samples) * sample_time);
  return f;
}

BestLinearApproximation estimate_bla(std::span<const PeriodicExperiment> experiments,
                                     double sample_time, const BlaOptions& options) {
  if (experiments.empty()) throw Error("BLA: no experiment");
  if (!(sample_time > 0.0) || !std::isfinite(sample_time))
    throw Error(fmt::format("BLA: sample time {} must be positive and finite", sample_time));
  if (!(options.excitation_threshold > 0.0 && options.excitation_threshold < 1.0))
    throw Error(fmt::format("BLA: excitation threshold {} must be in (0, 1)",
                            options.excitation_threshold));
  for (std::size_t i = 0; i < experiments.size(); ++i)
    check_experiment(experiments[i], i, experiments[0], options);

  BestLinearApproximation bla;
  bla.sample_time = sample_time;
  bla.samples = experiments[0].input.samples;
  bla.lines = excited_lines(experiments, options);
  const std::size_t m = experiments[0].input.channels;
  const std::size_t p = experiments[0].output.channels;
  const std::size_t lines = bla.lines.size();
  const auto frequencies = bla.frequencies();

  // Per block: the mean over periods and the variance of that mean.
  std::vector<std::vector<Eigen::MatrixXcd>> block_means;  // [block][line]
  std::vector<std::vector<Eigen::MatrixXd>> block_noise;   // [block][line]
  std::size_t periods = 0;
  for (std::size_t e = 0; e < experiments.size(); ++e) {
    const auto u = spectra(experiments[e].input, options.transient_periods, bla.lines);
    const auto y = spectra(experiments[e].output, options.transient_periods, bla.lines);
    periods = std::max(periods, u.periods);
    for (std::size_t first = 0; first < experiments[e].input.realisations; first += m) {
      std::vector<Eigen::MatrixXcd> means(lines);
      std::vector<Eigen::MatrixXd> noise(lines);
      for (std::size_t l = 0; l < lines; ++l) {
        std::vector<Eigen::MatrixXcd> per_period;
        for (std::size_t q = 0; q < u.periods; ++q)
          per_period.push_back(block_response(u, y, first, m, q, l, e, frequencies[l]));
        Eigen::MatrixXcd mean = Eigen::MatrixXcd::Zero(Eigen::Index(p), Eigen::Index(m));
        for (const auto& g : per_period)
          mean += g;
        mean /= double(per_period.size());
        Eigen::MatrixXd spread = Eigen::MatrixXd::Zero(Eigen::Index(p), Eigen::Index(m));
        for (const auto& g : per_period)
          spread += (g - mean).cwiseAbs2();
        if (per_period.size() > 1)
          spread /= double(per_period.size() - 1) * double(per_period.size());
        means[l] = std::move(mean);
        noise[l] = std::move(spread);
      }
      block_means.push_back(std::move(means));
      block_noise.push_back(std::move(noise));
    }
  }

  const std::size_t blocks = block_means.size();
  bla.blocks = blocks;
  bla.periods = periods;
  bla.response.assign(lines, Eigen::MatrixXcd::Zero(Eigen::Index(p), Eigen::Index(m)));
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t l = 0; l < lines; ++l)
      bla.response[l] += block_means[b][l] / double(blocks);
  if (periods > 1) {
    bla.noise_variance.assign(lines, Eigen::MatrixXd::Zero(Eigen::Index(p), Eigen::Index(m)));
    for (std::size_t b = 0; b < blocks; ++b)
      for (std::size_t l = 0; l < lines; ++l)
        bla.noise_variance[l] += block_noise[b][l] / double(blocks * blocks);
  }
  if (blocks > 1) {
    bla.total_variance.assign(lines, Eigen::MatrixXd::Zero(Eigen::Index(p), Eigen::Index(m)));
    for (std::size_t b = 0; b < blocks; ++b)
      for (std::size_t l = 0; l < lines; ++l)
        bla.total_variance[l] +=
            (block_means[b][l] - bla.response[l]).cwiseAbs2() / double((blocks - 1) * blocks);
  }
  return bla;
}

}  // namespace hyst
