// EXPECT: INPUTS records give (covariance_block, block, member, row) and INPUT_COVARIANCE_BLOCK is defined too
// Mistake: blocks given both on the records and index-addressed
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(odom)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[0])(variance, 0.5) \
     (covariance_block, 0, pose.covariance, 0)) \
  ((wheel)(odom)(nav_msgs::Odometry)(pose.pose.position.y)(observe, x[1])(variance, 0.2) \
     (covariance_block, 0, pose.covariance, 1))
#define INPUT_COVARIANCE_BLOCK (((0)(1))(pose.covariance)((0)(1)))
