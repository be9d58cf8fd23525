// The fusion-core test fixture: the moving train (thesis 2.2.1) with one control,
// v' = v + a T + u, a' = a, sensors v (input 0, R = 0.5) and a (input 1, R = 0.2), as a
// Kalman filter, and a collector of the core's estimates.
#pragma once

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/fusion_core.hpp"

namespace train_core {

using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

using Train = estimation::KalmanFilter<2, 2, 1>;
using Core = sf_filter::FusionCore<Train>;
constexpr double kPeriod = 0.1;

/// R of the train's sensors: speed 0.5, acceleration 0.2.
inline Matrix<2, 2> trainR() {
  Matrix<2, 2> R;
  R << 0.5, 0, 0, 0.2;
  return R;
}

/// The train with measurement noise R (default trainR()).
inline Train makeTrain(const Matrix<2, 2>& R = trainR()) {
  Matrix<2, 2> A;
  A << 1, kPeriod, 0, 1;
  Matrix<2, 1> B(1, 0);
  const Matrix<2, 2> H = Matrix<2, 2>::Identity();
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.01;
  return Train(A, B, H, Q, R, Vector<2>(0, 0), Matrix<2, 2>::Identity());
}

inline Core makeCore() {
  Core::Options options;
  options.period = kPeriod;
  return Core(makeTrain(), options);
}

struct Collector {
  std::vector<Core::Estimate> estimates;
  void operator()(const Core::Estimate& e) { estimates.push_back(e); }
};

/// A measurement with only the speed (input 0), with its own variance unless NaN.
inline Measurement<2> speedOnly(double v, double variance = NAN) {
  Measurement<2> z;
  z.value << v, 0.0;
  z.available << true, false;
  z.varianceGiven << !std::isnan(variance), false;
  z.variance << (std::isnan(variance) ? 0.0 : variance), 0.0;
  return z;
}

/// A measurement with the speed (input 0) and the acceleration (input 1).
inline Measurement<2> speedAndAcceleration(double v, double a) {
  Measurement<2> z;
  z.value << v, a;
  z.available << true, true;
  return z;
}

/// A measurement with only the acceleration (input 1).
inline Measurement<2> accelerationOnly(double a) {
  Measurement<2> z;
  z.value << 0.0, a;
  z.available << false, true;
  return z;
}

/// The core's estimate equals the reference filter's belief.
inline void expectSameBelief(const Core::Estimate& e, const Train& reference) {
  EXPECT_TRUE(e.state.isApprox(reference.state(), 1e-13))
      << e.state.transpose() << " vs " << reference.state().transpose();
  EXPECT_TRUE(e.covariance.isApprox(reference.covariance(), 1e-13));
}

}  // namespace train_core
