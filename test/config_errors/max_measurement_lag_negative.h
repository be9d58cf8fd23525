// EXPECT: MAX_MEASUREMENT_LAG: expected a number of milliseconds >= 0, found '-5'
// Mistake: a lag is not negative
#include "alignment_base_ekf.h"

#define ALIGN_BY_STAMP (0)
#define MAX_MEASUREMENT_LAG -5
