// EXPECT: INPUT_ALIGNMENT entry 0 ((1)(HOLD)(TAYLOR)(16)): HOLD order '16' is not an integer from 0 to 15
// Mistake: the history holds at most 16 samples
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(HOLD)(TAYLOR)(16))
