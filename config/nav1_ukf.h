// Pioneer 3-AT dead reckoning, model nav1 (accelerometer and gyroscope only; thesis section
// 5.2.1), with the UNSCENTED_KALMAN_FILTER: transition eqs. 5.1-5.7, observation eqs.
// 5.15-5.16; Q of eq. 5.20, R of section 5.1.2, known start pose. The equations are in
// pioneer/nav1_model.h.
#define METHOD UNSCENTED_KALMAN_FILTER
#include "pioneer/nav1_model.h"
