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
struct HasTransitionJacobian<Model,
                             std::void_t<decltype(std::declval<const Model&>().transitionJacobian(
                                 std::declval<const Vector<Model::StateSize>&>(),
                                 std::declval<const Vector<Model::ControlSize>&>(),
                                 std::declval<Matrix<Model::StateSize, Model::StateSize>&>()))>>
    : std::true_type {};

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

/// Copies the derivative rows of an AutoDiff result into a Jacobian, and its values into
/// `plain` when given. Entries that do not depend on x (constants, controls) may carry an
/// empty derivative vector.
template <class ADVector, class JacobianType>
void extractJacobian(const ADVector& values, Index cols, JacobianType& jacobian,
                     Vector<ADVector::RowsAtCompileTime>* plain = nullptr) {
  jacobian.resize(values.size(), cols);
  if (plain) {
    plain->resize(values.size());
    for (Index i = 0; i < values.size(); ++i) (*plain)(i) = values(i).value();
  }
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

/// A = df/dx at (x, u), and f(x, u) in `next` when it is given. Without the model's own
/// Jacobian both come from one pass of automatic differentiation: AutoDiffScalar computes each
/// value by the same double operations as the plain evaluation, so `next` is that evaluation's
/// bit for bit, and the EKF need not run the model a second time.
template <class Model>
void transitionJacobian(const Model& model, const Vector<Model::StateSize>& x,
                        const Vector<Model::ControlSize>& u,
                        Matrix<Model::StateSize, Model::StateSize>& A,
                        Vector<Model::StateSize>* next = nullptr) {
  if constexpr (detail::HasTransitionJacobian<Model>::value) {
    model.transitionJacobian(x, u, A);
    if (next) model.transition(x, u, *next);
  } else {
    constexpr int N = Model::StateSize;
    using ADScalar = Eigen::AutoDiffScalar<Vector<N>>;
    Eigen::Matrix<ADScalar, N, 1> xa, out;
    detail::seedDerivatives(x, xa);
    out.resize(x.size());
    model.transition(xa, u, out);
    detail::extractJacobian(out, x.size(), A, next);
  }
}

/// H = dh/dx at x, and h(x) in `expected` when it is given (as transitionJacobian).
template <class Model>
void observationJacobian(const Model& model, const Vector<Model::StateSize>& x,
                         Matrix<Model::MeasurementSize, Model::StateSize>& H,
                         Vector<Model::MeasurementSize>* expected = nullptr) {
  if constexpr (detail::HasObservationJacobian<Model>::value) {
    model.observationJacobian(x, H);
    if (expected) model.observation(x, *expected);
  } else {
    constexpr int N = Model::StateSize;
    constexpr int M = Model::MeasurementSize;
    using ADScalar = Eigen::AutoDiffScalar<Vector<N>>;
    Eigen::Matrix<ADScalar, N, 1> xa;
    Eigen::Matrix<ADScalar, M, 1> z;
    detail::seedDerivatives(x, xa);
    z.resize(model.measurementSize());
    model.observation(xa, z);
    detail::extractJacobian(z, x.size(), H, expected);
  }
}

}  // namespace estimation

// Explicit instantiation (PREFIX empty) or its declaration (PREFIX extern) of a model's two
// Jacobians, at global scope: a node compiles them once, in a unit of its own
// (doc/build_cost.md, "The Jacobians' unit").
#define SF_ESTIMATION_MODEL_JACOBIANS(PREFIX, MODEL)                 \
  PREFIX template void estimation::transitionJacobian<MODEL>(        \
      const MODEL&, const estimation::Vector<MODEL::StateSize>&,     \
      const estimation::Vector<MODEL::ControlSize>&,                 \
      estimation::Matrix<MODEL::StateSize, MODEL::StateSize>&,       \
      estimation::Vector<MODEL::StateSize>*);                        \
  PREFIX template void estimation::observationJacobian<MODEL>(       \
      const MODEL&, const estimation::Vector<MODEL::StateSize>&,     \
      estimation::Matrix<MODEL::MeasurementSize, MODEL::StateSize>&, \
      estimation::Vector<MODEL::MeasurementSize>*);
