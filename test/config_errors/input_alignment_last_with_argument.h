// EXPECT: INPUT_ALIGNMENT entry 0 ((2)(LAST)(1)): LAST takes the form ((index)(LAST)), found 3 elements
// Mistake: LAST has no parameter
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((2)(LAST)(1))
