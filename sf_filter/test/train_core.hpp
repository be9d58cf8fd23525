// The fusion-core test fixture: the moving train (thesis 2.2.1) with one control,
// v' = v + a T + u, a' = a, sensors v (input 0, R = 0.5) and a (input 1, R = 0.2), as a
// Kalman filter, and a collector of the core's estimates.
#pragma once

#include <vector>

#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/fusion_core.hpp"

namespace train_core {

using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

using Train = estimation::KalmanFilter<2, 2, 1>;
using Core = sf_filter::FusionCore<Train>;
constexpr double kPeriod = 0.1;

inline Train makeTrain() {
  Matrix<2, 2> A;
  A << 1, kPeriod, 0, 1;
  Matrix<2, 1> B(1, 0);
  const Matrix<2, 2> H = Matrix<2, 2>::Identity();
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.01;
  Matrix<2, 2> R;
  R << 0.5, 0, 0, 0.2;
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

}  // namespace train_core
