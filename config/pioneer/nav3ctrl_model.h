// Model nav3ctrl (thesis section 5.2.1): all sensors and the cmd_vel controls.
// Transition eqs. 5.8-5.14, observation eqs. 5.15-5.18.
#pragma once
#include "full_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CMD_VEL_TRANSITION
#define OBSERVATION_MODEL (x[3])(x[6]) PIONEER_WHEEL_OBSERVATION(x[5], x[3])
#define MEASUREMENT_NOISE_COVARIANCE PIONEER_ALL_INPUTS_R
#define TOPICS_IN PIONEER_ALL_INPUTS
#define TOPICS_IN_CTRL PIONEER_CMD_VEL_CONTROLS
