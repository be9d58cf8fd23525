// EXPECT: INPUTS: expected a sequence of records, each written as ((name)(topic)(type)(field)(option, arguments)...)
// Mistake: single parentheses around a record
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  (position)(position)(geometry_msgs::Vector3Stamped)(vector.x)
