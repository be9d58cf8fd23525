// Pioneer 3-AT dead reckoning, model nav3red (nav3ctrl without the pose in the state; thesis
// section 5.2.1), with the KALMAN_FILTER (the model's linear form): transition eqs. 5.11-5.14,
// observation eqs. 5.15-5.18; Q of eq. 5.20 without the pose, R of section 5.1.2. The equations
// are in pioneer/nav3red_model.h.
#define METHOD KALMAN_FILTER
#include "pioneer/nav3red_model.h"
