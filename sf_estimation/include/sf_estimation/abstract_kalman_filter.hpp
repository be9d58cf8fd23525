// State, covariance, noise and control shared by the Kalman filter family (thesis class
// AbstractKalmanFilter). Derived filters implement estimate() and commit its result.
#pragma once

#include <string>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <int N, int M, int L>
class AbstractKalmanFilter {
 public:
  static constexpr int StateSize = N;
  static constexpr int MeasurementSize = M;
  static constexpr int ControlSize = L;

  Index stateSize() const { return x_.size(); }
  Index measurementSize() const { return R_.rows(); }
  Index controlSize() const { return u_.size(); }

  const Vector<N>& state() const { return x_; }
  const Matrix<N, N>& covariance() const { return P_; }
  const Vector<L>& control() const { return u_; }
  const Matrix<N, N>& processNoise() const { return Q_; }
  const Matrix<M, M>& measurementNoise() const { return R_; }
  /// Which state variables and measurements are angles (wrapped to (-pi, pi]).
  const AngleMask<N>& angleStates() const { return angleStates_; }
  const AngleMask<M>& angleMeasurements() const { return angleMeasurements_; }
  /// Covariances repaired so far (numerical_repairs.hpp); reset() keeps the count.
  const NumericalRepairs& numericalRepairs() const { return repairs_; }

  void setControl(const Vector<L>& u) {
    validateControl(u, controlSize());
    u_ = u;
  }

  /// Restores the initial state and covariance; the control is kept.
  void reset() {
    x_ = x0_;
    P_ = P0_;
  }

  /// Replaces the current belief (e.g. after an external re-initialisation); angle states
  /// are wrapped, P (a covariance, requireCovariance) symmetrised.
  void setBelief(const Vector<N>& x, const Matrix<N, N>& P) {
    requireSize(method_, "x", x, stateSize(), 1);
    requireCovariance(method_, "P", P, stateSize(), false);
    x_ = x;
    angleStates_.wrap(x_);
    P_ = P;
    symmetrize(P_);  // asymmetric by at most kSymmetryTolerance: rounding, made exact
  }

  std::string description() const {
    return filterDescription(method_, stateSize(), measurementSize(), controlSize());
  }

 protected:
  AbstractKalmanFilter(std::string method, const Matrix<N, N>& Q, const Matrix<M, M>& R,
                       const Vector<N>& x0, const Matrix<N, N>& P0, Index controlSize,
                       const AngularComponents& angles)
      : method_(std::move(method)), x_(x0), x0_(x0), P_(P0), P0_(P0), Q_(Q), R_(R) {
    requireFilterParameters(method_, Q, R, x0, P0);
    requireControlSize(method_, controlSize, L);
    u_ = Vector<L>::Zero(controlSize);
    angleStates_ = AngleMask<N>(angles.states, Q.rows(), method_, "state");
    angleMeasurements_ = AngleMask<M>(angles.measurements, R.rows(), method_, "measurement");
    angleStates_.wrap(x0_);
    x_ = x0_;
  }

  /// Makes (x, P) the new belief: angle states wrapped, P symmetrised and, if it lost
  /// positive semi-definiteness, repaired (counted). A non-finite x or P is refused with
  /// NumericalError and the filter keeps its previous belief. `repairedBefore` counts a
  /// repair the step already made (the UKF's predicted covariance).
  void commit(Vector<N>& x, Matrix<N, N>& P, bool repairedBefore = false) {
    const bool repaired = settleBelief(x, P, angleStates_, method_);
    x_ = x;
    P_ = P;
    repairs_.covariance += (repaired ? 1 : 0) + (repairedBefore ? 1 : 0);
  }

  std::string method_;
  Vector<N> x_, x0_;
  Matrix<N, N> P_, P0_, Q_;
  Matrix<M, M> R_;
  Vector<L> u_;
  AngleMask<N> angleStates_;
  AngleMask<M> angleMeasurements_;
  NumericalRepairs repairs_;
};

}  // namespace estimation
