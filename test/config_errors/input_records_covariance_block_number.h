// EXPECT: INPUTS record 1 (wheel): block '4' of (covariance_block, block, member, row) is not one of 0 to 3
// Mistake: a block number beyond the four a header may have
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x)(observe, x[0])(variance, 0.5)) \
  ((wheel)(odom)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[1])(variance, 0.2) \
     (covariance_block, 4, pose.covariance, 0))
