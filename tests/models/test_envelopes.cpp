#include "hyst/models/envelopes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"

namespace hyst {
namespace {

// Closed forms by hand: tanh(0) = 0, atan(1) = pi/4.
TEST(Envelopes, ValuesAtHandPoints) {
  const double linear[] = {2.0, -1.0};
  EXPECT_EQ(LinearEnvelope::value(linear, 3.0), 5.0);
  const double tanh_c[] = {40.0, 0.8, -3.2, 40.0};
  EXPECT_EQ(TanhEnvelope::value(tanh_c, 4.0), 40.0);  // 0.8 * 4 - 3.2 = 0
  EXPECT_NEAR(TanhEnvelope::value(tanh_c, 0.0), 40.0 * std::tanh(-3.2) + 40.0, 40 * 4e-16);
  const double atan_c[] = {2.0, 1.0, 0.5, 1.0};
  EXPECT_DOUBLE_EQ(ArctanEnvelope::value(atan_c, 0.5), 2.0 * std::numbers::pi / 4 + 1.0);
}

// tanh from one exponential: within 4e-16 of the C library's tanh, exact at 0, odd, saturating.
TEST(Envelopes, TanhByExpMatchesTheLibraryTanh) {
  double worst = 0;
  for (int k = -40000; k <= 40000; ++k) {
    const double w = k * 1e-3;
    worst = std::max(worst, std::abs(tanh_by_exp(w) - std::tanh(w)));
    ASSERT_EQ(tanh_by_exp(-w), -tanh_by_exp(w));
  }
  EXPECT_LE(worst, 4e-16);
  EXPECT_EQ(tanh_by_exp(0.0), 0.0);
  EXPECT_EQ(tanh_by_exp(400.0), 1.0);
  EXPECT_EQ(tanh_by_exp(-1e308), -1.0);
  EXPECT_TRUE(std::isnan(tanh_by_exp(std::nan(""))));
}

template <class E>
void check_round_trip(const std::vector<double>& c, double v_lo, double v_hi) {
  for (int k = 0; k <= 200; ++k) {
    const double v = v_lo + (v_hi - v_lo) * k / 200.0;
    const double u = E::value(c.data(), v);
    ASSERT_TRUE(E::range(c.data()).contains(u)) << "v = " << v;
    const InverseSample back = E::inverse(c.data(), u);
    EXPECT_EQ(back.status, InverseStatus::ok) << "v = " << v;
    EXPECT_NEAR(back.input, v, 1e-9 * (1 + std::abs(v))) << "v = " << v;
  }
}

TEST(Envelopes, InverseUndoesValueInsideTheRange) {
  check_round_trip<LinearEnvelope>({0.5, 2.0}, -10, 10);
  check_round_trip<TanhEnvelope>({2.0, 0.8, -0.1, 0.05}, -3, 3);
  check_round_trip<TanhEnvelope>({40.0, 0.8, -3.2, 40.0}, 0, 8);
  check_round_trip<TanhEnvelope>({-2.0, -0.8, 0.3, 1.0}, -3, 3);  // negative convention
  check_round_trip<ArctanEnvelope>({1.5, 2.0, -0.5, 0.2}, -3, 3);
}

TEST(Envelopes, RangesAreTheSaturationLevels) {
  const double tanh_c[] = {40.0, 0.8, -3.2, 40.0};
  EXPECT_EQ(TanhEnvelope::range(tanh_c).lower, 0.0);
  EXPECT_EQ(TanhEnvelope::range(tanh_c).upper, 80.0);
  const double negative[] = {-2.0, -1.0, 0.0, 1.0};
  EXPECT_EQ(TanhEnvelope::range(negative).lower, -1.0);
  EXPECT_EQ(TanhEnvelope::range(negative).upper, 3.0);
  const double atan_c[] = {2.0, 1.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(ArctanEnvelope::range(atan_c).upper, std::numbers::pi);
  const double linear[] = {1.0, 0.0};
  EXPECT_TRUE(std::isinf(LinearEnvelope::range(linear).upper));
}

// Outside the open range the inverse clamps its argument, stays finite and says which side.
TEST(Envelopes, InverseSaturatesWithAStatus) {
  const double tanh_c[] = {40.0, 0.8, -3.2, 40.0};
  for (double u : {80.0, 95.0, 1e300}) {
    const auto s = TanhEnvelope::inverse(tanh_c, u);
    EXPECT_EQ(s.status, InverseStatus::above_range) << u;
    EXPECT_TRUE(std::isfinite(s.input));
    // atanh(1 - 1e-12) = 14.16: the largest input the clamp allows.
    EXPECT_NEAR(s.input, (std::atanh(1 - 1e-12) + 3.2) / 0.8, 1e-9);
  }
  const auto low = TanhEnvelope::inverse(tanh_c, -5.0);
  EXPECT_EQ(low.status, InverseStatus::below_range);
  EXPECT_NEAR(low.input, (-std::atanh(1 - 1e-12) + 3.2) / 0.8, 1e-9);
  const double negative[] = {-2.0, -1.0, 0.0, 1.0};  // increasing: low u -> low input
  EXPECT_EQ(TanhEnvelope::inverse(negative, -1.5).status, InverseStatus::below_range);
  EXPECT_EQ(TanhEnvelope::inverse(negative, 3.5).status, InverseStatus::above_range);
  EXPECT_LT(TanhEnvelope::inverse(negative, -1.5).input,
            TanhEnvelope::inverse(negative, 3.5).input);

  const double atan_c[] = {2.0, 1.0, 0.0, 0.0};
  EXPECT_EQ(ArctanEnvelope::inverse(atan_c, 4.0).status, InverseStatus::above_range);
  EXPECT_EQ(ArctanEnvelope::inverse(atan_c, -4.0).status, InverseStatus::below_range);
  EXPECT_TRUE(std::isfinite(ArctanEnvelope::inverse(atan_c, 4.0).input));
  EXPECT_EQ(TanhEnvelope::inverse(tanh_c, std::nan("")).status, InverseStatus::below_range);
}

TEST(Envelopes, KindNamesRoundTrip) {
  for (auto kind : {EnvelopeKind::linear, EnvelopeKind::tanh, EnvelopeKind::arctan}) {
    EXPECT_EQ(envelope_kind_from_string(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(EnvelopeKind::tanh), "tanh");
  EXPECT_HYST_ERROR(envelope_kind_from_string("cubic"),
                    "unknown envelope 'cubic' (expected linear, tanh or arctan)");
  EXPECT_EQ(visit_envelope(EnvelopeKind::arctan, [](auto e) { return decltype(e)::kind; }),
            EnvelopeKind::arctan);
  EXPECT_EQ(
      visit_envelope(EnvelopeKind::linear, [](auto e) { return decltype(e)::coefficient_count; }),
      2u);
}

TEST(Envelopes, RejectBadCoefficients) {
  const EnvelopeLabel a{"GPI", "ascending", 'a'};
  const EnvelopeLabel b{"GPI", "descending", 'b'};
  EXPECT_HYST_ERROR(
      TanhEnvelope::validate(std::vector<double>{1, 1, 0}, a),
      "GPI ascending envelope has 3 coefficients but a tanh envelope needs 4 (a0..a3)");
  EXPECT_HYST_ERROR(TanhEnvelope::validate(std::vector<double>{1, 1, NAN, 0}, b),
                    "GPI descending envelope (tanh) coefficient b2 = nan is not finite");
  EXPECT_HYST_ERROR(TanhEnvelope::validate(std::vector<double>{2, -0.8, 0, 0}, a),
                    "coefficient a1 = -0.8 must have the sign of a0 = 2: a0 a1 > 0");
  EXPECT_HYST_ERROR(ArctanEnvelope::validate(std::vector<double>{0, 1, 0, 0}, b),
                    "GPI descending envelope (arctan) coefficient b0 = 0 must be nonzero");
  EXPECT_HYST_ERROR(LinearEnvelope::validate(std::vector<double>{-1, 0}, a),
                    "GPI ascending envelope (linear) slope a0 = -1 must be > 0");
  EXPECT_NO_THROW(TanhEnvelope::validate(std::vector<double>{-2, -0.8, 0, 0}, a));
  try {
    TanhEnvelope::validate(std::vector<double>{1, 1, INFINITY, 0}, b);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "descending[2]");
  }
}

TEST(Envelopes, OrderingIsCheckedOnTheOperatingRange) {
  const double low[] = {2.0, 0.8, -0.1, 0.05};
  const double high[] = {2.0, 0.8, 0.25, 0.05};
  EXPECT_NO_THROW(check_envelope_ordering<TanhEnvelope>(low, high, -3, 3, "GPI"));
  EXPECT_NO_THROW(check_envelope_ordering<TanhEnvelope>(low, low, -3, 3, "GPI"));  // equal: ok
  EXPECT_HYST_ERROR(check_envelope_ordering<TanhEnvelope>(high, low, -3, 3, "GPI"),
                    "GPI envelopes violate the ordering gamma_l(v) <= gamma_r(v) at v = -3");
  // Different slopes cross: ordered on [0, 1] only.
  const double steep[] = {1.0, 2.0, 0.0, 0.0};
  const double flat[] = {1.0, 1.0, 0.0, 0.0};
  EXPECT_NO_THROW(check_envelope_ordering<TanhEnvelope>(flat, steep, 0, 1, "GPI"));
  EXPECT_HYST_ERROR(check_envelope_ordering<TanhEnvelope>(flat, steep, -1, 1, "GPI"),
                    "at v = -1: gamma_l = ");
  EXPECT_HYST_ERROR(check_envelope_ordering<TanhEnvelope>(low, high, NAN, 1, "GPI"),
                    "GPI operating range input_min = nan is not finite");
  EXPECT_HYST_ERROR(check_envelope_ordering<TanhEnvelope>(low, high, 2, 1, "GPI"),
                    "GPI operating range input_min = 2 must be < input_max = 1");
  try {
    check_envelope_ordering<TanhEnvelope>(high, low, -3, 3, "GPI");
  } catch (const Error& error) {
    EXPECT_EQ(error.field(), "descending");
  }
}

TEST(Envelopes, ScaleOutputScalesValues) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.1, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> c{unit(rng), unit(rng), unit(rng) - 1, unit(rng) - 1};
    const double factor = unit(rng);
    auto scaled = c;
    TanhEnvelope::scale_output(scaled.data(), factor);
    const double v = 3 * (unit(rng) - 1);
    EXPECT_NEAR(TanhEnvelope::value(scaled.data(), v), factor * TanhEnvelope::value(c.data(), v),
                1e-14);
    scaled = c;
    ArctanEnvelope::scale_output(scaled.data(), factor);
    EXPECT_NEAR(ArctanEnvelope::value(scaled.data(), v),
                factor * ArctanEnvelope::value(c.data(), v), 1e-14);
  }
}

}  // namespace
}  // namespace hyst
