// A flat filter's model (the configuration header's: next = f(x, u), z = h(x) over the stored
// entries) as a model of the manifold filters (manifold_filter_base.hpp): the process noise is
// a tangent vector added by the layout's retraction, next = f(x, u) [+] w, so that Q is over
// the tangent space (a quaternion's three rows in rad^2) and f's quaternion is renormalised.
// The measurement is the flat vector of the model's inputs; MeasurementLayout says which of its
// rows the layout filters compare on a manifold (measurement_rows.hpp), flat by default.
#pragma once

#include <utility>

#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {
namespace manifold {

template <class FlatModel, class Layout,
          class MeasurementLayout_ = FlatLayout<FlatModel::MeasurementSize>>
struct AdditiveNoiseModel {
  static_assert(FlatModel::StateSize == Layout::StoredSize,
                "AdditiveNoiseModel: the layout must store exactly the model's state");
  using StateSpace = Layout;
  using MeasurementSpace = FlatLayout<FlatModel::MeasurementSize>;
  using MeasurementLayout = MeasurementLayout_;
  static_assert(MeasurementLayout::StoredSize == FlatModel::MeasurementSize,
                "AdditiveNoiseModel: the measurement layout must store exactly the model's z");
  static constexpr int NoiseSize = Layout::TangentSize;
  static constexpr int ControlSize = FlatModel::ControlSize;
  static constexpr int N = Layout::StoredSize, D = Layout::TangentSize;

  FlatModel flat;

  template <class S>
  void transition(const Eigen::Matrix<S, N, 1>& x, const Vector<ControlSize>& u,
                  const Eigen::Matrix<S, D, 1>& w, Eigen::Matrix<S, N, 1>& next) const {
    Eigen::Matrix<S, N, 1> f;
    flat.transition(x, u, f);
    next = Layout::template plus<S>(f, w);
  }

  template <class S>
  void observation(const Eigen::Matrix<S, N, 1>& x,
                   Eigen::Matrix<S, FlatModel::MeasurementSize, 1>& z) const {
    flat.observation(x, z);
  }
};

}  // namespace manifold
}  // namespace estimation
