// EXPECT: QUATERNION_STATES is used by EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER only
// Mistake: an averaging method averages linearly and cannot keep a unit quaternion
#include "alignment_base_averaging.h"

#define QUATERNION_STATES (0)
