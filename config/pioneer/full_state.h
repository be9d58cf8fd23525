// The full state of thesis section 5.1.2, used by nav1, nav1ctrl, nav3 and nav3ctrl:
//   x = (x, y, theta, omega, delta_s, v, a)   [m, m, rad, rad/s, m, m/s, m/s^2]
// its two transition models, its process noise, start and outputs.
#pragma once
#include "common.h"

// Eqs. 5.1-5.7: the basic variables omega and a are assumed constant.
#define PIONEER_CONSTANT_TRANSITION \
  PIONEER_POSE_TRANSITION \
  (x[3]) \
  (x[5] * T) \
  (x[5] + x[6] * T) \
  (x[6])
// Eqs. 5.8-5.14: omega follows cmd_vel.angular.z (u[1]), a is the acceleration that
// reaches cmd_vel.linear.x (u[0]) within one period.
#define PIONEER_CMD_VEL_TRANSITION \
  PIONEER_POSE_TRANSITION \
  (u[1]) \
  (x[5] * T) \
  (x[5] + x[6] * T) \
  ((u[0] - x[5]) / T)

#if METHOD == PARTICLE_FILTER_SIR
// Section 5.1.2: the particles' diversity comes from the process noise, so every state
// variable gets some; 700 particles as in Table 5.3 (what fit into 100 ms on the robot).
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0.1)(0.1)(0.1)(0.5)(0.1)(0.1)(0.3))
#define NUMBER_OF_PARTICLES 700
#else
// Eq. 5.20: only the basic variables omega and a change unpredictably.
#define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0)(0)(0)(0.5)(0)(0)(0.3))
#endif

#define INITIAL_STATE (0)(0)(0)(0)(0)(0)(0)
#define INITIAL_ERROR_COVARIANCE \
  SF_DIAGONAL((PIONEER_POSE_START_VARIANCE)(PIONEER_POSE_START_VARIANCE) \
              (PIONEER_POSE_START_VARIANCE)(1)(1)(1)(1))
#define TOPICS_OUT PIONEER_POSE_OUTPUTS
#define POSE_OUT PIONEER_POSE_INDICES
// The Odometry's twist: v = x[5], omega = x[3].
#define TWIST_OUT (5)(3)
#define ANGLE_STATES PIONEER_ANGLE_STATES
