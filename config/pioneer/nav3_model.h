// Model nav3 (thesis section 5.2.1): accelerometer, gyroscope and wheel encoders, no
// controls. Transition eqs. 5.1-5.7, observation eqs. 5.15-5.18: the wheels and the
// accelerometer are fused into v, the wheels and the gyroscope into omega.
#pragma once
#include "full_state.h"

#define STATE_TRANSITION_MODEL PIONEER_CONSTANT_TRANSITION
#define OBSERVATION_MODEL (x[3])(x[6]) PIONEER_WHEEL_OBSERVATION(x[5], x[3])
#define MEASUREMENT_NOISE_COVARIANCE PIONEER_ALL_INPUTS_R
#define TOPICS_IN PIONEER_ALL_INPUTS
