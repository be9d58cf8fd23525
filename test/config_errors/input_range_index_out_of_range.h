// EXPECT: INPUT_RANGE entry 0: input index '-1' is out of range, expected an integer from 0 to 3
// Mistake: input indices start at 0
#include "alignment_base_ekf.h"

#define INPUT_RANGE ((-1)(0)(5))
