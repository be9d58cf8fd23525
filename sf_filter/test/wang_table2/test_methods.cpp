// Tests of the filters of Table II's rows: the bias model's matrices by hand, and runMethod
// (which drives the fusion core) against the same Kalman filter stepped by hand with the
// values each policy defines.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <random>

#include <sf_filter/core/alignment/gap_filling.hpp>

#include "wang_table2/bias_model.hpp"
#include "wang_table2/methods.hpp"

namespace wang_table2 {
// gtest prints a parameter with this instead of its bytes.
inline void PrintTo(Method m, std::ostream* os) { *os << nameOf(m); }
}  // namespace wang_table2

namespace {

using namespace wang_table2;

TEST(BiasModel, MatricesOfFootnotesTwoToFour) {
  const Parameters s;
  const BiasFilter f = makeBiasFilter(s, 0.25, 1.5);
  // A = [1, -0.001; 0, 1 - 0.001 / 100], B = [0.001; 0], H = [1, 0].
  EXPECT_DOUBLE_EQ(f.transitionMatrix()(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(f.transitionMatrix()(0, 1), -0.001);
  EXPECT_DOUBLE_EQ(f.transitionMatrix()(1, 0), 0.0);
  EXPECT_DOUBLE_EQ(f.transitionMatrix()(1, 1), 1.0 - 1e-5);
  EXPECT_DOUBLE_EQ(f.controlMatrix()(0, 0), 0.001);
  EXPECT_DOUBLE_EQ(f.controlMatrix()(1, 0), 0.0);
  EXPECT_DOUBLE_EQ(f.observationMatrix()(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(f.observationMatrix()(0, 1), 0.0);
  // Q = diag(0.5, 0.1) x 1 ms, R as given, P(0) = diag(0.1, 0.1), x(0) = [1.5, 0].
  EXPECT_DOUBLE_EQ(f.processNoise()(0, 0), 0.5e-3);
  EXPECT_DOUBLE_EQ(f.processNoise()(1, 1), 0.1e-3);
  EXPECT_DOUBLE_EQ(f.processNoise()(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(f.measurementNoise()(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(f.covariance()(0, 0), 0.1);
  EXPECT_DOUBLE_EQ(f.covariance()(1, 1), 0.1);
  EXPECT_DOUBLE_EQ(f.covariance()(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(f.state()(0), 1.5);
  EXPECT_DOUBLE_EQ(f.state()(1), 0.0);
}

TEST(BiasModel, TheKalmanFilterFindsAConstantBias) {
  // The sign convention of eqs. 1 and 2: exact vision of a moving robot whose encoder rate
  // carries a bias of 0.3 m/s; after 20 s the filter's bias estimate is that bias.
  Parameters s;
  s.duration = 20.0;
  s.biasStd = 0.0;
  s.encoderNoiseDensity = 0.0;
  std::mt19937_64 rng(9);
  SimulatedRun run = simulateRun(s, rng);
  for (double& r : run.encoderRate) r += 0.3;
  BiasFilter f = makeBiasFilter(s, s.kalmanR, run.position[0]);
  std::size_t next = 0;
  for (int k = 0; k < run.steps(); ++k) {
    f.setControl(estimation::Vector<1>(run.encoderRate[static_cast<std::size_t>(k)]));
    estimation::Measurement<1> z = estimation::Measurement<1>::missing();
    for (; next < run.vision.size() && run.vision[next].time < (k + 1) * 1e-3 - 1e-9; ++next) {
      z.available(0) = true;
      z.value(0) = run.vision[next].position;
    }
    f.estimate(z);
  }
  EXPECT_NEAR(f.state()(1), 0.3, 0.03);
  EXPECT_NEAR(f.state()(0), run.position.back(), 0.01);
}

TEST(Methods, PoliciesOfTheThreeRows) {
  Parameters s;
  s.omega = 0.002;
  s.holdSamples = 4;
  s.fillSamples = 6;
  EXPECT_EQ(policyOf(Method::Kalman, s), sf_filter::AlignmentPolicy::sampled());
  EXPECT_EQ(policyOf(Method::Hold, s),
            sf_filter::AlignmentPolicy::hold(sf_filter::HoldPrimitive::Bezier, 3));
  EXPECT_EQ(policyOf(Method::Fill, s), sf_filter::AlignmentPolicy::fill(0.002, 6));
  EXPECT_EQ(measurementVarianceOf(Method::Kalman, s), 0.1);
  EXPECT_EQ(measurementVarianceOf(Method::Hold, s), 1.0);
  EXPECT_EQ(measurementVarianceOf(Method::Fill, s), 0.1);
}

/// The method stepped by hand: control v'(k) for the step to t_k+1, the newest vision sample
/// of [t_k, t_k+1) if any, else (FILL) the gap filling at t_k+1 or (Kalman) nothing.
ErrorSeries steppedByHand(const SimulatedRun& run, const Parameters& s, Method method,
                          double visionStd) {
  BiasFilter f = makeBiasFilter(s, measurementVarianceOf(method, s), run.position[0]);
  sf_filter::GapFilling fill(s.omega, s.fillSamples);
  ErrorSeries errors;
  std::size_t next = 0;
  for (int k = 0; k < run.steps(); ++k) {
    const double end = (k + 1) * s.encoderPeriod;
    f.setControl(estimation::Vector<1>(run.encoderRate[static_cast<std::size_t>(k)]));
    estimation::Measurement<1> z = estimation::Measurement<1>::missing();
    for (; next < run.vision.size() && run.vision[next].time < end - 1e-9; ++next) {
      const VisionSample& u = run.vision[next];
      z.available(0) = true;
      z.value(0) = u.position + visionStd * u.unitNoise;
      fill.sampled(u.time, z.value(0));
    }
    if (!z.available(0) && method == Method::Fill && fill.ready()) {
      estimation::MeasurementPrediction<1> p;
      f.predictMeasurement(p);
      z.available(0) = true;
      z.value(0) = fill.value(end, p.mean(0));
    }
    f.estimate(z);
    if (end >= s.warmup - 1e-9) {
      errors.add(f.state()(0) - run.position[static_cast<std::size_t>(k + 1)]);
    }
  }
  return errors;
}

class MethodsAgainstHand : public ::testing::TestWithParam<Method> {};

TEST_P(MethodsAgainstHand, SameErrorsAsTheFilterSteppedByHand) {
  Parameters s;
  s.duration = 3.0;
  s.warmup = 0.5;
  std::mt19937_64 rng(17);
  const SimulatedRun run = simulateRun(s, rng);
  const ErrorSeries core = runMethod(run, s, GetParam(), 0.05);
  const ErrorSeries hand = steppedByHand(run, s, GetParam(), 0.05);
  EXPECT_EQ(core.count(), 2501u);  // estimates at 0.5 s, 0.501 s, ..., 3 s
  EXPECT_EQ(core.count(), hand.count());
  EXPECT_NEAR(core.variance(), hand.variance(), 1e-15);
  EXPECT_NEAR(core.rms(), hand.rms(), 1e-15);
  EXPECT_NEAR(core.mean(), hand.mean(), 1e-15);
}

INSTANTIATE_TEST_SUITE_P(KalmanAndFill, MethodsAgainstHand,
                         ::testing::Values(Method::Kalman, Method::Fill));

TEST(Methods, HoldDiffersFromTheKalmanFilterOnlyBetweenSamples) {
  // Hold with the Kalman filter's R: where no period lacks a sample (vision at 1000 Hz) the
  // two are the same filter; at 32 Hz the hold's substitutes make them differ.
  Parameters s;
  s.duration = 1.0;
  s.warmup = 0.0;
  s.holdR = s.kalmanR;
  std::mt19937_64 rng(23);
  SimulatedRun run = simulateRun(s, rng);
  const ErrorSeries kalman32 = runMethod(run, s, Method::Kalman, 0.05);
  const ErrorSeries hold32 = runMethod(run, s, Method::Hold, 0.05);
  EXPECT_GT(std::abs(kalman32.rms() - hold32.rms()), 1e-6);
  run.vision.clear();
  for (int k = 0; k < run.steps(); ++k) {
    run.vision.push_back(
        {k * s.encoderPeriod + 2e-4, run.position[static_cast<std::size_t>(k)], std::sin(k)});
  }
  const ErrorSeries kalman = runMethod(run, s, Method::Kalman, 0.05);
  const ErrorSeries hold = runMethod(run, s, Method::Hold, 0.05);
  EXPECT_EQ(kalman.rms(), hold.rms());
  EXPECT_EQ(kalman.variance(), hold.variance());
}

}  // namespace
