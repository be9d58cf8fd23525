// Pioneer 3-AT dead reckoning, model nav3red (nav3ctrl without the pose in the state; thesis
// section 5.2.1), with the PARTICLE_FILTER_SIR: transition eqs. 5.11-5.14, observation eqs.
// 5.15-5.18; the particle filter's Q of section 5.1.2, R of section 5.1.2 times 1000 (see
// pioneer/common.h). The equations are in pioneer/nav3red_model.h.
#define METHOD PARTICLE_FILTER_SIR
#include "pioneer/nav3red_model.h"
