// EXPECT: INPUT_ALIGNMENT entry 1: input 1 is already listed in an earlier entry
// Mistake: one input with two policies
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((1)(LAST))((1)(SAMPLED))
