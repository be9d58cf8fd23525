// EXPECT: OK
// valid_input_covariance_block.h written as INPUTS records: x, y and yaw of an odometry with
// their covariance block (covariance_block 0: rows 0, 1, 5 of pose.covariance), block 1 with
// its rows in another order, and a speed from another topic, outside any block.
#include "fake_msgs.h"

#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[3] * T * cos(x[2]))(x[1] + x[3] * T * sin(x[2]))(x[2])(x[3])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0)(0)(0))((0)(0.01)(0)(0))((0)(0)(0.01)(0))((0)(0)(0)(0.1))
#define TOPICS_OUT ((x)(0))
#define ANGLE_STATES (2)
#define INPUTS \
  ((x)(odom)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[0])(variance, 0.5) \
     (covariance_block, 0, pose.covariance, 0)) \
  ((y)(odom)(nav_msgs::Odometry)(pose.pose.position.y)(observe, x[1])(variance, 0.5) \
     (covariance_block, 0, pose.covariance, 1)) \
  ((yaw)(odom)(nav_msgs::Odometry)(pose.pose.orientation)(observe, x[2])(variance, 0.1) \
     (derived, YAW, ABSOLUTE)(covariance_block, 0, pose.covariance, 5)) \
  ((speed)(speed)(std_msgs::Float64)(data)(observe, x[3])(variance, 0.2)) \
  ((y2)(odom2)(nav_msgs::Odometry)(pose.pose.position.y)(observe, x[1])(variance, 0.5) \
     (covariance_block, 2, pose.covariance, 1)) \
  ((x2)(odom2)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[0])(variance, 0.5) \
     (covariance_block, 2, pose.covariance, 0))
#include <sf_filter/config/configuration.hpp>
static_assert(std::tuple_size_v<sf_config::CovarianceBlocks> == 2, "blocks 0 and 2");
static_assert(sf_config::CovarianceBlock0::size == 3 && sf_config::CovarianceBlock0::inputs[0] == 0 &&
                  sf_config::CovarianceBlock0::inputs[2] == 2 &&
                  sf_config::CovarianceBlock0::rows[2] == 5,
              "block 0: inputs 0 1 2, rows 0 1 5");
static_assert(sf_config::CovarianceBlock1::size == 2 && sf_config::CovarianceBlock1::inputs[0] == 4 &&
                  sf_config::CovarianceBlock1::rows[0] == 1 &&
                  sf_config::CovarianceBlock1::rows[1] == 0,
              "block 2 (the second entry): inputs 4 5, rows 1 0, in record order");
static_assert(sf_config::blockOf(3) == -1 && sf_config::blockOf(5) == 1, "speed in no block");
