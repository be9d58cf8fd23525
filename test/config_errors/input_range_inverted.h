// EXPECT: INPUT_RANGE entry 0 ((2)(5)(-5)): minimum '5' must be less than maximum '-5'
// Mistake: the bounds swapped
#include "alignment_base_ekf.h"

#define INPUT_RANGE ((2)(5)(-5))
