// Model nav1 (thesis section 5.2.1): accelerometer and gyroscope only, no controls.
// Transition eqs. 5.1-5.7 (omega and a constant), observation eqs. 5.15-5.16; nothing but
// the accelerometer tells v, so its drifting bias is integrated into the path (5.2.2).
#pragma once
#include "full_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CONSTANT_TRANSITION
#define OBSERVATION_MODEL (x[3])(x[6])
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL((PIONEER_GYRO_VARIANCE)(PIONEER_ACCEL_VARIANCE))
#define TOPICS_IN PIONEER_GYRO_INPUT PIONEER_ACCEL_INPUT
