// EXPECT: ANGLE_INPUTS is used by KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR only
// Mistake: an averaging method averages linearly and cannot take angles
#include "alignment_base_averaging.h"

#define ANGLE_INPUTS (0)
