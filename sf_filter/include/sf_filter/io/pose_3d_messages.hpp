// The messages of a 3D pose (POSE_OUT_3D, TWIST_OUT_3D; doc/filter_node.md, "Published
// topics"): nav_msgs/Odometry with the full 6x6 pose and twist covariances, and the Euler
// angles as geometry_msgs/Vector3Stamped. Shared by the node and the replay through
// EstimateWriter.
//
// The orientation block of the pose covariance is the covariance of a rotation vector about
// the fixed axes of the odom frame (header.frame_id), as nav_msgs/Odometry and
// robot_localization give it: the true orientation is exp(phi) q with phi ~ N(0, block). It is
// the state's own error (QUATERNION_STATES' So3WorldBlock perturbs on the left, about the
// world's axes), read from the quaternion's x, y, z rows of the n x n covariance, cross terms
// with the position included.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include "sf_filter/definition/node_description.hpp"
#include "sf_filter/io/estimate_messages.hpp"

namespace sf_filter {

/// The covariance of the state variables `index` as a row-major 6x6 message block; an index
/// -1 is a component the state does not hold: variance 1e6 (unknown), uncorrelated.
template <class Estimate>
boost::array<double, 36> covariance6(const Estimate& e, const std::array<int, 6>& index) {
  boost::array<double, 36> block{};
  for (std::size_t r = 0; r < 6; ++r) {
    for (std::size_t c = 0; c < 6; ++c) {
      const bool known = index[r] >= 0 && index[c] >= 0;
      block[r * 6 + c] =
          known ? e.covariance(index[r], index[c]) : (r == c ? kUnknownVariance : 0.0);
    }
  }
  return block;
}

/// The state's value at `index`, 0 for -1 (a component the state does not hold).
template <class Estimate>
double valueAt(const Estimate& e, int index) {
  return index >= 0 ? e.state(index) : 0.0;
}

/// POSE_OUT_3D as nav_msgs/Odometry: the position, the quaternion as stored (w, x, y, z) and
/// the 6x6 pose covariance (x, y, z, then the rotation vector about the odom frame's x, y, z);
/// with `twist` (TWIST_OUT_3D) the body-frame linear and angular velocity and their 6x6
/// covariance, else a zero twist of variance 1e6.
template <class Estimate>
nav_msgs::Odometry makeOdometry3d(const Estimate& e, const Pose3dIndices& pose,
                                  const std::string& frame, const std::string& childFrame,
                                  const std::optional<std::array<int, 6>>& twist) {
  const auto [ix, iy, iz] = pose.position;
  const int q = pose.quaternion;
  auto odom = stampedAt<nav_msgs::Odometry>(e, frame);
  odom.child_frame_id = childFrame;
  odom.pose.pose.position.x = valueAt(e, ix);
  odom.pose.pose.position.y = valueAt(e, iy);
  odom.pose.pose.position.z = valueAt(e, iz);
  odom.pose.pose.orientation.w = e.state(q);
  odom.pose.pose.orientation.x = e.state(q + 1);
  odom.pose.pose.orientation.y = e.state(q + 2);
  odom.pose.pose.orientation.z = e.state(q + 3);
  odom.pose.covariance = covariance6(e, {ix, iy, iz, q + 1, q + 2, q + 3});
  const std::array<int, 6> t = twist.value_or(std::array<int, 6>{-1, -1, -1, -1, -1, -1});
  auto& v = odom.twist.twist;
  v.linear.x = valueAt(e, t[0]);
  v.linear.y = valueAt(e, t[1]);
  v.linear.z = valueAt(e, t[2]);
  v.angular.x = valueAt(e, t[3]);
  v.angular.y = valueAt(e, t[4]);
  v.angular.z = valueAt(e, t[5]);
  odom.twist.covariance = covariance6(e, t);
  return odom;
}

/// The orientation of the quaternion at `q` (w, x, y, z) as roll, pitch and yaw [rad] in
/// vector x, y, z: Z-Y-X angles about the fixed axes of `frame` (tf2's getRPY; yaw and roll
/// in [-pi, pi], pitch in [-pi/2, pi/2]).
template <class Estimate>
geometry_msgs::Vector3Stamped makeEuler(const Estimate& e, int q, const std::string& frame) {
  auto msg = stampedAt<geometry_msgs::Vector3Stamped>(e, frame);
  const tf2::Quaternion rotation(e.state(q + 1), e.state(q + 2), e.state(q + 3), e.state(q));
  tf2::Matrix3x3(rotation).getRPY(msg.vector.x, msg.vector.y, msg.vector.z);
  return msg;
}

}  // namespace sf_filter
