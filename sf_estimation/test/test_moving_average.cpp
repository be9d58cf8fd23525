// Tests of MovingAverage against hand-computed window means and variances.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "window_test_utils.hpp"

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_adapter.hpp"
#include "sf_estimation/moving_average.hpp"

namespace {

using estimation::EstimatorAdapter;
using estimation::IEstimator;
using estimation::Index;
using estimation::Input;
using estimation::InputValue;
using estimation::InvalidInputError;
using estimation::Measurement;
using estimation::MovingAverage;
using estimation::Output;
using estimation::ParameterError;

using sftest::kInf;
using sftest::kMissing;
using sftest::measurementOf;

void expectOutput(const MovingAverage& filter, Index i, double value, double variance) {
  EXPECT_NEAR(filter.state()(i), value, 1e-12) << "entry " << i;
  if (std::isinf(variance)) {
    EXPECT_EQ(filter.covariance()(i, i), variance) << "entry " << i;
  } else {
    EXPECT_NEAR(filter.covariance()(i, i), variance, 1e-12) << "entry " << i;
  }
}

template <class Construct>
void expectParameterError(Construct construct, const std::string& parameter) {
  try {
    construct();
    FAIL() << "expected ParameterError naming " << parameter;
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
  }
}

TEST(MovingAverage, BeforeAnyValueTheOutputIsZeroWithInfiniteVariance) {
  const MovingAverage filter(2, 3);
  EXPECT_EQ(filter.state(), Eigen::VectorXd::Zero(2));
  EXPECT_EQ(filter.covariance()(0, 0), kInf);
  EXPECT_EQ(filter.covariance()(1, 1), kInf);
  EXPECT_EQ(filter.covariance()(0, 1), 0.0);
}

TEST(MovingAverage, UniformWindowMatchesHandComputedSequence) {
  MovingAverage filter(1, 3);
  // window {1}: mean 1, variance 0
  filter.estimate(measurementOf({1.0}));
  expectOutput(filter, 0, 1.0, 0.0);
  // window {2, 1}: mean 1.5, variance (0.25 + 0.25) / 2 = 0.25
  filter.estimate(measurementOf({2.0}));
  expectOutput(filter, 0, 1.5, 0.25);
  // window {6, 2, 1}: mean 3, variance (9 + 1 + 4) / 3 = 14/3
  filter.estimate(measurementOf({6.0}));
  expectOutput(filter, 0, 3.0, 14.0 / 3.0);
  // window {3, 6, 2} (1 dropped): mean 11/3, deviations -2/3, 7/3, -5/3,
  // variance (4 + 49 + 25) / 9 / 3 = 26/9
  filter.estimate(measurementOf({3.0}));
  expectOutput(filter, 0, 11.0 / 3.0, 26.0 / 9.0);
}

TEST(MovingAverage, WeightedWindowMatchesHandComputedSequence) {
  MovingAverage filter(1, 3, {3.0, 2.0, 1.0});  // newest weighs 3
  // {2}: mean 2, variance 0
  filter.estimate(measurementOf({2.0}));
  expectOutput(filter, 0, 2.0, 0.0);
  // {4 (w3), 2 (w2)}: mean (12 + 4) / 5 = 3.2,
  // variance (3 * 0.8^2 + 2 * 1.2^2) / 5 = (1.92 + 2.88) / 5 = 0.96
  filter.estimate(measurementOf({4.0}));
  expectOutput(filter, 0, 3.2, 0.96);
  // {8, 4, 2}: mean (24 + 8 + 2) / 6 = 17/3,
  // variance (3 (7/3)^2 + 2 (5/3)^2 + (11/3)^2) / 6 = (147 + 50 + 121) / 54 = 53/9
  filter.estimate(measurementOf({8.0}));
  expectOutput(filter, 0, 17.0 / 3.0, 53.0 / 9.0);
  // {0, 8, 4}: mean (0 + 16 + 4) / 6 = 10/3,
  // variance (3 (10/3)^2 + 2 (14/3)^2 + (2/3)^2) / 6 = (300 + 392 + 4) / 54 = 116/9
  filter.estimate(measurementOf({0.0}));
  expectOutput(filter, 0, 10.0 / 3.0, 116.0 / 9.0);
}

TEST(MovingAverage, EigenWeightsEqualVectorWeights) {
  MovingAverage fromVector(1, 2, std::vector<double>{1.0, 3.0});
  MovingAverage fromEigen(1, 2, Eigen::Vector2d(1.0, 3.0));
  for (double v : {1.0, 5.0}) {
    fromVector.estimate(measurementOf({v}));
    fromEigen.estimate(measurementOf({v}));
  }
  // {5 (w1), 1 (w3)}: mean (5 + 3) / 4 = 2, variance (9 + 3 * 1) / 4 = 3
  expectOutput(fromVector, 0, 2.0, 3.0);
  expectOutput(fromEigen, 0, 2.0, 3.0);
}

TEST(MovingAverage, DelayLineWeightsWaitForAWeightedValue) {
  MovingAverage filter(1, 2, {0.0, 1.0});  // outputs the previous value
  filter.estimate(measurementOf({4.0}));
  expectOutput(filter, 0, 0.0, kInf);  // only a zero-weight value held
  filter.estimate(measurementOf({6.0}));
  expectOutput(filter, 0, 4.0, 0.0);
  filter.estimate(measurementOf({8.0}));
  expectOutput(filter, 0, 6.0, 0.0);
}

TEST(MovingAverage, MissingEntriesDoNotEnterTheWindow) {
  MovingAverage filter(2, 2);
  filter.estimate(measurementOf({1.0, 10.0}));
  expectOutput(filter, 1, 10.0, 0.0);
  filter.estimate(measurementOf({2.0, kMissing}));
  // entry 0 {2, 1}: 1.5, variance 0.25; entry 1 keeps {10} (a -1 placeholder would give 4.5)
  expectOutput(filter, 0, 1.5, 0.25);
  expectOutput(filter, 1, 10.0, 0.0);
  filter.estimate(measurementOf({3.0, kMissing}));
  expectOutput(filter, 0, 2.5, 0.25);  // {3, 2}
  expectOutput(filter, 1, 10.0, 0.0);
  filter.estimate(measurementOf({kMissing, 20.0}));
  expectOutput(filter, 0, 2.5, 0.25);   // unchanged
  expectOutput(filter, 1, 15.0, 25.0);  // {20, 10}: mean 15, variance (25 + 25) / 2
}

TEST(MovingAverage, NonFiniteMeasurementThrowsAndChangesNothing) {
  MovingAverage filter(2, 2);
  filter.estimate(measurementOf({1.0, 10.0}));
  EXPECT_THROW(filter.estimate(measurementOf({std::numeric_limits<double>::infinity(), 5.0})),
               InvalidInputError);
  Measurement<Eigen::Dynamic> withNaN = measurementOf({2.0, 5.0});
  withNaN.value(1) = std::nan("");
  EXPECT_THROW(filter.estimate(withNaN), InvalidInputError);
  expectOutput(filter, 0, 1.0, 0.0);
  expectOutput(filter, 1, 10.0, 0.0);
  // the rejected 2 and 5 did not enter the windows: {3, 1} -> 2 and {20, 10} -> 15
  filter.estimate(measurementOf({3.0, 20.0}));
  expectOutput(filter, 0, 2.0, 1.0);
  expectOutput(filter, 1, 15.0, 25.0);
}

TEST(MovingAverage, WrongMeasurementSizeThrows) {
  MovingAverage filter(2, 2);
  EXPECT_THROW(filter.estimate(measurementOf({1.0})), InvalidInputError);
}

TEST(MovingAverage, ControlsMustBeEmpty) {
  MovingAverage filter(1, 2);
  EXPECT_NO_THROW(filter.setControl(Eigen::VectorXd(0)));
  EXPECT_THROW(filter.setControl(Eigen::VectorXd::Zero(1)), InvalidInputError);
  EXPECT_EQ(filter.controlSize(), 0);
}

TEST(MovingAverage, BadParametersThrowNamingTheParameter) {
  expectParameterError([] { MovingAverage(0, 3); }, "inputCount");
  expectParameterError([] { MovingAverage(1, 0); }, "windowSize");
  expectParameterError([] { MovingAverage(1, -2, {1.0}); }, "windowSize");
  expectParameterError([] { MovingAverage(1, 3, {1.0, 2.0}); }, "weights");
  expectParameterError([] { MovingAverage(1, 2, {1.0, -0.5}); }, "weights");
  expectParameterError([] { MovingAverage(1, 2, {1.0, std::nan("")}); }, "weights");
  expectParameterError([] { MovingAverage(1, 2, {0.0, 0.0}); }, "weights");
  expectParameterError([] { MovingAverage(1, 2, Eigen::Vector3d::Ones()); }, "weights");
}

TEST(MovingAverage, ResetEmptiesTheWindows) {
  MovingAverage filter(1, 3);
  filter.estimate(measurementOf({100.0}));
  filter.reset();
  expectOutput(filter, 0, 0.0, kInf);
  filter.estimate(measurementOf({4.0}));
  expectOutput(filter, 0, 4.0, 0.0);  // 100 is gone
}

TEST(MovingAverage, DescriptionNamesSizesAndWeights) {
  EXPECT_EQ(MovingAverage(2, 5).description(), "MovingAverage(inputs=2, window=5)");
  EXPECT_EQ(MovingAverage(1, 3, {3.0, 2.0, 0.5}).description(),
            "MovingAverage(inputs=1, window=3, weights=[3, 2, 0.5])");
}

TEST(MovingAverage, WorksThroughTheEstimatorInterface) {
  EstimatorAdapter<MovingAverage> adapter(MovingAverage(2, 2));
  IEstimator& estimator = adapter;
  EXPECT_EQ(estimator.description(), "MovingAverage(inputs=2, window=2)");
  EXPECT_EQ(estimator.getLastEstimate()[1].getVariance(), kInf);

  Input first;
  first.add(InputValue(1.0, 0.5));
  first.add(InputValue::missing());
  const Output out1 = estimator.estimate(first);
  ASSERT_EQ(out1.size(), 2u);
  EXPECT_EQ(out1[0].getValue(), 1.0);
  EXPECT_EQ(out1[0].getVariance(), 0.0);
  EXPECT_EQ(out1[0].getTimestamp(), 0.5);
  EXPECT_EQ(out1[1].getValue(), 0.0);
  EXPECT_EQ(out1[1].getVariance(), kInf);

  Input second;
  second.add(InputValue(3.0, 1.0));
  second.add(InputValue(5.0, 1.0));
  const Output out2 = estimator.estimate(second);
  EXPECT_EQ(out2[0].getValue(), 2.0);  // {3, 1}
  EXPECT_EQ(out2[0].getVariance(), 1.0);
  EXPECT_EQ(out2.covariance(0, 0), 1.0);
  EXPECT_EQ(out2[1].getValue(), 5.0);
  EXPECT_EQ(estimator.getLastEstimate()[0].getValue(), 2.0);

  Input tooShort;
  tooShort.add(InputValue(1.0));
  EXPECT_THROW(estimator.estimate(tooShort), InvalidInputError);
  EXPECT_NO_THROW(estimator.setControlInput(Input()));
  EXPECT_THROW(estimator.setControlInput(tooShort), InvalidInputError);

  estimator.reset();
  EXPECT_EQ(estimator.getLastEstimate()[0].getValue(), 0.0);
  EXPECT_EQ(estimator.getLastEstimate()[0].getVariance(), kInf);
}

}  // namespace
