// EXPECT: ALIGN_BY_STAMP entry 0: input index '-1' is out of range
// Mistake: indices start at 0
#include "alignment_base_ekf.h"

#define ALIGN_BY_STAMP (-1)
