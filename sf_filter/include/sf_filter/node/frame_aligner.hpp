// The tf2 side of the spatial alignment of inputs (doc/spatial_alignment.md): owns the tf2
// buffer and listener, rotates the vectors of the aligned inputs into the base frame, waits
// for the transforms on the first message of each aligned input and drops, counts and reports
// what cannot be rotated. Created by the fusion node only when FRAME_ALIGNED_INPUTS is given.
//
// Private parameters: ~base_frame (default BASE_FRAME), ~transform_timeout (wall-clock seconds
// to wait for a transform on the first message of an aligned input, default 1).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <geometry_msgs/Vector3.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "sf_filter/io/ros_parameters.hpp"
#include "sf_filter/io/vector_rotation.hpp"

namespace sf_filter {

class FrameAligner {
 public:
  /// How often a failing input is reported, in wall-clock seconds.
  static constexpr double kWarningPeriod = 5.0;

  /// `inputs`: a name per measurement input ("topic field"), used in the log.
  FrameAligner(const ParameterSource& pnh, const std::string& defaultBaseFrame,
               std::vector<std::string> inputs)
      : listener_(buffer_), names_(std::move(inputs)), states_(names_.size()) {
    baseFrame_ = detail::frameParameter(pnh, "base_frame", defaultBaseFrame);
    readScalarParameter(pnh, "transform_timeout", timeout_);
    if (!(timeout_ >= 0.0 && timeout_ <= kMaxTransformTimeoutSeconds)) {
      throw ParameterOverrideError(
          "parameter ~transform_timeout: expected 0 .. 60 s (it blocks the node's callbacks "
          "while it waits)");
    }
    ROS_INFO("spatial alignment: vectors rotated into frame '%s', transform timeout %.2f s",
             baseFrame_.c_str(), timeout_);
  }

  FrameAligner(const FrameAligner&) = delete;
  FrameAligner& operator=(const FrameAligner&) = delete;

  /// Component `axis` (0 x, 1 y, 2 z) of `vector`, given in `frame` at `stamp`, rotated into
  /// the base frame; nullopt if no transform is known (the value is then dropped and counted).
  /// On the first message of an input the transform may still be on its way: it waits up to
  /// ~transform_timeout for it (blocking the node's callbacks, once per input), unless tf
  /// already has the frames at a later time (transformMayStillArrive).
  std::optional<double> align(std::size_t input, const std::string& frame, const ros::Time& stamp,
                              const std::array<double, 3>& vector, int axis) {
    State& s = states_.at(input);
    geometry_msgs::Vector3 v;
    v.x = vector[0];
    v.y = vector[1];
    v.z = vector[2];
    std::string error;
    auto rotated = rotateVector(buffer_, v, frame, baseFrame_, stamp, &error);
    if (!rotated && !s.seen) {
      const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_);
      // Not once tf has the frames after the value's stamp: that wait lasted the whole
      // timeout, blocking the node's callbacks while its /clock ran on, and made the values
      // queued behind it late (the Husky recording's first IMU value, stamped before its
      // first transforms, doc/real_robot.md); the replay drops such a value at once.
      while (!rotated && ros::ok() && ros::WallTime::now() < deadline &&
             transformMayStillArrive(buffer_, baseFrame_, frame, stamp)) {
        ros::WallDuration(0.01).sleep();
        rotated = rotateVector(buffer_, v, frame, baseFrame_, stamp, &error);
      }
    }
    if (!rotated) {
      drop(input, frame, error);
      return std::nullopt;
    }
    if (!s.seen || s.failing || frame != s.frame) {
      ROS_INFO("input %zu (%s): rotating from frame '%s' into '%s'", input, names_[input].c_str(),
               frame.c_str(), baseFrame_.c_str());
    }
    s.seen = true;
    s.failing = false;
    s.frame = frame;
    return axis == 0 ? rotated->x : axis == 1 ? rotated->y : rotated->z;
  }

  /// Values of `input` dropped because they could not be rotated.
  std::uint64_t dropped(std::size_t input) const { return states_.at(input).dropped; }
  /// Why the last value of `input` was dropped (empty if none was).
  std::string dropReason(std::size_t input) const {
    const State& s = states_.at(input);
    if (s.dropped == 0) return "";
    return "no transform from frame '" + s.failedFrame + "' into '" + baseFrame_ +
           "': " + s.lastError;
  }
  const std::string& baseFrame() const { return baseFrame_; }
  double transformTimeout() const { return timeout_; }

 private:
  struct State {
    bool seen = false;     ///< a first message arrived (the transform was waited for)
    bool failing = false;  ///< the last value was dropped
    std::string frame;     ///< frame of the last rotated value
    std::uint64_t dropped = 0;
    std::string failedFrame, lastError;  ///< of the last dropped value
    ros::WallTime lastWarning;
  };

  void drop(std::size_t input, const std::string& frame, const std::string& error) {
    State& s = states_[input];
    s.seen = true;
    s.failing = true;
    ++s.dropped;
    s.failedFrame = frame;
    s.lastError = error;
    const ros::WallTime now = ros::WallTime::now();
    if (s.dropped == 1 || (now - s.lastWarning).toSec() >= kWarningPeriod) {
      s.lastWarning = now;
      ROS_WARN("input %zu (%s): no transform from frame '%s' into '%s', value dropped (%lu so "
               "far): %s",
               input, names_[input].c_str(), frame.c_str(), baseFrame_.c_str(),
               static_cast<unsigned long>(s.dropped), error.c_str());
    }
  }

  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  std::vector<std::string> names_;
  std::vector<State> states_;
  std::string baseFrame_;
  double timeout_ = 1.0;
};

}  // namespace sf_filter
