// EXPECT: INPUT_ALIGNMENT entry 0: input index '4' is out of range, expected an integer from 0 to 3
// Mistake: inputs are counted from 0
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((4)(LAST))
