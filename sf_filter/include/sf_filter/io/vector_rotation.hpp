// Rotating a free vector (angular velocity, acceleration, magnetic field, ...) from the frame a
// sensor reports it in into another frame with tf2: rotation only, the translation between
// the frames does not apply to such vectors. Used by the fusion node's spatial alignment
// (frame_aligner.hpp); independent of the configuration.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Vector3.h>
#include <ros/time.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace sf_filter {

/// The transform taking data in `source` to `target`, looked up at `stamp`. If that fails, the
/// latest transform is used only if the frames are connected by static transforms alone (tf2
/// reports stamp 0 for such a chain), which hold at every time. Otherwise nullopt, with the
/// tf2 error of the lookup at `stamp` in *error: a transform is never guessed.
inline std::optional<geometry_msgs::TransformStamped> lookupRotation(const tf2::BufferCore& buffer,
                                                                     const std::string& target,
                                                                     const std::string& source,
                                                                     const ros::Time& stamp,
                                                                     std::string* error = nullptr) {
  try {
    return buffer.lookupTransform(target, source, stamp);
  } catch (const tf2::TransformException& atStamp) {
    try {
      geometry_msgs::TransformStamped latest = buffer.lookupTransform(target, source, ros::Time(0));
      if (latest.header.stamp.isZero()) return latest;  // static: valid at any time
    } catch (const tf2::TransformException&) {
    }
    if (error) *error = atStamp.what();
    return std::nullopt;
  }
}

/// Whether a transform taking `source` to `target` at `stamp` may still arrive, once a lookup
/// at `stamp` failed: yes while the frames are not connected or tf's newest common time of
/// their chain is older than `stamp`; no when tf connects them at a later time (a transform
/// at a stamp before the oldest one held is not filled in later: each publisher sends its
/// transforms in stamp order) and for static chains, which hold at every time.
inline bool transformMayStillArrive(const tf2::BufferCore& buffer, const std::string& target,
                                    const std::string& source, const ros::Time& stamp) {
  try {
    const ros::Time latest = buffer.lookupTransform(target, source, ros::Time(0)).header.stamp;
    return !latest.isZero() && latest < stamp;
  } catch (const tf2::TransformException&) {
    return true;
  }
}

/// `vector`, given in frame `source`, expressed in frame `target` (see lookupRotation()).
inline std::optional<geometry_msgs::Vector3> rotateVector(
    const tf2::BufferCore& buffer, const geometry_msgs::Vector3& vector, const std::string& source,
    const std::string& target, const ros::Time& stamp, std::string* error = nullptr) {
  const auto transform = lookupRotation(buffer, target, source, stamp, error);
  if (!transform) return std::nullopt;
  geometry_msgs::Vector3 rotated;
  tf2::doTransform(vector, rotated, *transform);  // the Vector3 overload ignores translation
  return rotated;
}

}  // namespace sf_filter
