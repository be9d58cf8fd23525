// The state of nav2 and nav2ctrl (thesis section 5.2.1): the full state without the
// acceleration, which no wheel encoder measures ("there is no need to hold a state variable
// when the property is of no use"), and the wheel encoders as the only sensors.
//   x = (x, y, theta, omega, delta_s, v)   [m, m, rad, rad/s, m, m/s]
#pragma once
#include "common.h"

// Eqs. 5.1-5.6 with eq. 5.6 set to v = v (section 5.2.1, nav2).
#define PIONEER_CONSTANT_TRANSITION \
  PIONEER_POSE_TRANSITION \
  (x[3]) \
  (x[5] * T) \
  (x[5])
// Eqs. 5.8-5.13 with eq. 5.13 replaced by v = cmd_vel.linear.x (section 5.2.1, nav2ctrl).
#define PIONEER_CMD_VEL_TRANSITION \
  PIONEER_POSE_TRANSITION \
  (u[1]) \
  (x[5] * T) \
  (u[0])

// Eqs. 5.17-5.18 (the thesis lists 5.15-5.18 for nav2, but nav2 "uses only the wheel
// velocities", and nav2ctrl lists 5.17-5.18).
#define OBSERVATION_MODEL PIONEER_WHEEL_OBSERVATION(x[5], x[3])
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((PIONEER_WHEEL_VARIANCE)(PIONEER_WHEEL_VARIANCE))
#define TOPICS_IN PIONEER_WHEEL_INPUTS

// The thesis gives no Q for this state. With a removed, v is the basic variable that changes
// unpredictably, so it takes the variance eq. 5.20 gives a (0.3; the thesis sets T = 1 s for
// its Q, where a change of a by sqrt(0.3) m/s^2 changes v by as much in m/s).
#if METHOD == PARTICLE_FILTER_SIR
// Every variable gets noise, as the full state's particle filter (section 5.1.2).
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.1)(0.1)(0.1)(0.5)(0.1)(0.3))
#define NUMBER_OF_PARTICLES 700
#else
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0)(0)(0)(0.5)(0)(0.3))
#endif

#define INITIAL_STATE (0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((PIONEER_POSE_START_VARIANCE)(PIONEER_POSE_START_VARIANCE) \
              (PIONEER_POSE_START_VARIANCE)(1)(1)(1))
#define TOPICS_OUT PIONEER_POSE_OUTPUTS
#define POSE_OUT PIONEER_POSE_INDICES
// The Odometry's twist: v = x[5], omega = x[3].
#define TWIST_OUT (5)(3)
#define ANGLE_STATES PIONEER_ANGLE_STATES
