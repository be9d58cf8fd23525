// Tests of the simulated set-up (sf_filter/bench/wang_table2/simulation.hpp): exact identities
// of one run, and the noise levels over many draws against the set-up's parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "wang_table2/error_statistics.hpp"
#include "wang_table2/simulation.hpp"

namespace {

using wang_table2::ErrorSeries;
using wang_table2::Parameters;
using wang_table2::SimulatedRun;
using wang_table2::simulateRun;

Parameters shortParameters() {
  Parameters s;
  s.duration = 2.0;
  s.warmup = 0.0;
  return s;
}

TEST(Simulation, SizesAndVisionTimes) {
  std::mt19937_64 rng(3);
  const SimulatedRun run = simulateRun(shortParameters(), rng);
  EXPECT_EQ(run.steps(), 2000);
  EXPECT_EQ(run.encoderRate.size(), 2001u);
  EXPECT_EQ(run.bias.size(), 2001u);
  ASSERT_EQ(run.vision.size(), 64u);  // 32 Hz for 2 s, the first at t = 0
  for (std::size_t i = 0; i < run.vision.size(); ++i) {
    EXPECT_DOUBLE_EQ(run.vision[i].time, static_cast<double>(i) / 32.0);
  }
}

TEST(Simulation, WithoutNoiseNothingMoves) {
  Parameters s = shortParameters();
  s.speedStd = 0.0;
  s.biasStd = 0.0;
  s.encoderNoiseDensity = 0.0;
  std::mt19937_64 rng(3);
  const SimulatedRun run = simulateRun(s, rng);
  for (double x : run.position) EXPECT_EQ(x, 0.0);
  for (double r : run.encoderRate) EXPECT_EQ(r, 0.0);
  for (const auto& u : run.vision) EXPECT_EQ(u.position, 0.0);
}

TEST(Simulation, EncoderRateIsTheDStepDifferenceOfPositionAndBias) {
  // Without the encoder's white noise, v(k) - v(k - d) = x(k) - x(k - d) + Delta sum b(i),
  // i = k - d .. k - 1 (eq. 1 integrated), so v'(k) d Delta is that sum.
  Parameters s = shortParameters();
  s.encoderNoiseDensity = 0.0;
  s.differenceSteps = 3;
  std::mt19937_64 rng(5);
  const SimulatedRun run = simulateRun(s, rng);
  const double dt = s.encoderPeriod;
  for (int k = 3; k <= run.steps(); k += 97) {
    const auto i = static_cast<std::size_t>(k);
    const double expected = run.position[i] - run.position[i - 3] +
                            dt * (run.bias[i - 3] + run.bias[i - 2] + run.bias[i - 1]);
    EXPECT_NEAR(run.encoderRate[i] * 3 * dt, expected, 1e-14) << k;
  }
}

TEST(Simulation, VisionSeesThePositionInterpolatedAtItsTime) {
  std::mt19937_64 rng(7);
  const SimulatedRun run = simulateRun(shortParameters(), rng);
  // 1/32 s = 31.25 steps: a quarter of the way from step 31 to step 32.
  EXPECT_NEAR(run.vision[1].position, 0.75 * run.position[31] + 0.25 * run.position[32], 1e-15);
  // 2/32 s = 62.5 steps.
  EXPECT_NEAR(run.vision[2].position, 0.5 * run.position[62] + 0.5 * run.position[63], 1e-15);
  EXPECT_EQ(run.vision[0].position, run.position[0]);
}

TEST(Simulation, BiasIsStationaryWithTheGivenStdAndTimeConstant) {
  // b(0) is drawn from the stationary law N(0, sigma_b^2); one step later the part of b not
  // explained by c b(k), c = exp(-Delta / T), has variance sigma_b^2 (1 - c^2).
  Parameters s = shortParameters();
  s.duration = 0.01;
  s.biasTimeConstant = 0.005;  // short, so that the innovation is large enough to measure
  const double c = std::exp(-s.encoderPeriod / s.biasTimeConstant);
  ErrorSeries start, innovation;
  for (int r = 0; r < 4000; ++r) {
    std::mt19937_64 rng(1000 + r);
    const SimulatedRun run = simulateRun(s, rng);
    start.add(run.bias[0]);
    innovation.add(run.bias[1] - c * run.bias[0]);
  }
  // Sample variances of 4000 normal draws: relative standard error sqrt(2 / 4000) = 2.2 %.
  EXPECT_NEAR(std::sqrt(start.variance()), s.biasStd, 0.05 * s.biasStd);
  EXPECT_NEAR(std::sqrt(innovation.variance()), s.biasStd * std::sqrt(1.0 - c * c),
              0.05 * s.biasStd * std::sqrt(1.0 - c * c));
}

TEST(Simulation, EncoderWhiteNoiseHasTheGivenDensity) {
  // Robot at rest, no bias, d = 1: v'(k) = omega increments / Delta, variance q / Delta.
  Parameters s = shortParameters();
  s.duration = 20.0;
  s.speedStd = 0.0;
  s.biasStd = 0.0;
  s.differenceSteps = 1;
  std::mt19937_64 rng(11);
  const SimulatedRun run = simulateRun(s, rng);
  ErrorSeries rate;
  for (double r : run.encoderRate) rate.add(r);
  const double expected = s.encoderNoiseDensity / s.encoderPeriod;
  EXPECT_NEAR(rate.variance(), expected, 0.05 * expected);  // 20001 draws: 1 % std. error
}

TEST(Simulation, SpeedHasTheGivenStd) {
  // The position's increments over one step are Delta times the mean speed of the step.
  Parameters s = shortParameters();
  s.duration = 0.002;
  ErrorSeries speed;
  for (int r = 0; r < 4000; ++r) {
    std::mt19937_64 rng(5000 + r);
    const SimulatedRun run = simulateRun(s, rng);
    speed.add((run.position[1] - run.position[0]) / s.encoderPeriod);
  }
  EXPECT_NEAR(std::sqrt(speed.variance()), s.speedStd, 0.05 * s.speedStd);
}

TEST(Simulation, SameSeedSameRun) {
  std::mt19937_64 a(42), b(42);
  const SimulatedRun x = simulateRun(shortParameters(), a), y = simulateRun(shortParameters(), b);
  EXPECT_EQ(x.position, y.position);
  EXPECT_EQ(x.encoderRate, y.encoderRate);
  EXPECT_EQ(x.vision.back().unitNoise, y.vision.back().unitNoise);
}

}  // namespace
