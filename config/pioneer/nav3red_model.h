// Model nav3red (thesis section 5.2.1): nav3ctrl reduced to the state it needs,
//   x = (omega, v, a)   [rad/s, m/s, m/s^2]
// transition eqs. 5.11-5.14, observation eqs. 5.15-5.18. There is no pose in the state: the
// path is computed offline from the logged v and omega (tools/eval/evaluate.py
// --dead-reckoning v=x1,omega=x0), as in the thesis. The model is linear, so the
// KALMAN_FILTER takes it as matrices; the other methods take the same equations as
// expressions.
#pragma once
#include "common.h"

#if METHOD == KALMAN_FILTER
// omega' = u1; v' = v + a T; a' = (u0 - v) / T.
#define STATE_TRANSITION_MATRIX ((0)(0)(0))((0)(1)(T))((0)(-1 / T)(0))
#define CONTROL_INPUT_MATRIX ((0)(1))((0)(0))((1 / T)(0))
// gyro = omega; accelerometer = a; wheels = (v -+ omega R) * 1000.
#define OBSERVATION_MATRIX \
  ((1)(0)(0)) \
  ((0)(0)(1)) \
  ((-PIONEER_RADIUS * 1000)(1000)(0)) \
  ((PIONEER_RADIUS * 1000)(1000)(0))
#else
#define STATE_TRANSITION_MODEL (u[1])(x[1] + x[2] * T)((u[0] - x[1]) / T)
#define OBSERVATION_MODEL (x[0])(x[2]) PIONEER_WHEEL_OBSERVATION(x[1], x[0])
#endif

#if METHOD == PARTICLE_FILTER_SIR
// The full state's particle noise on the three variables left; 500 particles as in
// Table 5.3 (what fit into 100 ms on the robot with this state).
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.5)(0.1)(0.3))
#define NUMBER_OF_PARTICLES 500
#else
// Eq. 5.20 without the pose rows.
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.5)(0)(0.3))
#endif

#define MEASUREMENT_NOISE_COVARIANCE PIONEER_ALL_INPUTS_R
#define INITIAL_STATE (0)(0)(0)
#define TOPICS_IN PIONEER_ALL_INPUTS
#define TOPICS_IN_CTRL PIONEER_CMD_VEL_CONTROLS
#define TOPICS_OUT ((velocity/angular)(0))((velocity/linear)(1))((acceleration)(2))
