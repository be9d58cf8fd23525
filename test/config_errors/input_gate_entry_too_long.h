// EXPECT: INPUT_GATE: entry 0 has 3 elements, expected ((input index)(chi-square threshold))
// Mistake: one threshold per input
#include "alignment_base_ekf.h"

#define INPUT_GATE ((0)(9)(4))
