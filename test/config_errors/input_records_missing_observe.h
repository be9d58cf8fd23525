// EXPECT: INPUTS record 0 (position) has no (observe, expression): every record needs it
// Mistake: a record without its observation (the EKF needs OBSERVATION_MODEL)
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2))
