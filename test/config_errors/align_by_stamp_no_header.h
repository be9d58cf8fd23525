// EXPECT: ALIGN_BY_STAMP entry 1: the message type of TOPICS_IN entry 1 has no header.stamp
// Mistake: std_msgs/Float32 carries no stamp
#include "alignment_base_ekf.h"

#define ALIGN_BY_STAMP (0)(1)
