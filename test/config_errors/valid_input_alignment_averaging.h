// EXPECT: OK
// HOLD and LAST need no prediction: allowed for the averaging methods
#include "alignment_base_averaging.h"

#define INPUT_ALIGNMENT ((0)(LAST))((1)(HOLD)(LAGRANGE)(1)(0.5))
#define ALIGN_BY_STAMP (0)
