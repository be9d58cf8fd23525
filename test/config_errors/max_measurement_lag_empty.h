// EXPECT: MAX_MEASUREMENT_LAG is defined but empty
// Mistake: no value
#include "alignment_base_ekf.h"

#define ALIGN_BY_STAMP (0)
#define MAX_MEASUREMENT_LAG
