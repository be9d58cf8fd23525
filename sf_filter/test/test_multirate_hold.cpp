// Tests of the multi-rate hold (Armesto et al., Algorithm 1) on sequences: a slow input
// sampled every fourth base period, held at every period.
#include <gtest/gtest.h>

#include "sf_filter/core/alignment/multirate_hold.hpp"

namespace {

using sf_filter::HoldPrimitive;
using sf_filter::MultiRateHold;

constexpr double kT = 0.01;  // base period
constexpr int kRatio = 4;    // the input is sampled every kRatio periods

/// Algorithm 1 over 40 periods of u(t): the output at each period k (t = k T).
template <class Signal>
std::vector<double> runHold(MultiRateHold& hold, Signal u) {
  std::vector<double> out;
  for (int k = 1; k <= 40; ++k) {
    const double t = k * kT;
    if (k % kRatio == 0) {
      hold.sampled(t, u(t));
      out.push_back(u(t));
    } else {
      out.push_back(hold.ready() ? hold.value(t) : 0.0);
    }
  }
  return out;
}

TEST(MultiRateHold, ZeroOrderHoldRepeatsTheLastSample) {
  MultiRateHold hold(HoldPrimitive::Taylor, 0);
  const auto u = [](double t) { return 1.0 + 2.0 * t; };
  const std::vector<double> out = runHold(hold, u);
  for (int k = kRatio + 1; k <= 40; ++k) {
    const int sampled = k - k % kRatio;  // the last sampled period
    EXPECT_DOUBLE_EQ(out[k - 1], u(sampled * kT)) << k;
  }
}

TEST(MultiRateHold, FirstOrderHoldFollowsARampOnceTwoSamplesArrived) {
  for (HoldPrimitive p : {HoldPrimitive::Lagrange, HoldPrimitive::Bezier, HoldPrimitive::Taylor}) {
    MultiRateHold hold(p, 1);
    const auto u = [](double t) { return 1.0 + 2.0 * t; };
    const std::vector<double> out = runHold(hold, u);
    for (int k = 2 * kRatio; k <= 40; ++k) EXPECT_NEAR(out[k - 1], u(k * kT), 1e-12) << k;
    // Between the first and second sample only one is stored: the hold is zero-order.
    EXPECT_DOUBLE_EQ(out[kRatio + 1], u(kRatio * kT));
  }
}

TEST(MultiRateHold, SecondOrderLagrangeFollowsAParabolaOnceThreeSamplesArrived) {
  MultiRateHold hold(HoldPrimitive::Lagrange, 2);
  const auto u = [](double t) { return 0.5 - t + 30.0 * t * t; };
  const std::vector<double> out = runHold(hold, u);
  for (int k = 3 * kRatio; k <= 40; ++k) EXPECT_NEAR(out[k - 1], u(k * kT), 1e-12) << k;
  EXPECT_EQ(hold.history().size(), 3);  // the shift register holds order + 1 samples
}

TEST(MultiRateHold, ClearForgetsTheHistory) {
  MultiRateHold hold(HoldPrimitive::Bezier, 1);
  hold.sampled(0.0, 1.0);
  EXPECT_TRUE(hold.ready());
  hold.clear();
  EXPECT_FALSE(hold.ready());
}

}  // namespace
