// EXPECT: INPUT_ALIGNMENT: entry 0 is not a sequence of parenthesized elements
// Mistake: the entry needs its own parentheses
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT (0)(LAST)
