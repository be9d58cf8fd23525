// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(HOLD)(BEZIER)(1)(-0.5)): variance must be positive
// Mistake: a variance is positive
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(HOLD)(BEZIER)(1)(-0.5))
