// EXPECT: WARNING MAX_MEASUREMENT_LAG is not used without ALIGN_BY_STAMP and is ignored
// Not an error: the lag only matters for inputs aligned by stamp
#include "alignment_base_ekf.h"

#define MAX_MEASUREMENT_LAG 20
