// EXPECT: INPUT_GATE entry 0 ((0)(-1)): threshold '-1' must be a positive finite number
// Mistake: a chi-square quantile is positive
#include "alignment_base_ekf.h"

#define INPUT_GATE ((0)(-1))
