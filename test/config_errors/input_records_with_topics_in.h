// EXPECT: INPUTS and TOPICS_IN are both defined: a header gives its inputs either as INPUTS records
// Mistake: both syntaxes in one header
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5))
#define TOPICS_IN ((wheel)(std_msgs::Float32)(data))
