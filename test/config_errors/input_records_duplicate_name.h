// EXPECT: INPUTS record 1: the name 'wheel' is already used by an earlier record
// Mistake: two records with one name (overrides and diagnostics name inputs by it)
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((wheel)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2))
