// EXPECT: INPUTS record 0 (position): option '(gate, 4)' is given a second time
// Mistake: one option given twice on a record (which one would count?)
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5) \
     (gate, 9)(gate, 4)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2))
