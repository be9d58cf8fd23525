// The ROS messages an estimate is published as, shared by the online node and the offline
// bag replay so that both write exactly the same thing.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <geometry_msgs/AccelWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <tf2/LinearMath/Quaternion.h>
#include <Eigen/Core>

#include <sf_msgs/OutputEntityStamped.h>
#include <sf_msgs/StateEstimateStamped.h>

namespace sf_filter {

/// A message of type Message stamped with the estimate's time, in `frame`.
template <class Message, class Estimate>
Message stampedAt(const Estimate& e, const std::string& frame) {
  Message msg;
  msg.header.stamp = ros::Time(e.time);
  msg.header.frame_id = frame;
  return msg;
}

template <class Estimate>
sf_msgs::OutputEntityStamped makeOutputEntity(const Estimate& e, int index,
                                              const std::string& frame) {
  auto msg = stampedAt<sf_msgs::OutputEntityStamped>(e, frame);
  msg.value = e.state(index);
  msg.variance = e.covariance(index, index);
  return msg;
}

template <class Estimate>
sf_msgs::StateEstimateStamped makeStateEstimate(const Estimate& e, const std::string& method,
                                                const std::string& frame) {
  const Eigen::Index n = e.state.size();
  auto msg = stampedAt<sf_msgs::StateEstimateStamped>(e, frame);
  msg.method = method;
  msg.state.assign(e.state.data(), e.state.data() + n);
  msg.covariance.resize(static_cast<std::size_t>(n * n));
  for (Eigen::Index r = 0; r < n; ++r) {
    for (Eigen::Index c = 0; c < n; ++c) {
      msg.covariance[static_cast<std::size_t>(r * n + c)] = e.covariance(r, c);
    }
  }
  msg.present_inputs = static_cast<std::uint32_t>(e.presentInputs);
  return msg;
}

/// Variance of the Odometry's pose and twist components the state does not hold.
constexpr double kUnknownVariance = 1e6;

/// Planar pose (x, y, heading state indices) as nav_msgs/Odometry. The covariance block of
/// (x, y, yaw) comes from the state; z, roll and pitch are marked unknown (1e6). With `twist`
/// (TWIST_OUT: v, omega state indices) twist.linear.x, twist.angular.z and their covariance
/// block come from the state; every other twist component, and all of them without `twist`,
/// is zero with the variance 1e6 (unknown, never a certain zero).
template <class Estimate>
nav_msgs::Odometry makeOdometry(const Estimate& e, const std::array<int, 3>& pose,
                                const std::string& frame, const std::string& childFrame,
                                const std::optional<std::array<int, 2>>& twist = std::nullopt) {
  const auto [ix, iy, ith] = pose;
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, e.state(ith));
  auto odom = stampedAt<nav_msgs::Odometry>(e, frame);
  odom.child_frame_id = childFrame;
  odom.pose.pose.position.x = e.state(ix);
  odom.pose.pose.position.y = e.state(iy);
  odom.pose.pose.orientation.x = q.x();
  odom.pose.pose.orientation.y = q.y();
  odom.pose.pose.orientation.z = q.z();
  odom.pose.pose.orientation.w = q.w();
  const std::array<int, 3> index = {ix, iy, ith};
  const std::array<int, 3> slot = {0, 1, 5};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      odom.pose.covariance[static_cast<std::size_t>(slot[r] * 6 + slot[c])] =
          e.covariance(index[r], index[c]);
    }
  }
  for (int k : {2, 3, 4}) odom.pose.covariance[static_cast<std::size_t>(k * 7)] = kUnknownVariance;
  for (int k = 0; k < 6; ++k)
    odom.twist.covariance[static_cast<std::size_t>(k * 7)] = kUnknownVariance;
  if (twist) {
    const std::array<int, 2> tindex = *twist;
    const std::array<int, 2> tslot = {0, 5};  // linear.x, angular.z
    odom.twist.twist.linear.x = e.state(tindex[0]);
    odom.twist.twist.angular.z = e.state(tindex[1]);
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        odom.twist.covariance[static_cast<std::size_t>(tslot[r] * 6 + tslot[c])] =
            e.covariance(tindex[r], tindex[c]);
      }
    }
  }
  return odom;
}

/// ACCEL_OUT (a state index) as geometry_msgs/AccelWithCovarianceStamped in the robot's frame
/// `childFrame`, as robot_localization's accel/filtered: linear.x and its variance from the
/// state; every other component is zero with the variance 1e6 (unknown, never a certain zero).
template <class Estimate>
geometry_msgs::AccelWithCovarianceStamped makeAccel(const Estimate& e, int a,
                                                    const std::string& childFrame) {
  auto msg = stampedAt<geometry_msgs::AccelWithCovarianceStamped>(e, childFrame);
  msg.accel.accel.linear.x = e.state(a);
  for (int k = 0; k < 6; ++k)
    msg.accel.covariance[static_cast<std::size_t>(k * 7)] = kUnknownVariance;
  msg.accel.covariance[0] = e.covariance(a, a);
  return msg;
}

}  // namespace sf_filter
