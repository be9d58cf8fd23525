// EXPECT: INPUT_GATE entry 1: input 2 is already listed in an earlier entry
// Mistake: one input gated twice
#include "alignment_base_ekf.h"

#define INPUT_GATE ((2)(9))((2)(4))
