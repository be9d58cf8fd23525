// EXPECT: INPUT_TIMEOUT: expected a sequence of entries, each entry written as ((input index)(timeout in ms))
// Mistake: a bare number instead of ((input)(ms)) entries
#include "alignment_base_ekf.h"

#define INPUT_TIMEOUT 500
