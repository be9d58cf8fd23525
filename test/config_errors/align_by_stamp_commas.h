// EXPECT: ALIGN_BY_STAMP: expected a sequence of input indices, each in parentheses, e.g. (0)(2); found '0, 2'
// Mistake: a comma list instead of a sequence
#include "alignment_base_ekf.h"

#define ALIGN_BY_STAMP 0, 2
