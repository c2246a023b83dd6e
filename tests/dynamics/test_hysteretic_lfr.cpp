// The hysteretic LFR and the Hammerstein system against second algorithms: a scalar loop written
// out by hand, the blocks run one after the other, the linear model when the feedback is cut;
// its periodic steady state returns to itself after a period; step() allocates nothing; model
// files read back exactly and name the field of each error.

#include "hyst/dynamics/hysteretic_lfr.hpp"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/allocation_counter.hpp"
#include "../support/expect_error.hpp"
#include "hyst/models/prandtl_ishlinskii.hpp"
#include "hyst/operators/play.hpp"
#include "hyst/registry/hysteretic_lfr_file.hpp"
#include "hyst/registry/model_registry.hpp"
#include "hyst/registry/state_space_file.hpp"
#include "random_matrix.hpp"

namespace hyst::hysteretic_lfr_test {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using nlohmann::json;

using test::random_matrix;

// A stable random A (spectral radius 0.8) of order n.
MatrixXd stable_a(Eigen::Index n, std::mt19937_64& random) {
  MatrixXd a = random_matrix(n, n, random);
  const double radius = a.eigenvalues().cwiseAbs().maxCoeff();
  return a * (0.8 / radius);
}

PrandtlIshlinskii pi_block(double scale) {
  return PrandtlIshlinskii({{0.0, 0.2 * scale, 0.6 * scale}, {0.3, 0.2, 0.1}, 0.0});
}

// An LFR with 4 states, inputs u (2), feedback (2), outputs y (3): linear block 4 x (2+2) x (3+2).
HystereticLfr<PrandtlIshlinskii> random_lfr(std::uint64_t seed, double feedback_gain = 0.2) {
  std::mt19937_64 random(seed);
  const Eigen::Index n = 4, m = 2, q = 2, p = 3;
  StateSpace::Params params;
  params.sample_time = 1e-3;
  params.a = stable_a(n, random);
  params.b = random_matrix(n, m + q, random);
  params.b.rightCols(q) *= feedback_gain;
  params.c = random_matrix(p + q, n, random);
  params.d = random_matrix(p + q, m + q, random);
  params.d.bottomRightCorner(q, q).setZero();
  params.d.topRightCorner(p, q) *= feedback_gain;
  return {StateSpace(params), std::size_t(m), {pi_block(1.0), pi_block(2.0)}};
}

MatrixXd random_input(Eigen::Index samples, Eigen::Index inputs, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  MatrixXd u = random_matrix(samples, inputs, random);
  // Smooth it a little, so that the plays move in runs as with measured signals.
  for (Eigen::Index k = 1; k < samples; ++k)
    u.row(k) = 0.7 * u.row(k - 1) + 0.3 * u.row(k);
  return u;
}

TEST(HystereticLfr, WithTheFeedbackCutItIsTheLinearModel) {
  std::mt19937_64 random(3);
  const Eigen::Index n = 5, m = 2, q = 2, p = 2;
  StateSpace::Params params;
  params.a = stable_a(n, random);
  params.b = random_matrix(n, m + q, random);
  params.b.rightCols(q).setZero();
  params.c = random_matrix(p + q, n, random);
  params.d = random_matrix(p + q, m + q, random);
  params.d.rightCols(q).setZero();
  const HystereticLfr<PrandtlIshlinskii> lfr(StateSpace(params), m, {pi_block(1), pi_block(1)});
  const StateSpace linear({params.a, params.b.leftCols(m), params.c.topRows(p),
                           params.d.topLeftCorner(p, m), params.sample_time});
  const MatrixXd u = random_input(300, m, 4);
  EXPECT_EQ(lfr.simulate(u), linear.simulate(u));
  const MatrixXd period = random_input(64, m, 5);
  EXPECT_EQ(lfr.periodic_state(period).x, linear.periodic_state(period));
}

TEST(HystereticLfr, OneStateLoopAgreesWithTheLoopWrittenOut) {
  const double a = 0.9, bu = 0.5, bw = -0.3, cy = 1.2, cz = 0.8, dyu = 0.1, dyw = 0.25, dzu = 0.4;
  const StateSpace linear({MatrixXd::Constant(1, 1, a), (MatrixXd(1, 2) << bu, bw).finished(),
                           (MatrixXd(2, 1) << cy, cz).finished(),
                           (MatrixXd(2, 2) << dyu, dyw, dzu, 0.0).finished(), 0.01});
  const HystereticLfr<PrandtlIshlinskii> lfr(linear, 1, {pi_block(0.5)});
  const MatrixXd u = random_input(500, 1, 7) * 2.0;
  const MatrixXd y = lfr.simulate(u);

  double x = 0.0, play1 = 0.0, play2 = 0.0;  // the PI's plays r = 0.1, 0.3 start at 0
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    const double z = cz * x + dzu * u(k, 0);
    play1 = std::max(z - 0.1, std::min(z + 0.1, play1));
    play2 = std::max(z - 0.3, std::min(z + 0.3, play2));
    const double w = 0.3 * z + 0.2 * play1 + 0.1 * play2;
    ASSERT_NEAR(y(k, 0), cy * x + dyu * u(k, 0) + dyw * w, 1e-14) << "sample " << k;
    x = a * x + bu * u(k, 0) + bw * w;
  }
}

TEST(Hammerstein, IsEachInputsBlockThenTheLinearModel) {
  std::mt19937_64 random(11);
  const StateSpace linear({stable_a(3, random), random_matrix(3, 2, random),
                           random_matrix(2, 3, random), random_matrix(2, 2, random), 0.01});
  const std::vector<PrandtlIshlinskii> blocks = {pi_block(0.5), pi_block(1.5)};
  const auto system = HystereticLfr<PrandtlIshlinskii>::hammerstein(linear, blocks);
  const MatrixXd u = random_input(400, 2, 12) * 3.0;

  MatrixXd w(u.rows(), 2);
  for (Eigen::Index i = 0; i < 2; ++i) {
    auto state = blocks[std::size_t(i)].initial_state();
    for (Eigen::Index k = 0; k < u.rows(); ++k)
      w(k, i) = blocks[std::size_t(i)].step(state, u(k, i));
  }
  const MatrixXd expected = linear.simulate(w);
  const MatrixXd y = system.simulate(u);
  EXPECT_LE((y - expected).cwiseAbs().maxCoeff(), 1e-13 * expected.cwiseAbs().maxCoeff());
  EXPECT_EQ(system.inputs(), 2u);
  EXPECT_EQ(system.outputs(), 2u);
}

TEST(HystereticLfr, StepDoesNotAllocate) {
  const auto lfr = random_lfr(21);
  const MatrixXd u = random_input(200, 2, 22).transpose();
  auto state = lfr.initial_state();
  VectorXd y(3);
  const long before = test::allocation_count();
  for (Eigen::Index k = 0; k < u.cols(); ++k)
    lfr.step(state, {u.col(k).data(), 2}, {y.data(), 3});
  EXPECT_EQ(test::allocation_count() - before, 0);
}

TEST(HystereticLfr, PeriodicStateReturnsToItselfAfterAPeriod) {
  const auto lfr = random_lfr(31, 0.05);
  const MatrixXd period = random_input(128, 2, 32) * 2.0;
  const auto start = lfr.periodic_state(period);
  auto state = start;
  const MatrixXd first = lfr.simulate(period, state);
  EXPECT_LE((state.x - start.x).cwiseAbs().maxCoeff(), 1e-9 * start.x.cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < start.feedback.size(); ++i)
    for (std::size_t j = 0; j < start.feedback[i].play.size(); ++j)
      EXPECT_NEAR(state.feedback[i].play[j], start.feedback[i].play[j], 1e-9);
  // A second period repeats the first: what a long run from rest settles to.
  const MatrixXd second = lfr.simulate(period, state);
  EXPECT_LE((second - first).cwiseAbs().maxCoeff(), 1e-9 * first.cwiseAbs().maxCoeff());
  auto settled = lfr.initial_state();
  for (int p = 0; p < 200; ++p)
    lfr.simulate(period, settled);
  const MatrixXd late = lfr.simulate(period, settled);
  EXPECT_LE((late - first).cwiseAbs().maxCoeff(), 1e-8 * first.cwiseAbs().maxCoeff());
}

// x+ = 0.999 x + u - 0.01 w, z = x, w = PI(z): a stable loop (pole near 0.985) that forgets
// slowly, about a factor 0.2 per 100-sample period. The fixed point on w alone diverges here:
// an error in w moves the open loop's periodic state (pole 0.999) some 6 times as much as the
// closed loop forgets in a period, so periodic_state has to run periods instead.
TEST(HystereticLfr, PeriodicStateOfAStableLoopThatForgetsSlowly) {
  StateSpace::Params p;
  p.sample_time = 1e-3;
  p.a = MatrixXd::Constant(1, 1, 0.999);
  p.b = MatrixXd{{1.0, -0.01}};
  p.c = MatrixXd{{1.0}, {1.0}};
  p.d = MatrixXd::Zero(2, 2);
  const HystereticLfr<PrandtlIshlinskii> lfr(
      StateSpace(p), 1, {PrandtlIshlinskii({{0.0, 0.5, 1.5}, {1.0, 0.3, 0.1}, 0.0})});
  const MatrixXd period = random_input(100, 1, 33) * 2.0;
  const auto start = lfr.periodic_state(period);
  auto state = start;
  const MatrixXd first = lfr.simulate(period, state);
  EXPECT_NEAR(state.x[0], start.x[0], 1e-8 * std::abs(start.x[0]));
  auto settled = lfr.initial_state();
  for (int k = 0; k < 300; ++k)
    lfr.simulate(period, settled);
  const MatrixXd late = lfr.simulate(period, settled);
  EXPECT_LE((late - first).cwiseAbs().maxCoeff(), 1e-8 * first.cwiseAbs().maxCoeff());
}

TEST(HystereticLfr, PeriodicStateOfADivergingLoopSaysSo) {
  const auto lfr = random_lfr(31, 5.0);  // a loop gain far above 1
  const MatrixXd period = random_input(128, 2, 32) * 2.0;
  EXPECT_FALSE(lfr.simulate(period).cwiseAbs().maxCoeff() < 1e6);  // it does diverge
  // Said as such, not as a periodic state that failed to converge with a change of nan.
  EXPECT_HYST_ERROR(lfr.periodic_state(period),
                    "hysteretic LFR: the loop diverges: in period 2 of the search for the periodic "
                    "steady state the hysteresis outputs reach ");
}

TEST(HystereticLfr, NamesWhatIsWrong) {
  std::mt19937_64 random(41);
  StateSpace::Params p;
  p.a = stable_a(2, random);
  p.b = random_matrix(2, 3, random);
  p.c = random_matrix(3, 2, random);
  p.d = random_matrix(3, 3, random);  // Dzw = d(2, 2) is not zero
  EXPECT_HYST_ERROR(HystereticLfr<PrandtlIshlinskii>(StateSpace(p), 2, {pi_block(1)}), "D(2, 2)");
  EXPECT_HYST_ERROR(HystereticLfr<PrandtlIshlinskii>(StateSpace(p), 1, {pi_block(1)}),
                    "the linear block has 3 inputs; it needs 2");
  p.d(2, 2) = 0.0;
  EXPECT_HYST_ERROR(
      HystereticLfr<PrandtlIshlinskii>(StateSpace(p), 0, {pi_block(1), pi_block(1), pi_block(1)}),
      "at least one input");
  const StateSpace two_outputs({p.a, p.b, p.c.topRows(2), MatrixXd::Zero(2, 3), 1.0});
  EXPECT_HYST_ERROR(HystereticLfr<PrandtlIshlinskii>(two_outputs, 1, {pi_block(1), pi_block(1)}),
                    "more than the 2 hysteresis inputs");
  EXPECT_HYST_ERROR(HystereticLfr<PrandtlIshlinskii>::hammerstein(StateSpace(p), {pi_block(1)}),
                    "1 blocks for a linear block with 3 inputs");
  const HystereticLfr<PrandtlIshlinskii> lfr(StateSpace(p), 2, {pi_block(1)});
  MatrixXd u = MatrixXd::Zero(5, 2);
  u(3, 1) = std::nan("");
  EXPECT_HYST_ERROR(lfr.simulate(u), "input(3, 1) = nan is not finite");
  EXPECT_HYST_ERROR(lfr.simulate(MatrixXd::Zero(5, 3)), "input has 3 columns; the model has 2");
  EXPECT_HYST_ERROR(lfr.make_state(VectorXd::Zero(3)), "the state x has 3 values");
}

// --- run-time form, model files and score -------------------------------------------------------

std::unique_ptr<DynamicModel> registry_pi(double scale) {
  return ModelRegistry::builtin().find("pi").create(
      json{{"thresholds", {0.0, 0.2 * scale, 0.6 * scale}}, {"weights", {0.3, 0.2, 0.1}}}, nullptr);
}

TEST(HystereticLfrFile, RoundTripSimulatesTheSame) {
  const auto lfr = random_lfr(51);
  const auto a = registry_pi(1.0), b = registry_pi(2.0);
  const AnyHystereticLfr model(lfr.linear(), 2, {a.get(), b.get()});
  EXPECT_EQ(model.feedback_model(), "pi");
  // A (4 states) by its 4 eigenvalues, B (4 x 4), C (5 x 4) and D (5 x 4) less the 2 x 2 zero
  // Dzw, and 2 x 4 PI parameters (3 weights and the offset; the thresholds are fixed by the fit
  // and not counted: see the PI's entry).
  ASSERT_EQ(lfr.linear().order(), 4u);
  ASSERT_EQ(registry_pi(1)->parameter_count(), 4u);
  EXPECT_EQ(model.feedback_parameter_count(), 8u);
  EXPECT_EQ(model.parameter_count(), 4u + 16u + 20u + 20u - 4u + 8u);
  const MatrixXd u = random_input(300, 2, 52);
  const MatrixXd expected = lfr.simulate(u);
  EXPECT_EQ(model.simulate(u), expected);

  const json document = hysteretic_lfr_to_json(model, {{"note", "test"}});
  const auto loaded = hysteretic_lfr_from_json(json::parse(document.dump()), "m.json");
  EXPECT_EQ(loaded.model.simulate(u), expected);
  EXPECT_EQ(loaded.info, (json{{"note", "test"}}));
  EXPECT_EQ(hysteretic_lfr_to_json(loaded.model, loaded.info), document);
}

TEST(HystereticLfrFile, ErrorsNameTheFileAndTheField) {
  const auto lfr = random_lfr(61);
  const auto a = registry_pi(1.0), b = registry_pi(2.0);
  const json good = hysteretic_lfr_to_json(AnyHystereticLfr(lfr.linear(), 2, {a.get(), b.get()}));
  auto with = [&](auto change) {
    json document = good;
    change(document);
    return document;
  };
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(with([](json& d) { d["params"]["feedback"][1]["model"] = "nope"; }),
                               "m.json"),
      "m.json: params.feedback[1].model: unknown model 'nope'");
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(
          with([](json& d) { d["params"]["feedback"][0]["params"]["weights"] = "x"; }), "m.json"),
      "m.json: params.feedback[0].params.weights");
  EXPECT_HYST_ERROR(hysteretic_lfr_from_json(
                        with([](json& d) { d["params"]["linear"]["d"][4][3] = 1.0; }), "m.json"),
                    "m.json: params.linear.d[4][3]: hysteretic LFR: D(4, 3)");
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(with([](json& d) { d["params"]["inputs"] = 3; }), "m.json"),
      "m.json: params.linear.b: hysteretic LFR: the linear block has 4 inputs");
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(with([](json& d) { d["params"]["feedback"].erase(1); }), "m.json"),
      "the linear block has 4 inputs; it needs 3");
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(with([](json& d) { d["model"] = "state_space"; }), "m.json"),
      "m.json: model: \"state_space\" is not a hysteretic LFR model file");
  const auto narx_entry = ModelRegistry::builtin().find("rate_dependent_pi");
  EXPECT_HYST_ERROR(hysteretic_lfr_from_json(with([&](json& d) {
                                               d["params"]["feedback"][1] = {
                                                   {"model", "rate_dependent_pi"},
                                                   {"params", narx_entry.example_params}};
                                             }),
                                             "m.json"),
                    "feedback[1] is a 'rate_dependent_pi' model, which cannot be a hysteresis");
  const auto gpi = ModelRegistry::builtin().find("gpi");
  EXPECT_HYST_ERROR(
      hysteretic_lfr_from_json(
          with([&](json& d) {
            d["params"]["feedback"][1] = {{"model", "gpi"}, {"params", gpi.example_params}};
          }),
          "m.json"),
      "feedback[1] is a 'gpi' model, feedback[0] a 'pi' model");
}

TEST(HystereticLfrScore, WithTheFeedbackCutItScoresAsTheLinearModel) {
  std::mt19937_64 random(71);
  const Eigen::Index n = 3, m = 2, p = 2;
  StateSpace::Params params;
  params.a = stable_a(n, random);
  params.b = MatrixXd::Zero(n, m + 1);
  params.b.leftCols(m) = random_matrix(n, m, random);
  params.c = random_matrix(p + 1, n, random);
  params.d = MatrixXd::Zero(p + 1, m + 1);
  params.d.topLeftCorner(p, m) = random_matrix(p, m, random);
  const auto block = registry_pi(1.0);
  const AnyHystereticLfr model(StateSpace(params), m, {block.get()});
  const StateSpace linear(
      {params.a, params.b.leftCols(m), params.c.topRows(p), params.d.topLeftCorner(p, m), 1.0});

  PeriodicSignals u{32, 2, 2, 2, {}}, y{32, 2, 2, 2, {}};
  for (std::size_t r = 0; r < 2; ++r) {
    const MatrixXd period = random_input(32, 2, 80 + r);
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t s = 0; s < 32; ++s)
        for (std::size_t c = 0; c < 2; ++c)
          u.values.push_back(period(Eigen::Index(s), Eigen::Index(c)));
  }
  std::normal_distribution<double> gauss;
  for (std::size_t i = 0; i < u.values.size(); ++i)
    y.values.push_back(gauss(random));
  for (const bool periodic : {false, true}) {
    const ScoreOptions options{periodic, periodic ? 0u : 4u};
    const auto expected = score_state_space(linear, u, y, options);
    const auto score = score_hysteretic_lfr(model, u, y, options);
    EXPECT_NEAR(score.mean_relative_error, expected.mean_relative_error,
                1e-12 * expected.mean_relative_error);
    EXPECT_EQ(score.scored_samples, expected.scored_samples);
  }
}

}  // namespace
}  // namespace hyst::hysteretic_lfr_test
