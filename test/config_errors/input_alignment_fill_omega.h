// EXPECT: INPUT_ALIGNMENT entry 0 ((0)(FILL)(0)(5)): FILL omega '0' must be a positive number of seconds
// Mistake: omega 0 would put z^ at the time of the substitute (Remark 4.1)
#include "alignment_base_ekf.h"

#define INPUT_ALIGNMENT ((0)(FILL)(0)(5))
