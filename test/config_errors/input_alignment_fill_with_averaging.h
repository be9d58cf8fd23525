// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(FILL)(0.001)(5)): FILL needs the filter's predicted measurement h(x(k|k-1)), which MOVING_AVERAGE does not give
// Mistake: a moving average has no model to predict the measurement
#include "alignment_base_averaging.h"

#define INPUT_ALIGNMENT ((1)(FILL)(0.001)(5))
