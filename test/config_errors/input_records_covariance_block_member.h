// EXPECT: INPUTS record 1 (y): the member 'twist.covariance' of its covariance_block is not the one of the block's first record
// Mistake: two records of one block name different covariance arrays
#include "input_records_base.h"
#undef INPUTS
#define INPUTS \
  ((position)(odom)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[0])(variance, 0.5) \
     (covariance_block, 0, pose.covariance, 0)) \
  ((y)(odom)(nav_msgs::Odometry)(pose.pose.position.y)(observe, x[1])(variance, 0.2) \
     (covariance_block, 0, twist.covariance, 1))
