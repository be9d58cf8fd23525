// EXPECT: OK
// INPUTS records with every per-input option: the same configuration as alignment_base_ekf.h
// plus options, written one record per input.
#include "fake_msgs.h"
#define METHOD EXTENDED_KALMAN_FILTER
#define STATE_TRANSITION_MODEL (x[0] + x[1] * T)(x[1])
#define PROCESS_NOISE_COVARIANCE ((0.01)(0))((0)(0.1))
#define INPUTS \
  ((position)(position)(geometry_msgs::Vector3Stamped)(vector.x) \
     (observe, x[0])(variance, 0.5)(by_stamp)(gate, 9)(alignment, HOLD, LAGRANGE, 1)) \
  ((wheel)(wheel)(std_msgs::Float32)(data)(observe, x[1])(variance, 0.2)(range, -3, 3)) \
  ((imu_x)(imu)(sensor_msgs::Imu)(linear_acceleration.x)(observe, x[1])(variance, 0.3) \
     (timeout, 500)(alignment, FILL, 0.1, 4)) \
  ((odom_x)(odom)(nav_msgs::Odometry)(pose.pose.position.x)(observe, x[0])(variance, 0.4) \
     (variance_field, pose.covariance[0]))
#define TOPICS_OUT ((position)(0))((speed)(1))
#include <sf_filter/config/configuration.hpp>
static_assert(sf_config::kMeasurementSize == 4, "four records");
static_assert(sf_config::kInputNames[2] == "imu_x", "record names");
static_assert(sf_config::kGateThresholds[0] == 9 && sf_config::kAlignByStamp[0], "options");
static_assert(sf_config::kInputRanges[1].minimum == -3 && sf_config::kInputRanges[1].maximum == 3,
              "(range, -3, 3) on record 1 only");
static_assert(sf_config::kInputTimeoutsMs[2] == 500 && sf_config::kHasInputGate,
              "(timeout, 500) on record 2");
static_assert(sf_config::Input3::has_variance && !sf_config::Input0::has_variance,
              "(variance_field, ...) on record 3 only");
static_assert(sf_config::kInputTopics[1] == "wheel" && sf_config::Input2::field == "linear_acceleration.x",
              "topics and fields from the records");
