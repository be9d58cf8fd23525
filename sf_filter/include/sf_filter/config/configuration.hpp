// Compile-time configuration of a sensor fusion node (thesis section 4.3.5, "Configuration").
//
// USAGE
//   The user writes ONE configuration header of macros (Boost.Preprocessor sequences). The node's
//   generated translation unit includes it, then this header:
//
//     #include SF_CONFIG_HEADER                     // -DSF_CONFIG_HEADER=\"path/config.h\"
//     #include <sf_filter/config/configuration.hpp>
//
//   Everything is generated into namespace sf_config (API below). A configuration header only
//   #defines macros and #includes the message headers of its topics; the method names
//   (KALMAN_FILTER, ...) come from sf_filter/config/methods.hpp, included here (the user may
//   include it too). This header may be included once per translation unit.
//
// SYNTAX
//   vector:      (a)(b)(c)                      one parenthesized entry per element
//   matrix:      ((a11)(a12))((a21)(a22))       a sequence of rows, each row a vector
//   expression:  any C++ expression in x[i] (state, i = 0..n-1), u[i] (controls, i = 0..l-1) and
//                T (estimation period in seconds); sin cos tan asin acos atan atan2 sinh cosh
//                tanh sqrt pow exp log abs are available unqualified (they must stay
//                unqualified, std::sin would break automatic differentiation). Matrix and
//                vector entries are expressions too: they may use T (e.g. ((1)(T))((0)(1))).
//                An entry must not contain a comma outside parentheses: write atan2(y, x) but
//                not a template argument list such as f<a, b>(x) (wrap it: (f<a, b>(x))).
//   topic:       a ROS name such as acceleration or /robot/odom; names that are not C++
//                tokens, or that are macros (e.g. linux/unix with GNU extensions), may be
//                given as a string literal: ("my-topic").
//   type:        the C++ message type, e.g. geometry_msgs::Vector3Stamped (#include its header
//                in the configuration header); a type with commas needs a typedef.
//   field:       member access path below the message, e.g. vector.y, twist.twist.linear.x,
//                data[0] (any expression valid after "message."), converted to double.
//
// MACROS                                     KF   EKF  UKF  PF   MA   MM   CWA
//   METHOD                                   R    R    R    R    R    R    R
//   TOPICS_IN                                R    R    R    R    R    R    R
//   TOPICS_OUT                               R    R    R    R    R    R    R
//   ESTIMATION_PERIOD                        o    o    o    o    o    o    o
//   STATE_TRANSITION_MATRIX                  R    -    -    -    -    -    -
//   CONTROL_INPUT_MATRIX                     c    x    x    x    -    -    -
//   OBSERVATION_MATRIX                       R    -    -    -    -    -    -
//   STATE_TRANSITION_MODEL                   -    R    R    R    -    -    -
//   OBSERVATION_MODEL                        -    R    R    R    -    -    -
//   STATE_TRANSITION_JACOBIAN                -    o    -    -    -    -    -
//   OBSERVATION_JACOBIAN                     -    o    -    -    -    -    -
//   PROCESS_NOISE_COVARIANCE                 R    R    R    R    -    -    -
//   MEASUREMENT_NOISE_COVARIANCE             R    R    R    R    -    -    o
//   INITIAL_STATE                            o    o    o    o    -    -    -
//   INITIAL_ERROR_COVARIANCE                 o    o    o    o    -    -    -
//   TOPICS_IN_CTRL                           o    o    o    o    x    x    x
//   UKF_ALPHA, UKF_BETA, UKF_KAPPA           -    -    o    -    -    -    -
//   UKF_PROPAGATED_MEAN                      -    -    o    -    -    -    -
//   NUMBER_OF_PARTICLES                      -    -    -    o    -    -    -
//   RANDOM_SEED, RESAMPLING_THRESHOLD        -    -    -    o    -    -    -
//   PF_SHARED_DEAD_RECKONING                 -    -    -    o    -    -    -
//   PF_LINEARISED_PROPOSAL                   -    -    -    o    -    -    -
//   WINDOW_SIZE                              -    -    -    -    R    R    o
//   WEIGHTING_COEFFICIENTS                   x    x    x    x    o    x    x
//   INPUT_ALIGNMENT                          o    o    o    o    o    o    o
//   INPUT_GATE                               o    o    o    o    x    x    x
//   ALIGN_BY_STAMP, MAX_MEASUREMENT_LAG      o    o    o    o    o    o    o
//   INPUT_TIMEOUT, INPUT_RANGE               o    o    o    o    o    o    o
//   ANGLE_STATES, ANGLE_INPUTS               o    o    o    o    x    x    x
//   DERIVED_INPUTS, INPUT_COVARIANCE(_BLOCK) o    o    o    o    o    o    o
//     (ROLL, PITCH, YAW derived inputs:      o    o    o    o    x    x    x)
//   R required (#error if missing), o optional, c required if TOPICS_IN_CTRL is defined,
//   x not allowed (#error), - not used (a "#pragma GCC warning" says it is ignored).
//   T, x and u must not be macros (#error): the expressions use them.
//   KF = KALMAN_FILTER, EKF = EXTENDED_KALMAN_FILTER, UKF = UNSCENTED_KALMAN_FILTER,
//   PF = PARTICLE_FILTER_SIR, MA = MOVING_AVERAGE, MM = MOVING_MEDIAN,
//   CWA = CONFIDENCE_WEIGHTED_AVERAGING.
//
//   METHOD                      one of the names above (methods.hpp)
//   TOPICS_IN                   ((topic)(type)(field)) or ((topic)(type)(field)(variance_field))
//                               per measurement input; m = number of entries. Several entries
//                               may use the same topic (different fields).
//   INPUTS                      instead of TOPICS_IN and the per-input macros: one record
//                               ((name)(topic)(type)(field)(option, arguments)...) per input,
//                               turned into those macros (input_records.hpp); not both.
//   TOPICS_IN_CTRL              ((topic)(type)(field)) per control input u[i]; l = number of
//                               entries (l = 0 without the macro).
//   TOPICS_OUT                  ((topic)(state_index)) per published state variable,
//                               0 <= state_index < n.
//   ESTIMATION_PERIOD           period between estimations in ms, > 0.     Default 100.
//   STATE_TRANSITION_MATRIX     A, n x n: x(k) = A x(k-1) + B u(k); its row count defines n.
//   CONTROL_INPUT_MATRIX        B, n x l.
//   OBSERVATION_MATRIX          H, m x n: z(k) = H x(k).
//   STATE_TRANSITION_MODEL      n expressions: next x[i]; its size defines n.
//   OBSERVATION_MODEL           m expressions in x[i] and T: expected measurement of input i.
//   STATE_TRANSITION_JACOBIAN   n x n expressions d next(i) / d x[j]. Default: the filter
//                               differentiates STATE_TRANSITION_MODEL automatically.
//   OBSERVATION_JACOBIAN        m x n expressions d z(i) / d x[j]. Default: automatic.
//   PROCESS_NOISE_COVARIANCE    Q, n x n.
//   MEASUREMENT_NOISE_COVARIANCE R, m x m. CWA: variances of inputs without a variance field
//                               (default identity).
//   INITIAL_STATE               x0, n entries.                             Default zero vector.
//   INITIAL_ERROR_COVARIANCE    P0, n x n.                                 Default identity.
//   UKF_ALPHA                   in (0, 1].                                 Default 1e-3.
//   UKF_BETA                    >= 0.                                      Default 2.
//   UKF_KAPPA                   n + kappa > 0.                             Default 0.
//   UKF_PROPAGATED_MEAN         1: predicted mean f(mean) (UKF-M); 0: the sigma points'
//                               weighted mean.            Default 1 with ANGLE_STATES, else 0.
//   NUMBER_OF_PARTICLES         integer >= 1.                              Default 1000.
//   RANDOM_SEED                 integer >= 0.                              Default 42.
//   PF_SHARED_DEAD_RECKONING    1: the states no measurement weighs (a dead-reckoned pose) are
//                               one Gaussian shared by the particles; 0: per particle.
//                                                         Default 1 with ANGLE_STATES, else 0.
//   PF_LINEARISED_PROPOSAL      1: each particle drawn from the Kalman posterior of its
//                               prediction; 0: from the transition.       Default 0.
//   RESAMPLING_THRESHOLD        fraction of NUMBER_OF_PARTICLES in [0, 1]; resample when the
//                               effective sample size drops below it.      Default 0.5.
//   WINDOW_SIZE                 integer >= 1: measurements per input averaged. CWA default 1.
//   WEIGHTING_COEFFICIENTS      WINDOW_SIZE weights, one per measurement of the window.
//                               Default: none (equal weights).
//   INPUT_ALIGNMENT             per input i that is not averaged (doc/alignment_policies.md):
//                               ((i)(AVERAGE)), ((i)(LAST)), ((i)(SAMPLED)),
//                               ((i)(HOLD)(LAGRANGE|BEZIER|TAYLOR)(order)[(variance)]) with
//                               0 <= order <= 15, ((i)(FILL)(omega)(N)[(variance)]) with
//                               omega > 0 [s], 1 <= N <= 16 (not for MA, MM, CWA).
//                                                                          Default AVERAGE.
//   INPUT_GATE                  ((i)(threshold)) per gated input: chi-square threshold > 0 on
//                               the squared Mahalanobis distance.          Default no gate.
//   ALIGN_BY_STAMP              (i)(j)...: inputs aligned by header.stamp (stamped types).
//   MAX_MEASUREMENT_LAG         ms >= 0 a period waits for stamped values.  Default one
//                               ESTIMATION_PERIOD with ALIGN_BY_STAMP, else 0.
//   INPUT_TIMEOUT               ((i)(ms)) per input with a sensor timeout, ms > 0: with no
//                               value accepted for longer the input is timed out (missing,
//                               no HOLD/FILL substitute, diagnostic WARN). Default none.
//   INPUT_RANGE                 ((i)(minimum)(maximum)) per input, minimum < maximum: values
//                               outside are dropped and counted.           Default none.
//   ANGLE_STATES                (i)(j)...: state variables x[i] that are angles in radians;
//                               wrapped to (-pi, pi], averaged on the circle. Default none.
//   ANGLE_INPUTS                (i)(j)...: TOPICS_IN entries measuring an angle in radians;
//                               their innovations are wrapped.             Default none.
//   QUATERNION_INPUTS           (i)(j)...: TOPICS_IN entries i..i+3 are the w, x, y, z of one
//                               measured quaternion, compared on SO(3) (QUATERNION_STATES, EKF,
//                               UKF; quaternion_inputs.hpp).               Default none.
//   DERIVED_INPUTS              ((i)(quantity)(mode)) per TOPICS_IN entry whose field is a
//                               quaternion or pose member: quantity X Y Z (pose position) or
//                               ROLL PITCH YAW (angle inputs automatically), mode ABSOLUTE or
//                               DIFFERENTIAL (change since the topic's previous message, in the
//                               previous pose's frame; derived_inputs.hpp); or EAST NORTH UP
//                               of a sensor_msgs/NavSatFix, ABSOLUTE: the fix in the odom frame
//                               about the datum (GPS inputs, gps_inputs.hpp). Default none.
//   TWIST_OUT                   (v index)(omega index): the published Odometry's twist and its
//                               covariance from the state (requires POSE_OUT;
//                               twist_output.hpp).                          Default: unknown
//                               twist (zero, variance 1e6).
//   POSE_OUT_3D                 (x)(y)(z)(q) indices, or (q) alone: nav_msgs/Odometry with the
//                               6x6 pose covariance, the tf and the Euler angles of a
//                               QUATERNION_STATES orientation (pose_output_3d.hpp). Default:
//                               not published.
//   TWIST_OUT_3D                (vx)(vy)(vz)(wx)(wy)(wz) indices: its twist in the robot's
//                               frame with the 6x6 covariance (requires POSE_OUT_3D).
//   ACCEL_OUT                   (a index): the forward acceleration published on accel/filtered
//                               (geometry_msgs/AccelWithCovarianceStamped; accel_output.hpp).
//                                                                          Default: not published.
//   INPUT_COVARIANCE            ((i)(covariance array member)(entry)) per TOPICS_IN entry taking
//                               its variance from the message's covariance array; "unknown"
//                               arrays (all zero, -1 first) fall back to R (input_covariance.hpp).
//   INPUT_COVARIANCE_BLOCK      ((inputs)(covariance array member)(rows)) per group of TOPICS_IN
//                               entries of one message taking their covariance block,
//                               correlations included (input_covariance_blocks.hpp).
//
// STATE SIZE n: rows of STATE_TRANSITION_MATRIX (KF); entries of STATE_TRANSITION_MODEL
//   (EKF, UKF, PF); m (MA, MM: one averaged output per input); 1 (CWA: one fused value).
//
// GENERATED API (namespace sf_config)
//   constexpr int kMethod; constexpr const char* kMethodName;
//   constexpr int kStateSize (n), kMeasurementSize (m), kControlSize (l), kOutputCount;
//   constexpr bool kHasControls, kHasTransitionJacobian, kHasObservationJacobian,
//                  kHasInitialState, kHasInitialErrorCovariance,
//                  kHasMeasurementNoiseCovariance, kHasWeightingCoefficients;
//   constexpr double kEstimationPeriodMs; constexpr int kWindowSize;
//
//   struct Parameters { estimation_period_ms, process_noise_covariance (Q, n x n),
//     measurement_noise_covariance (R, m x m), initial_state (x0), initial_error_covariance (P0),
//     each method's own parameters (SF_METHOD_PARAMETER in config/methods/<method>.hpp:
//     number_of_particles, random_seed, resampling_threshold, ukf_alpha, ukf_beta, ukf_kappa,
//     ukf_propagated_mean, pf_shared_dead_reckoning, pf_linearised_proposal), window_size, weighting_coefficients (Eigen::VectorXd, empty =
//     equal weights) };
//   Parameters defaultParameters(double estimation_period_ms = kEstimationPeriodMs);
//     (entries using T are evaluated with T = estimation_period_ms / 1000)
//
//   EKF, UKF, PF:  struct Model {
//     static constexpr int StateSize = n, MeasurementSize = m, ControlSize = l;
//     double T = kEstimationPeriodMs / 1000;          // used by the expressions
//     Eigen::Index stateSize() const; measurementSize() const; controlSize() const;
//     template <class Scalar> void transition(const Eigen::Matrix<Scalar, n, 1>& x,
//         const Eigen::Matrix<double, l, 1>& u, Eigen::Matrix<Scalar, n, 1>& next_state) const;
//     template <class Scalar> void observation(const Eigen::Matrix<Scalar, n, 1>& x,
//         Eigen::Matrix<Scalar, m, 1>& measurement) const;
//     // only if STATE_TRANSITION_JACOBIAN / OBSERVATION_JACOBIAN are given (EKF):
//     void transitionJacobian(const Eigen::Matrix<double, n, 1>& x,
//         const Eigen::Matrix<double, l, 1>& u, Eigen::Matrix<double, n, n>& jacobian) const;
//     void observationJacobian(const Eigen::Matrix<double, n, 1>& x,
//         Eigen::Matrix<double, m, n>& jacobian) const; };
//     Scalar is double or Eigen::AutoDiffScalar<Eigen::Matrix<double, n, 1>> (include
//     <Eigen/Core> before <unsupported/Eigen/AutoDiff>).
//   KF:  struct LinearModel { same sizes, T, size functions;
//     Eigen::Matrix<double, n, n> transitionMatrix() const;      // A
//     Eigen::Matrix<double, n, l> controlInputMatrix() const;    // B (zero n x 0 if l = 0)
//     Eigen::Matrix<double, m, n> observationMatrix() const;     // H
//     plus transition/observation (A x + B u, H x) and transitionJacobian/observationJacobian
//     (A, H) with the signatures of Model }; using Model = LinearModel;
//   MA, MM, CWA: no model.
//
//   Inputs: struct Input0 .. Input<m-1> (TOPICS_IN order), each with
//     using Message = <type>;
//     static constexpr int index;                       // i, also the measurement index
//     static constexpr std::string_view topic, message_type, field, variance_field;
//     static constexpr bool has_variance;
//     static constexpr int first_same_topic;            // index of the first input with the
//     static constexpr bool owns_subscription;          //   same topic; == index for the owner
//     static double value(const Message&);              // message.<field> as double
//     static double variance(const Message&);           // message.<variance_field>, NaN if none
//   using Inputs = std::tuple<Input0, ...>;
//   template <class Visitor> void forEachInput(Visitor&& visitor);  // visitor(Input0{}), ...
//   inline constexpr std::string_view kInputTopics[m];
//
//   Controls: struct Control0 .. Control<l-1> like inputs without variance; using Controls;
//     forEachControl(visitor); kControlTopics[l] (only if l > 0).
//   Outputs: struct Output0 .. : static constexpr int index, state_index;
//     static constexpr std::string_view topic; using Outputs; forEachOutput(visitor);
//     kOutputTopics[kOutputCount].
//
//   Alignment (detail/input_alignment.hpp): constexpr bool kHasInputAlignment,
//     kHasInputGate, kHasAlignByStamp; inline constexpr std::array<..., m>
//     kInputAlignment (sf_filter::AlignmentPolicy), kGateThresholds (infinity: none),
//     kAlignByStamp, kInputHasStamp; constexpr double kMaxMeasurementLagMs;
//   Faults (detail/input_faults.hpp): constexpr bool kHasInputTimeout, kHasInputRange;
//     inline constexpr std::array<double, m> kInputTimeoutsMs (infinity: none);
//     inline constexpr std::array<InputRange, m> kInputRanges ({minimum, maximum}).
//   std::vector<sf_filter::InputOptions> defaultInputOptions();  // all of the above per input
//
//   Angles (detail/angles.hpp): constexpr bool kHasAngleStates, kHasAngleInputs;
//     inline constexpr std::array<bool, n> kAngleStates; std::array<bool, m> kAngleInputs.
//
//   One subscription per distinct topic: subscribe for every input with owns_subscription and,
//   in its callback, read every input J with J::first_same_topic == owner index:
//     sf_config::forEachInput([&](auto in) {
//       using In = decltype(in);
//       if constexpr (In::owns_subscription) {
//         subscribe<typename In::Message>(std::string(In::topic), [&](const auto& msg) {
//           sf_config::forEachInput([&](auto other) {
//             using O = decltype(other);
//             if constexpr (O::first_same_topic == In::index)
//               store(O::index, O::value(msg), O::has_variance ? O::variance(msg) : nan);
//           });
//         });
//       }
//     });
//   (Entries sharing a topic are checked to share the message type. Inputs and controls are
//   separate lists: a topic used by both gets one subscription per list.)
//
// ERRORS
//   Every mistake fails the build; the first error printed names the macro, what was expected
//   and what was found, e.g.
//     error: #error EXTENDED_KALMAN_FILTER, ... require OBSERVATION_MODEL: a sequence of m ...
//     error: static assertion failed: PROCESS_NOISE_COVARIANCE: expected 2 rows, found 3 (must
//            be n x n; n = 2 is the number of expressions in STATE_TRANSITION_MODEL)
//   A missing or forbidden macro is an #error; the compilation then ends right after it (a
//   deliberately missing include, "SF_CONFIGURATION_ERROR__compilation_stopped__...", which is
//   not a second mistake). An unknown METHOD or a malformed TOPICS_IN, TOPICS_IN_CTRL,
//   TOPICS_OUT or state-size macro is a static_assert and nothing is generated:
//   SF_CONFIG_OK is then 0, and the node's code must be wrapped in "#if SF_CONFIG_OK ...
//   #endif" to avoid follow-up errors. Size and value mistakes are static_asserts that leave
//   the generated code compilable (SF_CONFIG_OK is 1), so each is reported once. Checked at
//   compile time: matrix/vector shapes, entry counts of models, Jacobians and
//   WEIGHTING_COEFFICIENTS, x[i] with i >= n and u[i] with i >= l (or u without TOPICS_IN_CTRL, or
//   u in the observation model), TOPICS_OUT indices and duplicate output topics, missing or
//   non-numeric message fields, invalid topic names, a topic listed with two message types, scalar
//   ranges. Limits: indices are only checked when written as integer literals (x[2], u(1)); a
//   message type that is not declared (missing #include) and syntax errors inside an expression are
//   reported by the compiler itself, at the line of the configuration header.
#pragma once

// INPUTS records become the index-addressed macros first: everything below reads those.
#include "sf_filter/config/input_records.hpp"
#include "sf_filter/config/detail/validation.hpp"
#include "sf_filter/config/methods.hpp"

#if defined(SF_CFG_FATAL)
/// 0: the configuration has an error (reported above) and nothing was generated.
#define SF_CONFIG_OK 0
#if defined(SF_CFG_STOP)
// A missing or forbidden macro (reported by #error above): end the compilation here, before
// code that uses the configuration reports follow-up errors.
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#else
/// 1: the configuration is usable (size/value mistakes may still be reported by static_assert).
#define SF_CONFIG_OK 1
#include "sf_filter/config/detail/angles.hpp"
#include "sf_filter/config/detail/quaternions.hpp"  // after the angles, before the checks
#include "sf_filter/config/detail/quaternion_inputs.hpp"
#include "sf_filter/config/detail/checks.hpp"
#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/input_alignment.hpp"
#include "sf_filter/config/detail/input_faults.hpp"
#include "sf_filter/config/detail/input_names.hpp"
#include "sf_filter/config/detail/input_options.hpp"
#include "sf_filter/config/detail/model.hpp"
#include "sf_filter/config/detail/parameters.hpp"
#include "sf_filter/config/detail/topics.hpp"

// After the inputs (they read Input<i>::Field and the message types).
#include "sf_filter/config/derived_inputs.hpp"
#include "sf_filter/config/input_covariance.hpp"
#include "sf_filter/config/gps_inputs.hpp"
#include "sf_filter/config/input_covariance_blocks.hpp"
#include "sf_filter/config/pose_output_3d.hpp"  // before TWIST_OUT: its #error first
#include "sf_filter/config/twist_output.hpp"
#include "sf_filter/config/accel_output.hpp"
#include "sf_filter/config/initial_from_inputs.hpp"
#endif
