// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(Hold)(LAGRANGE)(1)): unknown policy 'Hold', expected AVERAGE, LAST, SAMPLED, HOLD or FILL
// Mistake: policy names are in capitals
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(Hold)(LAGRANGE)(1))
