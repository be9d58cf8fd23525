// Pioneer 3-AT dead reckoning, model nav2ctrl (wheel encoders and cmd_vel; thesis section
// 5.2.1), with the PARTICLE_FILTER_SIR: transition eqs. 5.8-5.13 with v = cmd_vel.linear.x,
// observation eqs. 5.17-5.18; the particle filter's Q of section 5.1.2, R of section 5.1.2
// times 1000 (see pioneer/common.h), known start pose. The equations are in
// pioneer/nav2ctrl_model.h.
#define METHOD PARTICLE_FILTER_SIR
#include "pioneer/nav2ctrl_model.h"
