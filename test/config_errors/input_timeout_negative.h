// EXPECT: INPUT_TIMEOUT entry 0 ((0)(-5)): timeout '-5' must be a positive finite number of milliseconds
// Mistake: a timeout is a positive duration
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT ((0)(-5))
