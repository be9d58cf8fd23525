// EXPECT: INPUT_GATE entry 1: input index '7' is out of range, expected an integer from 0 to 3
// Mistake: no input 7
#include "alignment_base_ekf.h"

#define INPUT_GATE ((0)(9))((7)(9))
