// EXPECT: INPUTS record 1: the name '2nd_wheel' is not an identifier
// Mistake: a record name that a parameter key or C++ name cannot be
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((2nd_wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2))
