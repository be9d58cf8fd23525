// Tests of MovingMedian against hand-computed window medians and variances.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "window_test_utils.hpp"

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_adapter.hpp"
#include "sf_estimation/moving_median.hpp"

namespace {

using estimation::EstimatorAdapter;
using estimation::IEstimator;
using estimation::Index;
using estimation::Input;
using estimation::InputValue;
using estimation::InvalidInputError;
using estimation::Measurement;
using estimation::MovingMedian;
using estimation::Output;
using estimation::ParameterError;

using sftest::kInf;
using sftest::kMissing;
using sftest::measurementOf;

void expectOutput(const MovingMedian& filter, Index i, double value, double variance) {
  EXPECT_NEAR(filter.state()(i), value, 1e-12) << "entry " << i;
  if (std::isinf(variance)) {
    EXPECT_EQ(filter.covariance()(i, i), variance) << "entry " << i;
  } else {
    EXPECT_NEAR(filter.covariance()(i, i), variance, 1e-12) << "entry " << i;
  }
}

TEST(MovingMedian, BeforeAnyValueTheOutputIsZeroWithInfiniteVariance) {
  const MovingMedian filter(1, 3);
  expectOutput(filter, 0, 0.0, kInf);
}

TEST(MovingMedian, OddWindowMatchesHandComputedSequence) {
  MovingMedian filter(1, 3);
  // {5}: median 5, variance 0
  filter.estimate(measurementOf({5.0}));
  expectOutput(filter, 0, 5.0, 0.0);
  // {5, 1}: median (1 + 5) / 2 = 3, mean 3, variance (4 + 4) / 2 = 4
  filter.estimate(measurementOf({1.0}));
  expectOutput(filter, 0, 3.0, 4.0);
  // {5, 1, 3}: median 3, mean 3, variance (4 + 4 + 0) / 3 = 8/3
  filter.estimate(measurementOf({3.0}));
  expectOutput(filter, 0, 3.0, 8.0 / 3.0);
  // {1, 3, 10}: median 3, mean 14/3, deviations -11/3, -5/3, 16/3,
  // variance (121 + 25 + 256) / 9 / 3 = 402/27
  filter.estimate(measurementOf({10.0}));
  expectOutput(filter, 0, 3.0, 402.0 / 27.0);
  // {3, 10, 2}: median 3, mean 5, variance (4 + 25 + 9) / 3 = 38/3
  filter.estimate(measurementOf({2.0}));
  expectOutput(filter, 0, 3.0, 38.0 / 3.0);
  // {10, 2, -7}: median 2, mean 5/3, deviations 25/3, 1/3, -26/3,
  // variance (625 + 1 + 676) / 9 / 3 = 1302/27
  filter.estimate(measurementOf({-7.0}));
  expectOutput(filter, 0, 2.0, 1302.0 / 27.0);
}

TEST(MovingMedian, EvenWindowAveragesTheTwoMiddleValues) {
  MovingMedian filter(1, 4);
  for (double v : {4.0, 1.0, 3.0, 2.0}) filter.estimate(measurementOf({v}));
  // {4, 1, 3, 2} sorted 1 2 3 4: median (2 + 3) / 2 = 2.5, mean 2.5,
  // variance (2.25 + 2.25 + 0.25 + 0.25) / 4 = 1.25
  expectOutput(filter, 0, 2.5, 1.25);
  filter.estimate(measurementOf({100.0}));
  // {1, 3, 2, 100} sorted 1 2 3 100: median 2.5, the outlier does not move it
  EXPECT_NEAR(filter.state()(0), 2.5, 1e-12);
  filter.estimate(measurementOf({-50.0}));
  // {3, 2, 100, -50} sorted -50 2 3 100: median 2.5
  EXPECT_NEAR(filter.state()(0), 2.5, 1e-12);
  filter.estimate(measurementOf({7.0}));
  // {2, 100, -50, 7} sorted -50 2 7 100: median 4.5
  EXPECT_NEAR(filter.state()(0), 4.5, 1e-12);
}

TEST(MovingMedian, MissingEntriesDoNotEnterTheWindow) {
  MovingMedian filter(2, 3);
  filter.estimate(measurementOf({1.0, 10.0}));
  filter.estimate(measurementOf({2.0, kMissing}));
  filter.estimate(measurementOf({3.0, kMissing}));
  // entry 0 {1, 2, 3}: 2; entry 1 {10}: 10 (placeholders for missing values would drag it)
  expectOutput(filter, 0, 2.0, 2.0 / 3.0);
  expectOutput(filter, 1, 10.0, 0.0);
  filter.estimate(measurementOf({kMissing, 20.0}));
  filter.estimate(measurementOf({kMissing, 30.0}));
  // entry 0 unchanged; entry 1 {10, 20, 30}: 20, variance (100 + 0 + 100) / 3
  expectOutput(filter, 0, 2.0, 2.0 / 3.0);
  expectOutput(filter, 1, 20.0, 200.0 / 3.0);
}

TEST(MovingMedian, NonFiniteMeasurementThrowsAndChangesNothing) {
  MovingMedian filter(2, 3);
  filter.estimate(measurementOf({1.0, 10.0}));
  Measurement<Eigen::Dynamic> withNaN = measurementOf({2.0, 5.0});
  withNaN.value(1) = std::nan("");
  EXPECT_THROW(filter.estimate(withNaN), InvalidInputError);
  expectOutput(filter, 0, 1.0, 0.0);
  expectOutput(filter, 1, 10.0, 0.0);
  // the rejected 2 did not enter: {1, 4} -> 2.5 (with 2 it would be {1, 2, 4} -> 2)
  filter.estimate(measurementOf({4.0, kMissing}));
  expectOutput(filter, 0, 2.5, 2.25);
}

TEST(MovingMedian, BadParametersThrowNamingTheParameter) {
  try {
    MovingMedian(1, 0);
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("windowSize"), std::string::npos) << e.what();
  }
  try {
    MovingMedian(0, 3);
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("inputCount"), std::string::npos) << e.what();
  }
}

TEST(MovingMedian, ResetEmptiesTheWindows) {
  MovingMedian filter(1, 3);
  filter.estimate(measurementOf({100.0}));
  filter.estimate(measurementOf({200.0}));
  filter.reset();
  expectOutput(filter, 0, 0.0, kInf);
  filter.estimate(measurementOf({4.0}));
  expectOutput(filter, 0, 4.0, 0.0);
}

TEST(MovingMedian, WorksThroughTheEstimatorInterface) {
  EstimatorAdapter<MovingMedian> adapter(MovingMedian(1, 3));
  IEstimator& estimator = adapter;
  EXPECT_EQ(estimator.description(), "MovingMedian(inputs=1, window=3)");
  Output out;
  for (double v : {7.0, -1.0, 4.0}) {
    Input in;
    in.add(InputValue(v));
    out = estimator.estimate(in);
  }
  // {7, -1, 4}: median 4, mean 10/3, variance (121 + 169 + 4) / 9 / 3 = 294/27
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].getValue(), 4.0);
  EXPECT_NEAR(out[0].getVariance(), 294.0 / 27.0, 1e-12);
  Input missing;
  missing.add(InputValue::missing());
  EXPECT_EQ(estimator.estimate(missing)[0].getValue(), 4.0);
  EXPECT_THROW(estimator.setControlInput(missing), InvalidInputError);
}

}  // namespace
