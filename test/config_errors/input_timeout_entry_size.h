// EXPECT: INPUT_TIMEOUT: entry 0 has 3 elements, expected ((input index)(timeout in ms))
// Mistake: one timeout per entry
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT ((0)(500)(2))
