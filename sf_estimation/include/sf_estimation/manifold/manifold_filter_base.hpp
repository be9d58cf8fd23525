// Belief, noise and checks shared by the filters on a state layout (manifold EKF, UKF-M).
//
// The model of those filters (fixed sizes only; S = double or an AutoDiffScalar):
//
//   struct MyModel {
//     using StateSpace = manifold::StateLayout<manifold::So2Block, manifold::VectorBlock<2>>;
//     using MeasurementSpace = manifold::FlatLayout<2>;   // or angles / quaternions
//     static constexpr int NoiseSize = 3, ControlSize = 2;
//     template <class S>   // next = f(x, u, w); w ~ N(0, Q) of NoiseSize entries
//     void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<2>& u,
//                     const Eigen::Matrix<S, 3, 1>& w, Eigen::Matrix<S, 3, 1>& next) const;
//     template <class S>   // the measurement without noise; z = h(x) [+] v, v ~ N(0, R)
//     void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const;
//   };
//
// Vectors are stored (StoredSize numbers, a quaternion as w, x, y, z), covariances are over the
// tangent space (TangentSize). The process noise enters through f itself, as in UKF-M, so that
// a noise defined in the body frame (odometry, a gyro) needs no hand-made mapping; additive
// noise is the special case next = f(x, u) [+] w. A measurement innovation is z [-] h(x): angles
// and quaternions are compared on their manifold, never by subtraction.
#pragma once

#include <cmath>
#include <string>
#include <utility>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/numerical_repairs.hpp"
#include "sf_estimation/parameter_checks.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace manifold {

template <class Model>
class ManifoldFilterBase {
 public:
  using StateSpace = typename Model::StateSpace;
  using MeasurementSpace = typename Model::MeasurementSpace;
  static constexpr int StoredSize = StateSpace::StoredSize;
  static constexpr int TangentSize = StateSpace::TangentSize;
  static constexpr int NoiseSize = Model::NoiseSize;
  static constexpr int ControlSize = Model::ControlSize;
  static constexpr int MeasurementStoredSize = MeasurementSpace::StoredSize;
  static constexpr int MeasurementTangentSize = MeasurementSpace::TangentSize;
  static_assert(NoiseSize > 0 && ControlSize >= 0, "a manifold filter needs fixed sizes");

  using State = Vector<StoredSize>;
  using Covariance = Matrix<TangentSize, TangentSize>;
  using Control = Vector<ControlSize>;
  using MeasurementValue = Vector<MeasurementStoredSize>;
  using ProcessNoise = Matrix<NoiseSize, NoiseSize>;
  using MeasurementNoise = Matrix<MeasurementTangentSize, MeasurementTangentSize>;

  const State& state() const { return x_; }
  /// Covariance of the tangent-space error: the true state is state() [+] e, e ~ N(0, P).
  const Covariance& covariance() const { return P_; }
  const ProcessNoise& processNoise() const { return Q_; }
  const MeasurementNoise& measurementNoise() const { return R_; }
  const Model& model() const { return model_; }
  Model& model() { return model_; }
  const NumericalRepairs& numericalRepairs() const { return repairs_; }

  /// Replaces the belief; x is normalised (angles wrapped, quaternions unit). Throws
  /// ParameterError for a non-finite x or a P that is not a covariance; the belief is then kept.
  void setBelief(const State& x, const Covariance& P) {
    requireSize(method_, "x", x, StoredSize, 1);
    requireCovariance(method_, "P", P, TangentSize, false);
    x_ = x;
    StateSpace::normalise(x_);
    P_ = P;
  }

  /// Replaces Q (for a step length that changes, or a sensor whose noise does). Throws
  /// ParameterError for a Q that is not a covariance; Q is then kept.
  void setProcessNoise(const ProcessNoise& Q) {
    requireCovariance(method_, "Q", Q, NoiseSize, false);
    Q_ = Q;
  }

  /// Replaces R (e.g. inflated for one measurement that is less trustworthy). Throws
  /// ParameterError for an R that is not a positive definite covariance; R is then kept.
  void setMeasurementNoise(const MeasurementNoise& R) {
    requireCovariance(method_, "R", R, MeasurementTangentSize, true);
    R_ = R;
  }

 protected:
  ManifoldFilterBase(std::string method, Model model, const ProcessNoise& Q,
                     const MeasurementNoise& R, const State& x0, const Covariance& P0)
      : method_(std::move(method)), model_(std::move(model)), Q_(Q), R_(R) {
    requireCovariance(method_, "Q", Q, NoiseSize, false);
    requireCovariance(method_, "R", R, MeasurementTangentSize, true);
    setBelief(x0, P0);
  }

  /// Throws InvalidInputError for a non-finite control or measurement entry.
  static void checkControl(const Control& u) { validateControl(u, ControlSize); }
  static void checkMeasurement(const MeasurementValue& z) {
    for (Index i = 0; i < z.size(); ++i) {
      if (!std::isfinite(z(i))) estimation::detail::refuseNonFiniteInput("measurement", i, z(i));
    }
  }

  /// Makes (x, P) the belief: P symmetrised and repaired if it lost positive
  /// semi-definiteness (counted), x normalised. A non-finite result is refused with
  /// NumericalError and the previous belief is kept.
  void commit(State& x, Covariance& P) {
    symmetrize(P);
    if (!x.allFinite() || !P.allFinite()) rejectStep(method_, "the estimate became non-finite");
    const bool repaired = repairCovariance(P);
    if (!P.allFinite()) rejectStep(method_, "the covariance repair failed");
    StateSpace::normalise(x);
    x_ = x;
    P_ = P;
    repairs_.covariance += repaired ? 1 : 0;
  }

  std::string method_;
  Model model_;
  ProcessNoise Q_;
  MeasurementNoise R_;
  State x_;
  Covariance P_;
  NumericalRepairs repairs_;
};

}  // namespace manifold
}  // namespace estimation
