// Model nav2 (thesis section 5.2.1): the wheel encoders only, no controls.
// Transition eqs. 5.1-5.6 with v = v (no acceleration state), observation eqs. 5.17-5.18.
#pragma once
#include "velocity_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CONSTANT_TRANSITION
