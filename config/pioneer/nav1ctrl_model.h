// Model nav1ctrl (thesis section 5.2.1): nav1 plus the cmd_vel controls.
// Transition eqs. 5.8-5.14 (omega and a follow cmd_vel), observation eqs. 5.15-5.16.
#pragma once
#include "full_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CMD_VEL_TRANSITION
#define OBSERVATION_MODEL (x[3])(x[6])
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((PIONEER_GYRO_VARIANCE)(PIONEER_ACCEL_VARIANCE))
#define TOPICS_IN PIONEER_GYRO_INPUT PIONEER_ACCEL_INPUT
#define TOPICS_IN_CTRL PIONEER_CMD_VEL_CONTROLS
