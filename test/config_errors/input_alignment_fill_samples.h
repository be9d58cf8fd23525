// EXPECT: INPUT_ALIGNMENT entry 0 ((0)(FILL)(0.001)(20)): FILL N '20' is not an integer from 1 to 16
// Mistake: more stored samples than the history holds
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((0)(FILL)(0.001)(20))
