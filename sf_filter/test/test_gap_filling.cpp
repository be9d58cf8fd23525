// Tests of Wang et al.'s gap filling (Algorithm 1, eqs. 5-11) against values computed by hand
// from the Bezier weights, and of its limits: a small omega follows the filter's prediction,
// a constant stays constant.
#include <gtest/gtest.h>

#include "sf_filter/core/alignment/gap_filling.hpp"

namespace {

using sf_filter::GapFilling;

TEST(GapFilling, TwoStoredSamplesByHand) {
  // Samples u(j-1) = 1 at 0 s and u(j) = 2 at 0.1 s, N = 2, omega = 0.05 s, z^ = 3 at 0.15 s:
  //   T_N = 0.15 + 0.05 - 0 = 0.2,  w1 = (0.15 - 0) / 0.2 = 0.75,  w2 = 0.05 / 0.2 = 0.25
  //   control points z^, u(j), u(j-1) with weights 0.75^2 = 0.5625, 2 * 0.75 * 0.25 = 0.375,
  //   0.25^2 = 0.0625:  0.5625 * 3 + 0.375 * 2 + 0.0625 * 1 = 2.5
  GapFilling fill(0.05, 2);
  EXPECT_FALSE(fill.ready());
  fill.sampled(0.0, 1.0);
  fill.sampled(0.1, 2.0);
  EXPECT_NEAR(fill.value(0.15, 3.0), 2.5, 1e-14);
}

TEST(GapFilling, OneStoredSampleByHand) {
  // u(j) = 2 at 0.1 s, omega = 0.05 s, z^ = 4 at 0.15 s: T_N = 0.1, w1 = w2 = 0.5: 3.
  GapFilling fill(0.05, 1);
  fill.sampled(0.1, 2.0);
  EXPECT_NEAR(fill.value(0.15, 4.0), 3.0, 1e-14);
}

TEST(GapFilling, KeepsTheNewestNSamples) {
  GapFilling fill(0.05, 2);
  fill.sampled(-0.1, 100.0);  // shifted out by the next two
  fill.sampled(0.0, 1.0);
  fill.sampled(0.1, 2.0);
  EXPECT_NEAR(fill.value(0.15, 3.0), 2.5, 1e-14);
}

TEST(GapFilling, UsesFewerControlPointsUntilNSamplesArrived) {
  // N = 5 with two samples stored: the curve of degree 2 of the first test.
  GapFilling fill(0.05, 5);
  fill.sampled(0.0, 1.0);
  fill.sampled(0.1, 2.0);
  EXPECT_NEAR(fill.value(0.15, 3.0), 2.5, 1e-14);
}

TEST(GapFilling, ASmallOmegaFollowsThePrediction) {
  // w2 = omega / T_N -> 0: all weight on z^ (Wang et al. use omega = 0.001 s with N = 5).
  GapFilling fill(1e-7, 5);
  for (int k = 0; k < 5; ++k) fill.sampled(0.03 * k, 10.0 + k);
  EXPECT_NEAR(fill.value(0.13, -4.0), -4.0, 1e-4);
  // omega = 0.001 s: z^ keeps (1 - 0.001 / (0.13 + 0.001))^5 = 96.2 % of the weight.
  const double w1 = 0.13 / 0.131, w2 = 0.001 / 0.131;
  const double expected = w1 * w1 * w1 * w1 * w1 * -4.0 + 5 * w1 * w1 * w1 * w1 * w2 * 14.0 +
                          10 * w1 * w1 * w1 * w2 * w2 * 13.0 + 10 * w1 * w1 * w2 * w2 * w2 * 12.0 +
                          5 * w1 * w2 * w2 * w2 * w2 * 11.0 + w2 * w2 * w2 * w2 * w2 * 10.0;
  GapFilling paper(0.001, 5);
  for (int k = 0; k < 5; ++k) paper.sampled(0.03 * k, 10.0 + k);
  EXPECT_NEAR(paper.value(0.13, -4.0), expected, 1e-12);
}

TEST(GapFilling, AConstantStaysConstant) {
  GapFilling fill(0.02, 4);
  for (int k = 0; k < 4; ++k) fill.sampled(0.031 * k, 7.0);
  for (double t : {0.1, 0.12, 0.3}) EXPECT_NEAR(fill.value(t, 7.0), 7.0, 1e-12) << t;
}

}  // namespace
