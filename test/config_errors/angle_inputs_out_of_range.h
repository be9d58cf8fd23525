// EXPECT: ANGLE_INPUTS entry 0: index '2' is out of range, expected an integer from 0 to 1 (the TOPICS_IN entry; m = 2 is the number of TOPICS_IN entries)
// Mistake: the index of a TOPICS_IN entry that does not exist
#define SF_ANGLES_CASE
#include "valid_angles.h"

#define ANGLE_INPUTS (2)
