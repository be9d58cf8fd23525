// Tests of the multi-rate hold primitives (Armesto et al., Table 1 and eq. 2) against values
// computed by hand from the formulas, and of their exactness properties: the first-order
// hold extrapolates a ramp exactly, Lagrange of order n reproduces a polynomial of degree n
// (also at non-uniform sample times), every primitive holds a constant.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <utility>

#include "sf_filter/core/alignment/hold_primitives.hpp"

namespace {

using sf_filter::HoldPrimitive;
using sf_filter::SampleHistory;

/// A history from (time, value) pairs, oldest first.
SampleHistory historyOf(std::initializer_list<std::pair<double, double>> samples) {
  SampleHistory h;
  for (const auto& s : samples) h.push(s.first, s.second);
  return h;
}

constexpr HoldPrimitive kAll[] = {HoldPrimitive::Lagrange, HoldPrimitive::Bezier,
                                  HoldPrimitive::Taylor};

TEST(HoldPrimitives, OrderZeroHoldsTheNewestSample) {
  const SampleHistory h = historyOf({{0.0, 4.0}, {0.1, -1.0}, {0.2, 7.5}});
  for (HoldPrimitive p : kAll) {
    EXPECT_DOUBLE_EQ(sf_filter::holdValue(p, h, 0, 0.35), 7.5) << toString(p);
  }
}

TEST(HoldPrimitives, FirstOrderExtrapolatesARampExactly) {
  // u = 2 + 3 t sampled at 0, 0.1, 0.2: at t = 0.35 every first-order hold gives 3.05.
  const SampleHistory h = historyOf({{0.0, 2.0}, {0.1, 2.3}, {0.2, 2.6}});
  for (HoldPrimitive p : kAll) {
    EXPECT_NEAR(sf_filter::holdValue(p, h, 1, 0.35), 3.05, 1e-12) << toString(p);
  }
}

TEST(HoldPrimitives, EveryPrimitiveAndOrderHoldsAConstant) {
  // Non-uniform times: the weights of each primitive still sum to one.
  const SampleHistory h = historyOf({{0.0, 1.5}, {0.03, 1.5}, {0.1, 1.5}, {0.22, 1.5}});
  for (HoldPrimitive p : kAll) {
    for (int order = 0; order <= 3; ++order) {
      EXPECT_NEAR(sf_filter::holdValue(p, h, order, 0.5), 1.5, 1e-12)
          << toString(p) << " order " << order;
    }
  }
}

TEST(HoldPrimitives, LagrangeOfOrderNReproducesAPolynomialOfDegreeN) {
  const auto cubic = [](double t) { return 1.0 - 2.0 * t + 0.5 * t * t + 4.0 * t * t * t; };
  const auto quadratic = [](double t) { return -3.0 + t - 2.0 * t * t; };
  SampleHistory c, q;
  for (double t : {0.0, 0.07, 0.2, 0.26}) {  // non-uniform
    c.push(t, cubic(t));
    q.push(t, quadratic(t));
  }
  for (double t : {0.3, 0.4, 0.75}) {
    EXPECT_NEAR(sf_filter::lagrangeHold(c, 3, t), cubic(t), 1e-11) << t;
    EXPECT_NEAR(sf_filter::lagrangeHold(q, 2, t), quadratic(t), 1e-11) << t;
  }
  // One order too low is not exact: order 2 through the newest 3 samples of the cubic
  // misses it by 4 (t - 0.07)(t - 0.2)(t - 0.26) = 4 * 0.33 * 0.2 * 0.14 at t = 0.4.
  EXPECT_NEAR(sf_filter::lagrangeHold(c, 2, 0.4), cubic(0.4) - 4 * 0.33 * 0.2 * 0.14, 1e-11);
}

TEST(HoldPrimitives, SecondOrderOfAParabolaByHand) {
  // u = t^2 sampled at 0.1, 0.2, 0.3 (0.01, 0.04, 0.09), extrapolated to t = 0.4 (u = 0.16):
  //   Lagrange: exact, 0.16.
  //   Bezier:   s = (0.4 - 0.3) / (0.3 - 0.1) = 0.5, w1 = 1.5, w2 = -0.5, weights
  //             1.5^2 = 2.25, 2 * 1.5 * (-0.5) = -1.5, 0.25:
  //             2.25 * 0.09 - 1.5 * 0.04 + 0.25 * 0.01 = 0.145.
  //   Taylor:   u'(0.3) = (0.09 - 0.04) / 0.1 = 0.5, u'(0.2) = 0.3, u'' = (0.5 - 0.3) / 0.1 = 2:
  //             0.09 + 0.1 * 0.5 + 0.1^2 / 2 * 2 = 0.15.
  const SampleHistory h = historyOf({{0.1, 0.01}, {0.2, 0.04}, {0.3, 0.09}});
  EXPECT_NEAR(sf_filter::lagrangeHold(h, 2, 0.4), 0.16, 1e-14);
  EXPECT_NEAR(sf_filter::bezierHold(h, 2, 0.4), 0.145, 1e-14);
  EXPECT_NEAR(sf_filter::taylorHold(h, 2, 0.4), 0.15, 1e-14);
}

TEST(HoldPrimitives, NonUniformSamplesByHand) {
  // Samples (0, 1), (0.1, 2), (0.3, 5), extrapolated to t = 0.4.
  //   Taylor (eq. 2): u'(0.3) = (5 - 2) / 0.2 = 15, u'(0.1) = (2 - 1) / 0.1 = 10,
  //     u''(0.3) = (15 - 10) / (0.3 - 0.1) = 25:  5 + 0.1 * 15 + 0.01 / 2 * 25 = 6.625.
  //   Bezier: s = 0.1 / 0.3 = 1/3, w1 = 4/3, w2 = -1/3, weights 16/9, -8/9, 1/9:
  //     (16 * 5 - 8 * 2 + 1) / 9 = 65 / 9.
  //   Lagrange: l0 = (0.4 - 0.1)(0.4 - 0)/((0.3 - 0.1)(0.3 - 0)) = 2,
  //     l1 = (0.4 - 0.3)(0.4 - 0)/((0.1 - 0.3)(0.1 - 0)) = -2,
  //     l2 = (0.4 - 0.3)(0.4 - 0.1)/((0 - 0.3)(0 - 0.1)) = 1:  2 * 5 - 2 * 2 + 1 = 7.
  const SampleHistory h = historyOf({{0.0, 1.0}, {0.1, 2.0}, {0.3, 5.0}});
  EXPECT_NEAR(sf_filter::taylorHold(h, 2, 0.4), 6.625, 1e-13);
  EXPECT_NEAR(sf_filter::bezierHold(h, 2, 0.4), 65.0 / 9.0, 1e-13);
  EXPECT_NEAR(sf_filter::lagrangeHold(h, 2, 0.4), 7.0, 1e-13);
}

TEST(HoldPrimitives, TheOrderDropsToWhatTheHistoryHolds) {
  // Two samples only: any order >= 1 is the first-order hold, 4 + (4 - 3) * 0.5 / 0.1 = 9.
  const SampleHistory h = historyOf({{0.0, 3.0}, {0.1, 4.0}});
  for (HoldPrimitive p : kAll) {
    EXPECT_NEAR(sf_filter::holdValue(p, h, 3, 0.6), 9.0, 1e-12) << toString(p);
  }
}

TEST(HoldPrimitives, BernsteinWeightsAreBinomialProducts) {
  // n = 3, w1 = 0.7, w2 = 0.3: weights 0.343, 3 * 0.49 * 0.3 = 0.441, 3 * 0.7 * 0.09 = 0.189,
  // 0.027 (they sum to (0.7 + 0.3)^3 = 1); control points 1, 10, 100, 1000.
  const double points[] = {1.0, 10.0, 100.0, 1000.0};
  const double value =
      sf_filter::bernsteinCombination(3, 0.7, 0.3, [&](int l) { return points[l]; });
  EXPECT_NEAR(value, 0.343 + 4.41 + 18.9 + 27.0, 1e-12);
}

}  // namespace
