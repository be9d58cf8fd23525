// EXPECT: INPUTS record 1 (wheel): option '(range, -3)' has the wrong number of arguments, expected (range, minimum, maximum)
// Mistake: a range with one bound
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2)(range, -3))
