// EXPECT: INPUT_GATE entry 0
// Mistake in an option value: reported by the generated macro's check, entry 0 of INPUT_GATE
// (the first record with a gate)
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2)(gate, -1))
