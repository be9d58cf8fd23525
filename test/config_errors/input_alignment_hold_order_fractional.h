// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(HOLD)(BEZIER)(1.5)): HOLD order '1.5' is not an integer
// Mistake: the order is a whole number
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(HOLD)(BEZIER)(1.5))
