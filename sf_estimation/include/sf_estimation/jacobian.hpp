// Jacobians of a model: the model's own when it provides them, otherwise exact forward-mode
// automatic differentiation of the same templated model code (Eigen's AutoDiffScalar), so
// a model written once serves EKF, UKF and PF without hand-derived derivatives.
#pragma once

#include <type_traits>
#include <utility>

#include <unsupported/Eigen/AutoDiff>

#include "sf_estimation/model.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

namespace detail {

template <class Model, class = void>
struct HasTransitionJacobian : std::false_type {};
template <class Model>
struct HasTransitionJacobian<
    Model, std::void_t<decltype(std::declval<const Model&>().transitionJacobian(
               std::declval<const Vector<Model::StateSize>&>(),
               std::declval<const Vector<Model::ControlSize>&>(),
               std::declval<Matrix<Model::StateSize, Model::StateSize>&>()))>> : std::true_type {};

template <class Model, class = void>
struct HasObservationJacobian : std::false_type {};
template <class Model>
struct HasObservationJacobian<
    Model, std::void_t<decltype(std::declval<const Model&>().observationJacobian(
               std::declval<const Vector<Model::StateSize>&>(),
               std::declval<Matrix<Model::MeasurementSize, Model::StateSize>&>()))>>
    : std::true_type {};

/// Seeds an AutoDiff vector with x and the unit derivative directions. Entries are written in
/// place: assigning a temporary AutoDiffScalar costs a store-forwarding stall per entry.
template <class ADVector>
void seedDerivatives(const Vector<ADVector::RowsAtCompileTime>& x, ADVector& seeded) {
  using Derivatives = typename ADVector::Scalar::DerType;
  const Index n = x.size();
  seeded.resize(n);
  for (Index i = 0; i < n; ++i) {
    seeded(i).value() = x(i);
    seeded(i).derivatives() = Derivatives::Unit(n, i);
  }
}

/// Copies the derivative rows of an AutoDiff result into a Jacobian. Entries that do not
/// depend on x (constants, controls) may carry an empty derivative vector.
template <class ADVector, class JacobianType>
void extractJacobian(const ADVector& values, Index cols, JacobianType& jacobian) {
  jacobian.resize(values.size(), cols);
  for (Index i = 0; i < values.size(); ++i) {
    const auto& d = values(i).derivatives();
    if (d.size() == cols) {
      jacobian.row(i) = d.transpose();
    } else {
      jacobian.row(i).setZero();
    }
  }
}

}  // namespace detail

/// A = df/dx at (x, u).
template <class Model>
void transitionJacobian(const Model& model, const Vector<Model::StateSize>& x,
                        const Vector<Model::ControlSize>& u,
                        Matrix<Model::StateSize, Model::StateSize>& A) {
  if constexpr (detail::HasTransitionJacobian<Model>::value) {
    model.transitionJacobian(x, u, A);
  } else {
    constexpr int N = Model::StateSize;
    using ADScalar = Eigen::AutoDiffScalar<Vector<N>>;
    Eigen::Matrix<ADScalar, N, 1> xa, next;
    detail::seedDerivatives(x, xa);
    next.resize(x.size());
    model.transition(xa, u, next);
    detail::extractJacobian(next, x.size(), A);
  }
}

/// H = dh/dx at x.
template <class Model>
void observationJacobian(const Model& model, const Vector<Model::StateSize>& x,
                         Matrix<Model::MeasurementSize, Model::StateSize>& H) {
  if constexpr (detail::HasObservationJacobian<Model>::value) {
    model.observationJacobian(x, H);
  } else {
    constexpr int N = Model::StateSize;
    constexpr int M = Model::MeasurementSize;
    using ADScalar = Eigen::AutoDiffScalar<Vector<N>>;
    Eigen::Matrix<ADScalar, N, 1> xa;
    Eigen::Matrix<ADScalar, M, 1> z;
    detail::seedDerivatives(x, xa);
    z.resize(model.measurementSize());
    model.observation(xa, z);
    detail::extractJacobian(z, x.size(), H);
  }
}

}  // namespace estimation
