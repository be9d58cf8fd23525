// EXPECT: INPUTS record 1 (wheel): unknown option '(gaet, 9)'; the options are observe,
// Mistake: a misspelt option name
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2)(gaet, 9))
