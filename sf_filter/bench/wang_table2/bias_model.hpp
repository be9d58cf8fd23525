// Wang et al.'s kinematic model (eqs. 2 and 4, after Bevly) as the linear Kalman filter of
// sf_estimation, sampled at the encoder period Delta:
//
//   state x = [position, bias b_x],  control = the encoder rate v',  measurement = position
//   position(k+1) = position(k) + Delta (v'(k) - b_x(k))       (eq. 2, Euler)
//   b_x(k+1)      = (1 - Delta / T) b_x(k)                     (eq. 4, Euler)
//   A = [1, -Delta; 0, 1 - Delta / T],  B = [Delta; 0],  H = [1, 0]
//
// Q of the footnotes is read as a spectral density (Q_d = Q Delta): taken per 1 ms step, Q =
// diag(0.5, 0.1) would make every filter trust each vision sample almost fully, and the
// Kalman filter's error could not fall below the vision noise, while Table II's is 0.084 m
// at sigma_u = 0.202 m.
#pragma once

#include <sf_estimation/kalman_filter.hpp>

#include "parameters.hpp"

namespace wang_table2 {

using BiasFilter = estimation::KalmanFilter<2, 1, 1>;

/// The filter of footnotes 2-4 with measurement variance `r`, starting at `position` with a
/// bias estimate of zero.
inline BiasFilter makeBiasFilter(const Parameters& parameters, double r, double position) {
  const double dt = parameters.encoderPeriod;
  estimation::Matrix<2, 2> A;
  A << 1.0, -dt, 0.0, 1.0 - dt / parameters.biasTimeConstant;
  const estimation::Matrix<2, 1> B(dt, 0.0);
  estimation::Matrix<1, 2> H;
  H << 1.0, 0.0;
  estimation::Matrix<2, 2> Q = estimation::Matrix<2, 2>::Zero();
  Q(0, 0) = parameters.positionNoiseDensity * dt;
  Q(1, 1) = parameters.biasNoiseDensity * dt;
  estimation::Matrix<1, 1> R;
  R << r;
  const estimation::Matrix<2, 2> P0 =
      estimation::Matrix<2, 2>::Identity() * parameters.initialVariance;
  return BiasFilter(A, B, H, Q, R, estimation::Vector<2>(position, 0.0), P0);
}

}  // namespace wang_table2
