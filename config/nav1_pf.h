// Pioneer 3-AT dead reckoning, model nav1 (accelerometer and gyroscope only; thesis section
// 5.2.1), with the PARTICLE_FILTER_SIR: transition eqs. 5.1-5.7, observation eqs. 5.15-5.16;
// the particle filter's Q of section 5.1.2, R of section 5.1.2 times 1000 (see
// pioneer/common.h), known start pose. The equations are in pioneer/nav1_model.h.
#define METHOD PARTICLE_FILTER_SIR
#include "pioneer/nav1_model.h"
