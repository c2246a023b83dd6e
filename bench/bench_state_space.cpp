// ns/sample of the linear state-space model's step for a 28th-order model with 3 inputs and
// 3 outputs (a piezo stage's lightly damped modes, identified from a MIMO measurement), and of
// the hysteretic LFR that adds a 16-operator PI model in each of 3 feedback channels. Items
// processed = samples.

#include <cstdint>
#include <random>

#include <benchmark/benchmark.h>

#include "hyst/dynamics/hysteretic_lfr.hpp"
#include "hyst/dynamics/state_space.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"

namespace {

constexpr std::size_t kSamples = 1 << 14;
constexpr Eigen::Index kOrder = 28;
constexpr Eigen::Index kChannels = 3;

Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& random) {
  std::normal_distribution<double> gauss;
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      m(i, j) = gauss(random);
  return m;
}

// A stable model: damped 2x2 rotations on the diagonal (poles r e^(+-j theta), r in [0.9, 0.999]),
// the real modal form that fit_state_space() returns, or (dense) after a random orthogonal
// similarity, which keeps the poles.
enum class Form { modal, dense };
hyst::StateSpace make_model(Form form, Eigen::Index inputs = kChannels,
                            Eigen::Index outputs = kChannels) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> radius(0.9, 0.999);
  std::uniform_real_distribution<double> angle(0.05, 3.0);
  Eigen::MatrixXd blocks = Eigen::MatrixXd::Zero(kOrder, kOrder);
  for (Eigen::Index i = 0; i < kOrder; i += 2) {
    const double r = radius(random);
    const double t = angle(random);
    blocks.block(i, i, 2, 2) << r * std::cos(t), -r * std::sin(t), r * std::sin(t), r * std::cos(t);
  }
  Eigen::MatrixXd q = random_matrix(kOrder, kOrder, random).householderQr().householderQ();
  if (form == Form::modal) q.setIdentity();
  return hyst::StateSpace({q * blocks * q.transpose(), random_matrix(kOrder, inputs, random),
                           random_matrix(outputs, kOrder, random),
                           random_matrix(outputs, inputs, random), 1e-4});
}

// Steps a model with 3 inputs and 3 outputs through kSamples random samples per iteration.
template <class Model>
void run_steps(const Model& model, benchmark::State& bench) {
  auto state = model.initial_state();
  std::mt19937_64 random(2);
  const Eigen::MatrixXd input = random_matrix(kChannels, Eigen::Index(kSamples), random);
  double output[kChannels];
  for (auto _ : bench) {
    for (Eigen::Index k = 0; k < input.cols(); ++k) {
      model.step(state, {input.col(k).data(), std::size_t(kChannels)}, output);
      benchmark::DoNotOptimize(output);
    }
  }
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations() * kSamples));
}

void BM_StateSpaceStep(benchmark::State& bench) {
  run_steps(make_model(Form::dense), bench);
}

void BM_StateSpaceStepModal(benchmark::State& bench) {
  run_steps(make_model(Form::modal), bench);
}

// The linear block with 3 more inputs (w) and outputs (z), weak feedback gains (a stable loop),
// no Dzw; a PI model of 16 plays (thresholds 0 .. 1.5) in each channel.
hyst::HystereticLfr<hyst::PrandtlIshlinskii> make_lfr(Form form) {
  auto params = make_model(form, 2 * kChannels, 2 * kChannels).params();
  params.b.rightCols(kChannels) *= 0.01;
  params.d.rightCols(kChannels) *= 0.01;
  params.d.bottomRightCorner(kChannels, kChannels).setZero();
  std::vector<double> thresholds, weights;
  for (int j = 0; j < 16; ++j) {
    thresholds.push_back(0.1 * j);
    weights.push_back(1.0 / (1 + j));
  }
  const hyst::PrandtlIshlinskii pi({thresholds, weights, 0.0});
  return {hyst::StateSpace(params), std::size_t(kChannels), {pi, pi, pi}};
}

void BM_HystereticLfrStep(benchmark::State& bench) {
  run_steps(make_lfr(Form::dense), bench);
}

void BM_HystereticLfrStepModal(benchmark::State& bench) {
  run_steps(make_lfr(Form::modal), bench);
}

}  // namespace

BENCHMARK(BM_StateSpaceStep);
BENCHMARK(BM_StateSpaceStepModal);
BENCHMARK(BM_HystereticLfrStep);
BENCHMARK(BM_HystereticLfrStepModal);
