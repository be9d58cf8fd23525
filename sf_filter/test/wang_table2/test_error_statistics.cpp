// Tests of the Table II statistics (sf_filter/bench/wang_table2/error_statistics.hpp) against
// values computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "wang_table2/error_statistics.hpp"

namespace {

using wang_table2::ErrorSeries;
using wang_table2::PairedChange;
using wang_table2::RunAverage;

TEST(ErrorSeries, VarianceAndRmsByHand) {
  // e = 1, 2, 3, 4: mean 2.5, variance (2.25 + 0.25 + 0.25 + 2.25) / 4 = 1.25,
  // rms sqrt((1 + 4 + 9 + 16) / 4) = sqrt(7.5).
  ErrorSeries e;
  for (double x : {1.0, 2.0, 3.0, 4.0}) e.add(x);
  EXPECT_EQ(e.count(), 4u);
  EXPECT_DOUBLE_EQ(e.mean(), 2.5);
  EXPECT_DOUBLE_EQ(e.variance(), 1.25);
  EXPECT_DOUBLE_EQ(e.rms(), std::sqrt(7.5));
}

TEST(ErrorSeries, VarianceIsAboutTheMeanAndRmsIsNot) {
  // A constant error: no variance, rms = |error| (a biased estimate shows in the rms only).
  ErrorSeries e;
  for (int k = 0; k < 10; ++k) e.add(-0.3);
  EXPECT_NEAR(e.variance(), 0.0, 1e-18);
  EXPECT_DOUBLE_EQ(e.rms(), 0.3);
}

TEST(ErrorSeries, VarianceStaysExactFarFromZero) {
  // 1e8 + {1, 2, 3, 4}: the naive E[e^2] - E[e]^2 loses every digit here.
  ErrorSeries e;
  for (double x : {1.0, 2.0, 3.0, 4.0}) e.add(1e8 + x);
  EXPECT_NEAR(e.variance(), 1.25, 1e-6);
}

TEST(ErrorSeries, EmptyGivesZero) {
  const ErrorSeries e;
  EXPECT_EQ(e.variance(), 0.0);
  EXPECT_EQ(e.rms(), 0.0);
}

TEST(RunAverage, MeanAndStandardErrorByHand) {
  // 1, 2, 3, 4: sample variance 5 / 3, standard error sqrt(5 / 3) / sqrt(4).
  RunAverage a;
  for (double x : {1.0, 2.0, 3.0, 4.0}) a.add(x);
  EXPECT_EQ(a.runs(), 4u);
  EXPECT_DOUBLE_EQ(a.mean(), 2.5);
  EXPECT_NEAR(a.standardError(), std::sqrt(5.0 / 3.0) / 2.0, 1e-15);
}

TEST(RunAverage, OneRunHasNoStandardError) {
  RunAverage a;
  a.add(1.0);
  EXPECT_THROW(a.standardError(), std::logic_error);
}

TEST(PairedChange, RelativeChangeAndStandardErrorByHand) {
  // a = 1, 2, 3; b = 2, 2, 5: differences 1, 0, 2 (mean 1, sample std 1); mean a = 2.
  // change 1 / 2 = 50 %, standard error (1 / sqrt(3)) / 2.
  PairedChange c;
  c.add(1.0, 2.0);
  c.add(2.0, 2.0);
  c.add(3.0, 5.0);
  EXPECT_EQ(c.runs(), 3u);
  EXPECT_DOUBLE_EQ(c.relative(), 0.5);
  EXPECT_NEAR(c.standardError(), 1.0 / std::sqrt(3.0) / 2.0, 1e-15);
}

TEST(PairedChange, ProportionalFiguresGiveTheirRatio) {
  // b = 0.8 a on every run: the change is -20 % with no spread, however much a varies.
  PairedChange c;
  for (double a : {1.0, 5.0, 0.2, 3.0}) c.add(a, 0.8 * a);
  EXPECT_NEAR(c.relative(), -0.2, 1e-15);
  // The per-run differences (-0.2 a) vary, so the standard error is not zero; it is their
  // sample std / sqrt(4) / mean a = 0.2 * std(a) / 2 / mean(a), std(a) the sample std of a.
  const double meanA = 9.2 / 4.0;
  double ss = 0.0;
  for (double a : {1.0, 5.0, 0.2, 3.0}) ss += (a - meanA) * (a - meanA);
  EXPECT_NEAR(c.standardError(), 0.2 * std::sqrt(ss / 3.0) / 2.0 / meanA, 1e-15);
}

}  // namespace
