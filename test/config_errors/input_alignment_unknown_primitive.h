// EXPECT: INPUT_ALIGNMENT entry 1 ((1)(HOLD)(SPLINE)(2)): unknown hold primitive 'SPLINE', expected LAGRANGE, BEZIER or TAYLOR
// Mistake: a primitive that Table 1 does not have
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((0)(LAST))((1)(HOLD)(SPLINE)(2))
