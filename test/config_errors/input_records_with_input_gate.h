// EXPECT: INPUTS cannot be combined with INPUT_ALIGNMENT, INPUT_GATE, INPUT_TIMEOUT, INPUT_RANGE or ALIGN_BY_STAMP
// Mistake: an index-addressed option beside the records
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5))
#define INPUT_GATE ((0)(9))
