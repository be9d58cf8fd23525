// Stage 1 of the configuration: validation that must pass before any code can be generated.
//
//  - METHOD is defined and names a method of methods.hpp           (#error / static_assert)
//  - the macros required by the chosen method are defined           (#error)
//  - macros that cannot be combined with the method are absent      (#error)
//    (the method's own ones in its traits header, config/methods/<method>.hpp)
//  - TOPICS_IN, TOPICS_IN_CTRL, TOPICS_OUT and the macro defining the state size are
//    well-formed sequences                                          (static_assert)
//
// Any failure defines SF_CFG_FATAL: configuration.hpp then generates nothing (SF_CONFIG_OK is 0).
// Failures reported by #error (preprocessing time) also define SF_CFG_STOP: configuration.hpp
// then ends the compilation right away. (A static_assert is only reported when the file is
// parsed, which GCC does after reading the whole file, so those cannot stop it early.)
//
// On success this header defines the sizes as preprocessor literals:
//   SF_CFG_N   state size n          SF_CFG_N_WHY   "n = 2 is the number of ..."
//   SF_CFG_M   measurement size m    SF_CFG_M_WHY
//   SF_CFG_L   control size l        SF_CFG_L_WHY
//   SF_CFG_D   tangent size d        SF_CFG_D_WHY (with QUATERNION_STATES; d = n without)
// and SF_CFG_HAS_<X> (0/1) for every optional part.
#pragma once

#include <boost/preprocessor/arithmetic/sub.hpp>
#include <boost/preprocessor/facilities/is_empty.hpp>

#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/methods.hpp"

// clang-format off

#define SF_CFG_TOPICS_IN_FORMAT                                                                    \
  "((topic)(type)(field)) or ((topic)(type)(field)(variance_field))"
#define SF_CFG_TOPICS_IN_CTRL_FORMAT "((topic)(type)(field)) (controls have no variance field)"
#define SF_CFG_TOPICS_OUT_FORMAT "((topic)(state_index))"

// ---------------------------------------------------------------------------------------------
// METHOD: defined and not empty (methods.hpp), then named by one traits header (methods/*.hpp)
// ---------------------------------------------------------------------------------------------
#define SF_METHOD_CHECK_DEFINED
#include "sf_filter/config/methods.hpp"

#if !defined(SF_CFG_FATAL)
#define SF_METHOD_PART SF_METHOD_PART_DECLARE
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#if !defined(SF_CFG_METHOD_NAME) /* METHOD must be one identifier */
static_assert(false, "METHOD: expected one of " SF_METHOD_NAMES "; found '" SF_PP_STR(METHOD) "'");
#define SF_CFG_FATAL
#endif
#endif

#if !defined(SF_CFG_FATAL)

#define SF_CFG_IS_LINEAR (SF_CFG_METHOD_KIND == SF_METHOD_KIND_LINEAR)
#define SF_CFG_IS_MODEL_BASED (SF_CFG_METHOD_KIND == SF_METHOD_KIND_MODEL)
#define SF_CFG_IS_AVERAGING (SF_CFG_METHOD_KIND == SF_METHOD_KIND_WINDOW)

// ---------------------------------------------------------------------------------------------
// Names used by the expressions must not be macros
// ---------------------------------------------------------------------------------------------
#if defined(T)
#error T is defined as a macro, but T is the estimation period in seconds that the expressions use: remove the #define of T and set ESTIMATION_PERIOD (in ms) instead
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if defined(x) || defined(u)
#error x or u is defined as a macro, but x[i] and u[i] name the state and the control inputs in the expressions: remove that #define
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif

// ---------------------------------------------------------------------------------------------
// Required macros (all methods)
// ---------------------------------------------------------------------------------------------
#if !defined(TOPICS_IN)
#error TOPICS_IN is not defined: every method needs its measurement inputs, one entry per input, e.g. #define TOPICS_IN ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y))((velocity)(std_msgs::Float32)(data))
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if !defined(TOPICS_OUT)
#error TOPICS_OUT is not defined: every method needs its outputs, one ((topic)(state_index)) entry per published state variable, e.g. #define TOPICS_OUT ((velocity)(0))
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif

// ---------------------------------------------------------------------------------------------
// The macros the chosen method needs or refuses (its traits header, SF_METHOD_PART_MACROS)
// ---------------------------------------------------------------------------------------------
#define SF_METHOD_PART SF_METHOD_PART_MACROS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART

// ---------------------------------------------------------------------------------------------
// EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER, PARTICLE_FILTER_SIR
// ---------------------------------------------------------------------------------------------
#if SF_CFG_IS_MODEL_BASED
#if !defined(STATE_TRANSITION_MODEL)
#if defined(STATE_TRANSITION_MATRIX)
#error EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require STATE_TRANSITION_MODEL but found STATE_TRANSITION_MATRIX: write one expression per state variable, e.g. (x[0] + x[1]*T)(x[1]), or use METHOD KALMAN_FILTER
#else
#error EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require STATE_TRANSITION_MODEL: a sequence of n expressions in x[i], u[i] and T, one per state variable, e.g. (x[0] + x[1]*T)(x[1])
#endif
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if !defined(OBSERVATION_MODEL)
#if defined(OBSERVATION_MATRIX)
#error EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require OBSERVATION_MODEL but found OBSERVATION_MATRIX: write one expression in x[i] per TOPICS_IN entry, e.g. (x[0])(x[1]), or use METHOD KALMAN_FILTER
#else
#error EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require OBSERVATION_MODEL: a sequence of m expressions in x[i] and T, one per TOPICS_IN entry, e.g. (x[0])(x[1])
#endif
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if defined(CONTROL_INPUT_MATRIX)
#error CONTROL_INPUT_MATRIX is only used by KALMAN_FILTER: with a STATE_TRANSITION_MODEL write the controls u[i] into the expressions instead
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#endif  // model based

#if !SF_CFG_IS_AVERAGING
#if !defined(PROCESS_NOISE_COVARIANCE)
#error KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require PROCESS_NOISE_COVARIANCE: the n x n matrix Q, as a sequence of rows, e.g. ((0.1)(0))((0)(0.1))
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if !defined(MEASUREMENT_NOISE_COVARIANCE)
#error KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR require MEASUREMENT_NOISE_COVARIANCE: the m x m matrix R (m = number of TOPICS_IN entries), as a sequence of rows, e.g. ((0.5)(0))((0)(0.2))
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#endif

// ---------------------------------------------------------------------------------------------
// MOVING_AVERAGE, MOVING_MEDIAN, CONFIDENCE_WEIGHTED_AVERAGING
// ---------------------------------------------------------------------------------------------
#if defined(SF_CFG_METHOD_NEEDS_WINDOW_SIZE) && !defined(WINDOW_SIZE)
#error MOVING_AVERAGE and MOVING_MEDIAN require WINDOW_SIZE: the number of measurements per input that are averaged, a positive integer, e.g. #define WINDOW_SIZE 5
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#if SF_CFG_IS_AVERAGING && defined(TOPICS_IN_CTRL)
#error TOPICS_IN_CTRL is defined but MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING take no control inputs: remove TOPICS_IN_CTRL or choose a state estimator as METHOD
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif

// ---------------------------------------------------------------------------------------------
// Well-formed input/output lists and state-size macro (their sizes define m, l and n)
// ---------------------------------------------------------------------------------------------
#if !defined(SF_CFG_FATAL)

#if !SF_PP_IS_LIST(3, 4, TOPICS_IN)
SF_PP_CHECK_LIST("TOPICS_IN", 3, 4, SF_CFG_TOPICS_IN_FORMAT, TOPICS_IN)
#define SF_CFG_FATAL
#endif

#if defined(TOPICS_IN_CTRL)
#if !SF_PP_IS_LIST(3, 3, TOPICS_IN_CTRL)
SF_PP_CHECK_LIST("TOPICS_IN_CTRL", 3, 3, SF_CFG_TOPICS_IN_CTRL_FORMAT, TOPICS_IN_CTRL)
#define SF_CFG_FATAL
#endif
#endif

#if !SF_PP_IS_LIST(2, 2, TOPICS_OUT)
SF_PP_CHECK_LIST("TOPICS_OUT", 2, 2, SF_CFG_TOPICS_OUT_FORMAT, TOPICS_OUT)
#define SF_CFG_FATAL
#endif

#if SF_CFG_IS_LINEAR
#if !SF_PP_IS_MATRIX(STATE_TRANSITION_MATRIX)
SF_PP_MATRIX_FORM_ERROR("STATE_TRANSITION_MATRIX", n, n, "", STATE_TRANSITION_MATRIX)
#define SF_CFG_FATAL
#endif
#elif SF_CFG_IS_MODEL_BASED
#if !SF_PP_IS_VECTOR(STATE_TRANSITION_MODEL)
static_assert(false, "STATE_TRANSITION_MODEL: expected a sequence of n expressions in x[i], u[i] "
              "and T, each in parentheses, e.g. (x[0] + x[1]*T)(x[1]); found '"
              SF_PP_STR(STATE_TRANSITION_MODEL) "'");
#define SF_CFG_FATAL
#endif
#endif

#endif  // !SF_CFG_FATAL (lists)

// ---------------------------------------------------------------------------------------------
// Sizes
// ---------------------------------------------------------------------------------------------
#if !defined(SF_CFG_FATAL)

#define SF_CFG_M BOOST_PP_SEQ_SIZE(TOPICS_IN)
#define SF_CFG_M_WHY "m = " SF_PP_STR(SF_CFG_M) " is the number of TOPICS_IN entries"

#if defined(TOPICS_IN_CTRL)
#define SF_CFG_L BOOST_PP_SEQ_SIZE(TOPICS_IN_CTRL)
#define SF_CFG_L_WHY "l = " SF_PP_STR(SF_CFG_L) " is the number of TOPICS_IN_CTRL entries"
#else
#define SF_CFG_L 0
#define SF_CFG_L_WHY "l = 0 because TOPICS_IN_CTRL is not defined"
#endif

#if SF_CFG_IS_LINEAR
#define SF_CFG_N BOOST_PP_SEQ_SIZE(STATE_TRANSITION_MATRIX)
#define SF_CFG_N_WHY "n = " SF_PP_STR(SF_CFG_N) " is the number of rows of STATE_TRANSITION_MATRIX"
#elif SF_CFG_IS_MODEL_BASED
#define SF_CFG_N BOOST_PP_SEQ_SIZE(STATE_TRANSITION_MODEL)
#define SF_CFG_N_WHY                                                                               \
  "n = " SF_PP_STR(SF_CFG_N) " is the number of expressions in STATE_TRANSITION_MODEL"
#elif defined(SF_CFG_METHOD_STATE_SIZE)
#define SF_CFG_N SF_CFG_METHOD_STATE_SIZE
#define SF_CFG_N_WHY SF_CFG_METHOD_STATE_SIZE_WHY
#else
#define SF_CFG_N SF_CFG_M
#define SF_CFG_N_WHY "n = m = " SF_PP_STR(SF_CFG_M) " (the number of TOPICS_IN entries) for "      \
  SF_CFG_METHOD_NAME
#endif

// The tangent size d, over which the covariances of a header with QUATERNION_STATES are
// given: n less one per quaternion, whose 4 stored entries have 3 tangent rows (quaternions.hpp).
#if defined(QUATERNION_STATES) && SF_PP_IS_VECTOR(QUATERNION_STATES)
#define SF_CFG_HAS_QUATERNION_STATES 1
#define SF_CFG_D BOOST_PP_SUB(SF_CFG_N, BOOST_PP_SEQ_SIZE(QUATERNION_STATES))
#define SF_CFG_D_WHY                                                                               \
  "d = " SF_PP_STR(SF_CFG_D) " is the tangent size: n = " SF_PP_STR(SF_CFG_N) " less one per "     \
  "QUATERNION_STATES entry (a quaternion's 4 stored entries have 3 rows, in rad^2)"
#else
#define SF_CFG_HAS_QUATERNION_STATES 0
#define SF_CFG_D SF_CFG_N
#endif

// Optional parts (1 when given; a malformed value is reported by checks.hpp, not generated).
#if SF_CFG_IS_LINEAR && defined(CONTROL_INPUT_MATRIX) && SF_PP_IS_MATRIX(CONTROL_INPUT_MATRIX)
#define SF_CFG_HAS_CONTROL_INPUT_MATRIX 1
#else
#define SF_CFG_HAS_CONTROL_INPUT_MATRIX 0
#endif
#if defined(SF_CFG_METHOD_TAKES_JACOBIANS) && defined(STATE_TRANSITION_JACOBIAN) &&                      \
    SF_PP_IS_MATRIX(STATE_TRANSITION_JACOBIAN)
#define SF_CFG_HAS_STATE_TRANSITION_JACOBIAN 1
#else
#define SF_CFG_HAS_STATE_TRANSITION_JACOBIAN 0
#endif
#if defined(SF_CFG_METHOD_TAKES_JACOBIANS) && defined(OBSERVATION_JACOBIAN) &&                           \
    SF_PP_IS_MATRIX(OBSERVATION_JACOBIAN)
#define SF_CFG_HAS_OBSERVATION_JACOBIAN 1
#else
#define SF_CFG_HAS_OBSERVATION_JACOBIAN 0
#endif
#if defined(INITIAL_STATE) && SF_PP_IS_VECTOR(INITIAL_STATE)
#define SF_CFG_HAS_INITIAL_STATE 1
#else
#define SF_CFG_HAS_INITIAL_STATE 0
#endif
#if defined(INITIAL_ERROR_COVARIANCE) && SF_PP_IS_MATRIX(INITIAL_ERROR_COVARIANCE)
#define SF_CFG_HAS_INITIAL_ERROR_COVARIANCE 1
#else
#define SF_CFG_HAS_INITIAL_ERROR_COVARIANCE 0
#endif
#if defined(PROCESS_NOISE_COVARIANCE) && SF_PP_IS_MATRIX(PROCESS_NOISE_COVARIANCE)
#define SF_CFG_HAS_PROCESS_NOISE_COVARIANCE 1
#else
#define SF_CFG_HAS_PROCESS_NOISE_COVARIANCE 0
#endif
#if defined(MEASUREMENT_NOISE_COVARIANCE) && SF_PP_IS_MATRIX(MEASUREMENT_NOISE_COVARIANCE)
#define SF_CFG_HAS_MEASUREMENT_NOISE_COVARIANCE 1
#else
#define SF_CFG_HAS_MEASUREMENT_NOISE_COVARIANCE 0
#endif
#if defined(WEIGHTING_COEFFICIENTS) && SF_PP_IS_VECTOR(WEIGHTING_COEFFICIENTS)
#define SF_CFG_HAS_WEIGHTING_COEFFICIENTS 1
#else
#define SF_CFG_HAS_WEIGHTING_COEFFICIENTS 0
#endif
#if SF_CFG_IS_MODEL_BASED && SF_PP_IS_VECTOR(OBSERVATION_MODEL)
#define SF_CFG_HAS_OBSERVATION_MODEL 1
#else
#define SF_CFG_HAS_OBSERVATION_MODEL 0
#endif
#if SF_CFG_IS_LINEAR && SF_PP_IS_MATRIX(OBSERVATION_MATRIX)
#define SF_CFG_HAS_OBSERVATION_MATRIX 1
#else
#define SF_CFG_HAS_OBSERVATION_MATRIX 0
#endif

// ---------------------------------------------------------------------------------------------
// Macros that the chosen method does not use: warn instead of silently ignoring them.
// ---------------------------------------------------------------------------------------------
#if !SF_CFG_IS_MODEL_BASED
#if defined(STATE_TRANSITION_MODEL)
#pragma GCC warning "STATE_TRANSITION_MODEL is not used by the chosen METHOD and is ignored"
#endif
#if defined(OBSERVATION_MODEL)
#pragma GCC warning "OBSERVATION_MODEL is not used by the chosen METHOD and is ignored"
#endif
#endif
// Each method's own macros, when another method is chosen.
#define SF_METHOD_PART SF_METHOD_PART_UNUSED
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#if !SF_CFG_IS_AVERAGING && defined(WINDOW_SIZE)
#pragma GCC warning "WINDOW_SIZE is not used by the chosen METHOD and is ignored"
#endif
#if SF_CFG_IS_AVERAGING
#if defined(CONTROL_INPUT_MATRIX)
#pragma GCC warning "CONTROL_INPUT_MATRIX is not used by the chosen METHOD and is ignored"
#endif
#if defined(PROCESS_NOISE_COVARIANCE)
#pragma GCC warning "PROCESS_NOISE_COVARIANCE is not used by the chosen METHOD and is ignored"
#endif
#if defined(INITIAL_STATE)
#pragma GCC warning "INITIAL_STATE is not used by the chosen METHOD and is ignored"
#endif
#if defined(INITIAL_ERROR_COVARIANCE)
#pragma GCC warning "INITIAL_ERROR_COVARIANCE is not used by the chosen METHOD and is ignored"
#endif
#if !defined(SF_CFG_METHOD_TAKES_R) && defined(MEASUREMENT_NOISE_COVARIANCE)
#pragma GCC warning "MEASUREMENT_NOISE_COVARIANCE is not used by the chosen METHOD and is ignored"
#endif
#endif

#endif  // !SF_CFG_FATAL (sizes)

#endif  // !SF_CFG_FATAL (method)

// clang-format on
