// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(HOLD)(TAYLOR)): HOLD takes the form ((index)(HOLD)(LAGRANGE|BEZIER|TAYLOR)(order)[(variance)]), found 3 elements
// Mistake: the order is missing
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(HOLD)(TAYLOR))
