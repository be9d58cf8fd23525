// EXPECT: INPUTS cannot be combined with OBSERVATION_MODEL, OBSERVATION_MATRIX or OBSERVATION_JACOBIAN
// Mistake: the observation model kept as a macro beside the records
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(variance, 0.5))
#define OBSERVATION_MODEL (x[0])
