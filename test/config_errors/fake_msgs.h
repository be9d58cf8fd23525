// Minimal stand-ins for the ROS message types used by the configuration tests, so that the
// configuration machinery can be checked without a ROS installation. Same member names and
// numeric types as the real messages (std_msgs, geometry_msgs, nav_msgs, sensor_msgs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace std_msgs {
struct Header {
  std::uint32_t seq = 0;
  double stamp = 0.0;
  std::string frame_id;
};
struct Float32 {
  float data = 0.0f;
};
struct Float64 {
  double data = 0.0;
};
struct Int32 {
  std::int32_t data = 0;
};
struct Float32MultiArray {
  std::vector<float> data;
};
}  // namespace std_msgs

namespace geometry_msgs {
struct Vector3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct Vector3Stamped {
  std_msgs::Header header;
  Vector3 vector;
};
struct Twist {
  Vector3 linear, angular;
};
struct TwistWithCovariance {
  Twist twist;
  double covariance[36] = {};
};
struct Point {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct Quaternion {
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
};
struct Pose {
  Point position;
  Quaternion orientation;
};
struct PoseWithCovariance {
  Pose pose;
  double covariance[36] = {};
};
}  // namespace geometry_msgs

namespace nav_msgs {
struct Odometry {
  std_msgs::Header header;
  std::string child_frame_id;
  geometry_msgs::PoseWithCovariance pose;
  geometry_msgs::TwistWithCovariance twist;
};
}  // namespace nav_msgs

namespace sensor_msgs {
struct Imu {
  std_msgs::Header header;
  geometry_msgs::Quaternion orientation;
  double orientation_covariance[9] = {};
  geometry_msgs::Vector3 angular_velocity;
  double angular_velocity_covariance[9] = {};
  geometry_msgs::Vector3 linear_acceleration;
  double linear_acceleration_covariance[9] = {};
};
struct MagneticField {
  std_msgs::Header header;
  geometry_msgs::Vector3 magnetic_field;
  double magnetic_field_covariance[9] = {};
};
}  // namespace sensor_msgs
