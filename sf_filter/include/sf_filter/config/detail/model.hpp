// Generated state-space model (KF: LinearModel; EKF/UKF/PF: Model) with the compile-time checks
// of the x[i] / u[i] indices used in the expressions. See configuration.hpp for the API.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <boost/preprocessor/control/if.hpp>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/support.hpp"

// clang-format off

// --- index checks on the stringized expressions -------------------------------------------------
// KIND is TRANSITION (u allowed) or OBSERVATION (no u).
#define SF_CFG_EXPR_CHECKS(NAME, KIND, WHERE, e)                                                   \
  static_assert(::sf_config::detail::maxIndexUsed(SF_PP_STR(e), 'x') < kStateSize,                 \
                NAME ": " WHERE " '" SF_PP_STR(e) "' uses x[i] with i >= " SF_PP_STR(SF_CFG_N)     \
                ", but the state has only the variables x[0] .. x["                                \
                SF_PP_STR(BOOST_PP_DEC(SF_CFG_N)) "] (" SF_CFG_N_WHY ")");                         \
  BOOST_PP_CAT(SF_CFG_U_CHECK_, KIND)(NAME, WHERE, e)

#if defined(TOPICS_IN_CTRL)
#define SF_CFG_U_CHECK_TRANSITION(NAME, WHERE, e)                                                  \
  static_assert(::sf_config::detail::maxIndexUsed(SF_PP_STR(e), 'u') < kControlSize,               \
                NAME ": " WHERE " '" SF_PP_STR(e) "' uses u[i] with i >= " SF_PP_STR(SF_CFG_L)     \
                ", but TOPICS_IN_CTRL declares only the control inputs u[0] .. u["                 \
                SF_PP_STR(BOOST_PP_DEC(SF_CFG_L)) "] (" SF_CFG_L_WHY ")");
#else
#define SF_CFG_U_CHECK_TRANSITION(NAME, WHERE, e)                                                  \
  static_assert(!::sf_config::detail::usesIdentifier(SF_PP_STR(e), 'u'),                           \
                NAME ": " WHERE " '" SF_PP_STR(e) "' uses the control input u, but "               \
                "TOPICS_IN_CTRL is not defined; declare one ((topic)(type)(field)) entry of "      \
                "TOPICS_IN_CTRL per control input u[i]");
#endif
#define SF_CFG_U_CHECK_OBSERVATION(NAME, WHERE, e)                                                 \
  static_assert(!::sf_config::detail::usesIdentifier(SF_PP_STR(e), 'u'),                           \
                NAME ": " WHERE " '" SF_PP_STR(e) "' uses the control input u, but control "       \
                "inputs are not available in the observation model");

/// Checks of every expression of a model sequence.
#define SF_CFG_CHECK_EXPRESSIONS(NAME, KIND, seq)                                                  \
  BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_CHECK_EXPRESSION, (NAME, KIND), seq)
#define SF_CFG_CHECK_EXPRESSION(r, data, i, e)                                                     \
  SF_CFG_EXPR_CHECKS(BOOST_PP_TUPLE_ELEM(2, 0, data), BOOST_PP_TUPLE_ELEM(2, 1, data),             \
                     "expression " SF_PP_STR(i), e)

/// Checks of every entry of a Jacobian matrix.
#define SF_CFG_CHECK_MATRIX_EXPRESSIONS(NAME, KIND, m)                                             \
  BOOST_PP_REPEAT(BOOST_PP_SEQ_SIZE(m), SF_CFG_CHECK_MATRIX_ROW, (NAME, KIND, m))
#define SF_CFG_CHECK_MATRIX_ROW(z, i, data)                                                        \
  BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_CHECK_MATRIX_ENTRY,                                               \
                          (BOOST_PP_TUPLE_ELEM(3, 0, data), BOOST_PP_TUPLE_ELEM(3, 1, data), i),   \
                          BOOST_PP_SEQ_ELEM(i, BOOST_PP_TUPLE_ELEM(3, 2, data)))
#define SF_CFG_CHECK_MATRIX_ENTRY(r, data, j, e)                                                   \
  SF_CFG_EXPR_CHECKS(BOOST_PP_TUPLE_ELEM(3, 0, data), BOOST_PP_TUPLE_ELEM(3, 1, data),             \
                     "entry (" SF_PP_STR(BOOST_PP_TUPLE_ELEM(3, 2, data)) ", " SF_PP_STR(j) ")", e)

// clang-format on

namespace sf_config {

/// What every model of the header has: its sizes and the estimation period T.
struct ModelBase {
  static constexpr int StateSize = kStateSize;
  static constexpr int MeasurementSize = kMeasurementSize;
  static constexpr int ControlSize = kControlSize;

  /// Estimation period in seconds; the expressions and matrix entries refer to it as T.
  double T = kEstimationPeriodMs / 1000.0;

  Eigen::Index stateSize() const { return StateSize; }
  Eigen::Index measurementSize() const { return MeasurementSize; }
  Eigen::Index controlSize() const { return ControlSize; }
};

// -------------------------------------------------------------------- EKF / UKF / PF: Model
#if SF_CFG_IS_MODEL_BASED

namespace checks {
SF_CFG_CHECK_EXPRESSIONS("STATE_TRANSITION_MODEL", TRANSITION, STATE_TRANSITION_MODEL)
#if SF_CFG_HAS_OBSERVATION_MODEL
SF_CFG_CHECK_EXPRESSIONS("OBSERVATION_MODEL", OBSERVATION, OBSERVATION_MODEL)
#endif
#if SF_CFG_HAS_STATE_TRANSITION_JACOBIAN
SF_CFG_CHECK_MATRIX_EXPRESSIONS("STATE_TRANSITION_JACOBIAN", TRANSITION, STATE_TRANSITION_JACOBIAN)
#endif
#if SF_CFG_HAS_OBSERVATION_JACOBIAN
SF_CFG_CHECK_MATRIX_EXPRESSIONS("OBSERVATION_JACOBIAN", OBSERVATION, OBSERVATION_JACOBIAN)
#endif
}  // namespace checks

/// The state-space model of STATE_TRANSITION_MODEL / OBSERVATION_MODEL (and the Jacobians when
/// given). The filters of the estimation library are templates on this interface.
struct Model : ModelBase {
  /// next_state(i) = expression i of STATE_TRANSITION_MODEL, evaluated at x (a posteriori state of
  /// the last step) and u (current control inputs).
  template <class Scalar>
  void transition(const Eigen::Matrix<Scalar, StateSize, 1>& x,
                  const Eigen::Matrix<double, ControlSize, 1>& u,
                  Eigen::Matrix<Scalar, StateSize, 1>& next_state) const {
    SF_CFG_MATH_USINGS
    static_cast<void>(x);
    static_cast<void>(u);
    SF_PP_ASSIGN_VECTOR(next_state, STATE_TRANSITION_MODEL)
  }

  /// measurement(i) = expression i of OBSERVATION_MODEL (the measurement expected from TOPICS_IN
  /// entry i).
  template <class Scalar>
  void observation(const Eigen::Matrix<Scalar, StateSize, 1>& x,
                   Eigen::Matrix<Scalar, MeasurementSize, 1>& measurement) const {
    SF_CFG_MATH_USINGS
    [[maybe_unused]] constexpr detail::NoControlInput u{};
    static_cast<void>(x);
#if SF_CFG_HAS_OBSERVATION_MODEL
    SF_PP_ASSIGN_VECTOR(measurement, OBSERVATION_MODEL)
#else
    measurement.setZero();
#endif
  }

#if SF_CFG_HAS_STATE_TRANSITION_JACOBIAN
  /// jacobian(i, j) = entry (i, j) of STATE_TRANSITION_JACOBIAN (d next_state(i) / d x[j]).
  void transitionJacobian(const Eigen::Matrix<double, StateSize, 1>& x,
                          const Eigen::Matrix<double, ControlSize, 1>& u,
                          Eigen::Matrix<double, StateSize, StateSize>& jacobian) const {
    SF_CFG_MATH_USINGS
    static_cast<void>(x);
    static_cast<void>(u);
    jacobian.setZero();
    SF_PP_ASSIGN_MATRIX(jacobian, STATE_TRANSITION_JACOBIAN)
  }
#endif

#if SF_CFG_HAS_OBSERVATION_JACOBIAN
  /// jacobian(i, j) = entry (i, j) of OBSERVATION_JACOBIAN (d measurement(i) / d x[j]).
  void observationJacobian(const Eigen::Matrix<double, StateSize, 1>& x,
                           Eigen::Matrix<double, MeasurementSize, StateSize>& jacobian) const {
    SF_CFG_MATH_USINGS
    [[maybe_unused]] constexpr detail::NoControlInput u{};
    static_cast<void>(x);
    jacobian.setZero();
    SF_PP_ASSIGN_MATRIX(jacobian, OBSERVATION_JACOBIAN)
  }
#endif
};

#endif  // SF_CFG_IS_MODEL_BASED

// ------------------------------------------------------------------------ KF: LinearModel
// clang-format off
// The body of a LinearModel matrix getter: a ROWS x COLS matrix of zeros, with the entries of
// the header's matrix M when GIVEN (its entries may use T and the math functions).
#define SF_CFG_LINEAR_MATRIX(ROWS, COLS, GIVEN, M)                                                 \
  SF_CFG_MATH_USINGS                                                                               \
  Eigen::Matrix<double, ROWS, COLS> matrix = Eigen::Matrix<double, ROWS, COLS>::Zero();            \
  BOOST_PP_IF(GIVEN, SF_PP_ASSIGN_MATRIX, SF_PP_NOTHING)(matrix, M)                                \
  return matrix;
// clang-format on

#if SF_CFG_IS_LINEAR

/// The linear model x(k) = A x(k-1) + B u(k), z(k) = H x(k) of STATE_TRANSITION_MATRIX,
/// CONTROL_INPUT_MATRIX and OBSERVATION_MATRIX. The entries may use T. Besides the matrices it
/// offers the interface of Model (transition, observation, Jacobians), so a linear
/// configuration also works with the non-linear filters.
struct LinearModel : ModelBase {
  /// A (n x n) of STATE_TRANSITION_MATRIX.
  Eigen::Matrix<double, StateSize, StateSize> transitionMatrix() const {
      SF_CFG_LINEAR_MATRIX(StateSize, StateSize, 1, STATE_TRANSITION_MATRIX)}

  /// B (n x l) of CONTROL_INPUT_MATRIX (n x 0 without controls).
  Eigen::Matrix<double, StateSize, ControlSize> controlInputMatrix() const {
      SF_CFG_LINEAR_MATRIX(StateSize, ControlSize, SF_CFG_HAS_CONTROL_INPUT_MATRIX,
                           CONTROL_INPUT_MATRIX)}

  /// H (m x n) of OBSERVATION_MATRIX.
  Eigen::Matrix<double, MeasurementSize, StateSize> observationMatrix() const {
    SF_CFG_LINEAR_MATRIX(MeasurementSize, StateSize, SF_CFG_HAS_OBSERVATION_MATRIX,
                         OBSERVATION_MATRIX)
  }

  /// next_state = A x + B u.
  template <class Scalar>
  void transition(const Eigen::Matrix<Scalar, StateSize, 1>& x,
                  const Eigen::Matrix<double, ControlSize, 1>& u,
                  Eigen::Matrix<Scalar, StateSize, 1>& next_state) const {
    next_state = transitionMatrix().template cast<Scalar>() * x;
    if constexpr (ControlSize > 0) {
      const Eigen::Matrix<double, StateSize, 1> control_effect = controlInputMatrix() * u;
      next_state += control_effect.template cast<Scalar>();
    } else {
      static_cast<void>(u);
    }
  }

  /// measurement = H x.
  template <class Scalar>
  void observation(const Eigen::Matrix<Scalar, StateSize, 1>& x,
                   Eigen::Matrix<Scalar, MeasurementSize, 1>& measurement) const {
    measurement = observationMatrix().template cast<Scalar>() * x;
  }

  /// A (the Jacobian of a linear transition).
  void transitionJacobian(const Eigen::Matrix<double, StateSize, 1>&,
                          const Eigen::Matrix<double, ControlSize, 1>&,
                          Eigen::Matrix<double, StateSize, StateSize>& jacobian) const {
    jacobian = transitionMatrix();
  }

  /// H (the Jacobian of a linear observation).
  void observationJacobian(const Eigen::Matrix<double, StateSize, 1>&,
                           Eigen::Matrix<double, MeasurementSize, StateSize>& jacobian) const {
    jacobian = observationMatrix();
  }
};

/// A KALMAN_FILTER configuration also provides the Model interface.
using Model = LinearModel;

#endif  // SF_CFG_IS_LINEAR

}  // namespace sf_config
