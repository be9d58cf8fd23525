// test/configs/tune_cart_kf.h's cart and noise as an UNSCENTED_KALMAN_FILTER: its innovation
// covariance S comes from the unscented transform, not from H P H^T + R.
#include "tune_cart_kf.h"

#undef METHOD
#undef STATE_TRANSITION_MATRIX
#undef OBSERVATION_MATRIX
#define METHOD UNSCENTED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + T * x[1])(x[1])
#define OBSERVATION_MODEL (x[0])(x[1])
