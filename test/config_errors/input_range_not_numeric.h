// EXPECT: INPUT_RANGE entry 0 ((2)("low")(5)): minimum '"low"' and maximum '5' must be numbers
// Mistake: a bound written as a string
#include "alignment_base_ekf.h"

#define INPUT_RANGE ((2)("low")(5))
