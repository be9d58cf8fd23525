// EXPECT: INPUT_TIMEOUT entry 1: input index '4' is out of range, expected an integer from 0 to 3
// Mistake: no input 4 (there are 4 inputs, 0 to 3)
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT ((0)(500))((4)(500))
