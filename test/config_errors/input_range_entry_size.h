// EXPECT: INPUT_RANGE: entry 0 has 2 elements, expected ((input index)(minimum)(maximum))
// Mistake: only one bound
#include "alignment_base_ekf.h"

#define INPUT_RANGE ((2)(5))
