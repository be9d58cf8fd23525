// EXPECT: INPUTS record 1: expected (name)(topic)(type)(field) before the options
// Mistake: the field left out, so an option stands where the field belongs
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(observe, x[1])(variance, 0.2))
