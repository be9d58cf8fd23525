// Models shared by the tests of the filters on a state layout (test_manifold_filters.cpp) and
// of their smoother (test_manifold_rts_smoother.cpp): a flat linear model, a heading on SO(2)
// and an attitude on SO(3) with a gyro bias.
#pragma once

#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/types.hpp"

namespace manifold_test {

namespace mf = estimation::manifold;
using estimation::Matrix;
using estimation::Vector;

// x' = A x + B u + G w, z = H x (position, velocity, acceleration; noise on the last two).
struct LinearModel {
  using StateSpace = mf::FlatLayout<3>;
  using MeasurementSpace = mf::FlatLayout<2>;
  static constexpr int NoiseSize = 2, ControlSize = 1;
  Matrix<3, 3> A;
  Matrix<3, 1> B;
  Matrix<3, 2> G;
  Matrix<2, 3> H;
  LinearModel() {
    A << 1.0, 0.1, 0.005, 0.0, 1.0, 0.1, 0.0, 0.0, 0.9;
    B << 0.0, 0.0, 0.1;
    G << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0;
    H << 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  }
  template <class S>
  void transition(const Eigen::Matrix<S, 3, 1>& x, const Vector<1>& u,
                  const Eigen::Matrix<S, 2, 1>& w, Eigen::Matrix<S, 3, 1>& next) const {
    next = A.cast<S>() * x + (B * u).cast<S>() + G.cast<S>() * w;
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 3, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z = H.cast<S>() * x;
  }
};

// A heading driven by a rate, measured directly (a compass).
struct HeadingModel {
  using StateSpace = mf::StateLayout<mf::So2Block>;
  using MeasurementSpace = mf::StateLayout<mf::So2Block>;
  static constexpr int NoiseSize = 1, ControlSize = 1;
  template <class S>
  void transition(const Eigen::Matrix<S, 1, 1>& x, const Vector<1>& u,
                  const Eigen::Matrix<S, 1, 1>& w, Eigen::Matrix<S, 1, 1>& next) const {
    next(0) = mf::so2Plus<S>(x(0), S(u(0)) + w(0));
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 1, 1>& x, Eigen::Matrix<S, 1, 1>& z) const {
    z = x;
  }
};

// An attitude driven by a gyro (body rates, noise w) with a gyro bias; measured as a quaternion.
struct AttitudeModel {
  using StateSpace = mf::StateLayout<mf::So3Block, mf::VectorBlock<3>>;
  using MeasurementSpace = mf::StateLayout<mf::So3Block>;
  static constexpr int NoiseSize = 3, ControlSize = 3;
  double dt = 0.1;
  template <class S>
  void transition(const Eigen::Matrix<S, 7, 1>& x, const Vector<3>& u,
                  const Eigen::Matrix<S, 3, 1>& w, Eigen::Matrix<S, 7, 1>& next) const {
    const mf::Vector3<S> rate = u.cast<S>() - x.template tail<3>() + w;
    const mf::Vector3<S> phi = rate * S(dt);
    mf::storeQuaternion(mf::so3Plus<S>(mf::storedQuaternion(x.template head<4>()), phi), next);
    next.template tail<3>() = x.template tail<3>();
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 7, 1>& x, Eigen::Matrix<S, 4, 1>& z) const {
    z = x.template head<4>();
  }
};

}  // namespace manifold_test
