// EXPECT: INPUTS record 1 (wheel) has no (variance, R_ii): every record needs it
// Mistake: a record without its variance (the EKF needs R)
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1]))
