// The interface of the flat Kalman filters (abstract_kalman_filter.hpp: stored-size state,
// N x N covariance, control, angle measurements) on a manifold filter whose model is an
// AdditiveNoiseModel, so that the node's fusion core, written for the flat filters, runs it
// unchanged. Covariances cross the interface in LayoutEmbedding's form: Q, P0, setBelief's P
// and covariance() are N x N with the tangent rows on the stored entries (a quaternion's x, y,
// z rows in rad^2, its w row zero). Angle states are the layout's So2Blocks; the run-time
// angle measurements are wrapped as in the flat filters. R is M x M over the stored
// measurement; a measured quaternion's w row and column must be zero (measurement_rows.hpp).
#pragma once

#include <string>
#include <type_traits>
#include <utility>

#include "sf_estimation/angles.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/manifold/layout_embedding.hpp"
#include "sf_estimation/manifold/measurement_rows.hpp"
#include "sf_estimation/measurement.hpp"
#include "sf_estimation/parameter_checks.hpp"

namespace estimation {
namespace manifold {

template <class ManifoldFilter>
class FlatInterface : public ManifoldFilter {
  using Base = ManifoldFilter;
  using Embedding = LayoutEmbedding<typename Base::StateSpace>;
  using Rows = MeasurementRows<
      typename std::decay_t<decltype(std::declval<const Base&>().model())>::MeasurementLayout>;

 public:
  static constexpr int StateSize = Base::StoredSize;
  static constexpr int MeasurementSize = Base::MeasurementStoredSize;
  static constexpr int ControlSize = Base::ControlSize;
  static constexpr int TangentSize = Base::TangentSize;
  using StoredMatrix = Matrix<StateSize, StateSize>;

  Index stateSize() const { return StateSize; }
  Index measurementSize() const { return MeasurementSize; }
  Index controlSize() const { return ControlSize; }

  /// The tangent covariance in the stored form (see the top of the file).
  StoredMatrix covariance() const { return Embedding::toStored(this->P_); }
  StoredMatrix processNoise() const { return Embedding::toStored(this->Q_); }
  const Vector<ControlSize>& control() const { return u_; }
  const AngleMask<MeasurementSize>& angleMeasurements() const { return angleMeasurements_; }

  void setControl(const Vector<ControlSize>& u) {
    validateControl(u, ControlSize);
    u_ = u;
  }

  /// Replaces the belief; P in the stored form. Throws ParameterError (belief kept) for a P that
  /// is not a covariance or has entries off the tangent rows, or an x with a zero quaternion.
  void setBelief(const Vector<StateSize>& x, const StoredMatrix& P) {
    const typename Base::State before = this->x_;
    Base::setBelief(x, tangentOf("P", P));
    if (!this->x_.allFinite()) {
      this->x_ = before;
      throw ParameterError(this->method_ + ": x has a quaternion of zero norm");
    }
  }

  /// Restores the initial state and covariance; the control is kept.
  void reset() { Base::setBelief(x0_, P0_); }

  std::string description() const {
    return filterDescription(this->method_, StateSize, MeasurementSize, ControlSize);
  }

 protected:
  template <class Model, class... Own>
  FlatInterface(const AngularComponents& angles, Model model, const StoredMatrix& Q,
                const typename Base::MeasurementNoise& R, const Vector<StateSize>& x0,
                const StoredMatrix& P0, Own&&... own)
      : Base(std::move(model), tangentOf("Q", Q), Rows::storedNoise("R", R), x0,
             tangentOf("P0", P0), std::forward<Own>(own)...),
        x0_(this->x_),
        P0_(this->P_),
        u_(Vector<ControlSize>::Zero()),
        angleMeasurements_(angles.measurements, MeasurementSize, this->method_, "measurement") {
    if (!x0_.allFinite())
      throw ParameterError(this->method_ + ": x0 has a quaternion of zero norm");
  }

  /// The tangent rows of a stored-form matrix; ParameterError if it has others.
  static typename Base::Covariance tangentOf(const char* name, const StoredMatrix& P) {
    const typename Base::Covariance tangent = Embedding::toTangent(P);
    if (P.allFinite() && Embedding::toStored(tangent) != P) {  // else the base refuses it
      throw ParameterError(std::string(name) +
                           ": a quaternion's w row and column must be zero (the covariance is "
                           "over the tangent space, three rows per quaternion)");
    }
    return tangent;
  }

  typename Base::State x0_;
  typename Base::Covariance P0_;
  Vector<ControlSize> u_;
  AngleMask<MeasurementSize> angleMeasurements_;
};

}  // namespace manifold
}  // namespace estimation
