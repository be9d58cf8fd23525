// Pioneer 3-AT dead reckoning, model nav2 (wheel encoders only; thesis section 5.2.1), with the
// PARTICLE_FILTER_SIR: transition eqs. 5.1-5.6 with v = v, observation eqs. 5.17-5.18; the
// particle filter's Q of section 5.1.2, R of section 5.1.2 times 1000 (see pioneer/common.h),
// known start pose. The equations are in pioneer/nav2_model.h.
#define METHOD PARTICLE_FILTER_SIR
#include "pioneer/nav2_model.h"
