// Model nav2ctrl (thesis section 5.2.1): nav2 plus the cmd_vel controls.
// Transition eqs. 5.8-5.13 with v = cmd_vel.linear.x, observation eqs. 5.17-5.18.
#pragma once
#include "velocity_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CMD_VEL_TRANSITION
#define TOPICS_IN_CTRL PIONEER_CMD_VEL_CONTROLS
