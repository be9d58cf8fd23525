// EXPECT: INPUT_TIMEOUT entry 1: input 1 is already listed in an earlier entry
// Mistake: two timeouts for one input
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT ((1)(500))((1)(200))
