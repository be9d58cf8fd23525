// EXPECT: QUATERNION_STATES is used by EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER only
// Mistake: a linear Kalman filter cannot keep a unit quaternion
#include "valid_kf.h"

#define QUATERNION_STATES (0)
