// Tests of ConfidenceWeightedAveraging against hand-computed inverse-variance means.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "window_test_utils.hpp"

#include "sf_estimation/confidence_weighted_averaging.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_adapter.hpp"

namespace {

using estimation::ConfidenceWeightedAveraging;
using estimation::EstimatorAdapter;
using estimation::IEstimator;
using estimation::Index;
using estimation::Input;
using estimation::InputValue;
using estimation::InvalidInputError;
using estimation::Measurement;
using estimation::NumericalError;
using estimation::Output;
using estimation::ParameterError;

using sftest::kInf;
using sftest::kMissing;
using sftest::measurementOf;

void expectEstimate(const ConfidenceWeightedAveraging& filter, double value, double variance) {
  ASSERT_EQ(filter.state().size(), 1);
  EXPECT_NEAR(filter.state()(0), value, 1e-12);
  if (std::isinf(variance)) {
    EXPECT_EQ(filter.covariance()(0, 0), variance);
  } else {
    EXPECT_NEAR(filter.covariance()(0, 0), variance, 1e-12);
  }
}

void expectParameterError(Index inputCount, const Eigen::VectorXd& variances,
                          const std::string& parameter) {
  try {
    ConfidenceWeightedAveraging filter(inputCount, variances);
    FAIL() << "expected ParameterError naming " << parameter;
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
  }
}

TEST(ConfidenceWeightedAveraging, InitialEstimateIsZeroWithInfiniteVariance) {
  const ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  expectEstimate(filter, 0.0, kInf);
  EXPECT_EQ(filter.stateSize(), 1);
  EXPECT_EQ(filter.measurementSize(), 2);
}

TEST(ConfidenceWeightedAveraging, FusesWithDefaultVariances) {
  ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  // x = (2/1 + 6/4) / (1/1 + 1/4) = 3.5 / 1.25 = 2.8, variance 1 / 1.25 = 0.8
  filter.estimate(measurementOf({2.0, 6.0}));
  expectEstimate(filter, 2.8, 0.8);
  // three sensors, variances 1, 2, 4: weights 1, 0.5, 0.25, sum 1.75
  ConfidenceWeightedAveraging three(3, Eigen::Vector3d(1.0, 2.0, 4.0));
  // x = (1 + 0.5 * 3 + 0.25 * 8) / 1.75 = 4.5 / 1.75 = 18/7, variance 1 / 1.75 = 4/7
  three.estimate(measurementOf({1.0, 3.0, 8.0}));
  expectEstimate(three, 18.0 / 7.0, 4.0 / 7.0);
}

TEST(ConfidenceWeightedAveraging, PerStepVarianceReplacesTheDefault) {
  ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  Measurement<Eigen::Dynamic> z = measurementOf({2.0, 6.0});
  z.varianceGiven(1) = true;
  z.variance(1) = 1.0;
  // equal variances 1, 1: x = (2 + 6) / 2 = 4, variance 1/2
  filter.estimate(z);
  expectEstimate(filter, 4.0, 0.5);
}

TEST(ConfidenceWeightedAveraging, MissingEntriesAreLeftOutAndAllMissingKeepsTheEstimate) {
  ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  filter.estimate(measurementOf({kMissing, 6.0}));
  expectEstimate(filter, 6.0, 4.0);  // only sensor 1: its value and variance
  filter.estimate(measurementOf({kMissing, kMissing}));
  expectEstimate(filter, 6.0, 4.0);
  filter.estimate(measurementOf({2.0, kMissing}));
  expectEstimate(filter, 2.0, 1.0);  // steps are independent: 6 is not remembered
}

TEST(ConfidenceWeightedAveraging, InvalidMeasurementsThrowAndChangeNothing) {
  ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  filter.estimate(measurementOf({2.0, 6.0}));
  Measurement<Eigen::Dynamic> withNaN = measurementOf({2.0, 6.0});
  withNaN.value(0) = std::nan("");
  EXPECT_THROW(filter.estimate(withNaN), InvalidInputError);
  Measurement<Eigen::Dynamic> badVariance = measurementOf({5.0, 6.0});
  badVariance.varianceGiven(0) = true;
  badVariance.variance(0) = 0.0;
  EXPECT_THROW(filter.estimate(badVariance), InvalidInputError);
  EXPECT_THROW(filter.estimate(measurementOf({1.0})), InvalidInputError);
  // 1/1e-320 overflows to inf, the fused value is inf/inf
  Measurement<Eigen::Dynamic> overflowing = measurementOf({5.0, 6.0});
  overflowing.varianceGiven(0) = true;
  overflowing.variance(0) = 1e-320;
  EXPECT_THROW(filter.estimate(overflowing), NumericalError);
  expectEstimate(filter, 2.8, 0.8);
}

TEST(ConfidenceWeightedAveraging, BadParametersThrowNamingTheParameter) {
  expectParameterError(0, Eigen::VectorXd(0), "inputCount");
  expectParameterError(3, Eigen::Vector2d(1.0, 1.0), "defaultVariances");
  expectParameterError(2, Eigen::Vector2d(1.0, 0.0), "defaultVariances");
  expectParameterError(2, Eigen::Vector2d(-1.0, 1.0), "defaultVariances");
  expectParameterError(2, Eigen::Vector2d(1.0, kInf), "defaultVariances");
  expectParameterError(2, Eigen::Vector2d(1.0, std::nan("")), "defaultVariances");
}

TEST(ConfidenceWeightedAveraging, ResetRestoresTheInitialEstimate) {
  ConfidenceWeightedAveraging filter(2, Eigen::Vector2d(1.0, 4.0));
  filter.estimate(measurementOf({2.0, 6.0}));
  filter.reset();
  expectEstimate(filter, 0.0, kInf);
}

TEST(ConfidenceWeightedAveraging, WorksThroughTheEstimatorInterface) {
  EstimatorAdapter<ConfidenceWeightedAveraging> adapter(
      ConfidenceWeightedAveraging(3, Eigen::Vector3d(1.0, 2.0, 4.0)));
  IEstimator& estimator = adapter;
  EXPECT_EQ(estimator.description(),
            "ConfidenceWeightedAveraging(inputs=3, defaultVariances=[1, 2, 4])");
  Input in;
  in.add(InputValue(1.0, 0.25, 3.0));  // own variance 0.25: weight 4
  in.add(InputValue(3.0, 3.5));        // default variance 2: weight 0.5
  in.add(InputValue::missing());
  const Output out = estimator.estimate(in);
  // x = (4 * 1 + 0.5 * 3) / 4.5 = 5.5 / 4.5 = 11/9, variance 1 / 4.5 = 2/9
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].getValue(), 11.0 / 9.0, 1e-12);
  EXPECT_NEAR(out[0].getVariance(), 2.0 / 9.0, 1e-12);
  EXPECT_EQ(out[0].getTimestamp(), 3.5);  // the newest present input
  EXPECT_NO_THROW(estimator.setControlInput(Input()));
  estimator.reset();
  EXPECT_EQ(estimator.getLastEstimate()[0].getVariance(), kInf);
}

}  // namespace
