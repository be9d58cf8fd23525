// Every message an estimate is published as, built once from it, for the online node
// (FusionNode::publish) and the offline replay's output bag (BagReplay::writeBag): the entities
// of TOPICS_OUT, the ~state estimate, POSE_OUT's nav_msgs/Odometry (with TWIST_OUT's twist) or
// POSE_OUT_3D's (with TWIST_OUT_3D's twist) and its Euler angles, and ACCEL_OUT's acceleration. One
// writer, so that the node and the replay cannot drift apart; an output kind is added here (declare
// and write) and in the header macro that enables it (doc/design.md, "How to add an output kind").
#pragma once

#include <cstddef>
#include <string>
#include <utility>

#include "sf_filter/definition/node_description.hpp"
#include "sf_filter/io/estimate_messages.hpp"
#include "sf_filter/io/pose_3d_messages.hpp"

namespace sf_filter {

/// Where an output's topic lives: the node's namespace, or its private one (~state).
enum class OutputScope { Node, Private };

/// The frames of the outputs (the node's ~frame_id and ~child_frame_id, the replay's
/// --frame-id and --child-frame-id).
struct OutputFrames {
  std::string frameId = "odom";
  std::string childFrameId = "base_link";
};

class EstimateWriter {
 public:
  EstimateWriter(NodeDescription description, OutputFrames frames)
      : description_(std::move(description)), frames_(std::move(frames)) {}

  /// Calls `sink.template declare<Message>(k, topic, scope)` for every output k in the order
  /// write() numbers them (the node advertises its publishers here).
  template <class Sink>
  void declare(Sink& sink) const {
    std::size_t k = 0;
    for (const auto& out : description_.outputs) {
      sink.template declare<sf_msgs::OutputEntityStamped>(k++, out.first, OutputScope::Node);
    }
    sink.template declare<sf_msgs::StateEstimateStamped>(k++, "state", OutputScope::Private);
    if (description_.hasOdometry()) {
      sink.template declare<nav_msgs::Odometry>(k++, "odometry/filtered", OutputScope::Node);
    }
    if (description_.pose3d) {
      sink.template declare<geometry_msgs::Vector3Stamped>(k++, kEulerTopic, OutputScope::Node);
    }
    if (description_.accel) {
      sink.template declare<geometry_msgs::AccelWithCovarianceStamped>(k, "accel/filtered",
                                                                       OutputScope::Node);
    }
  }

  /// Calls `sink(k, topic, scope, message)` for every message of `e`, in declare()'s order.
  /// The robot's motion (odometry, acceleration) only with `measured`: the node's initial belief
  /// is no position of the robot before a real input (doc/filter_node.md).
  template <class Estimate, class Sink>
  void write(const Estimate& e, bool measured, Sink& sink) const {
    std::size_t k = 0;
    for (const auto& out : description_.outputs) {
      sink(k++, out.first, OutputScope::Node, makeOutputEntity(e, out.second, frames_.frameId));
    }
    sink(k++, "state", OutputScope::Private,
         makeStateEstimate(e, description_.method, frames_.frameId));
    if (description_.hasOdometry()) {
      if (measured) sink(k, "odometry/filtered", OutputScope::Node, odometry(e));
      ++k;
    }
    if (description_.pose3d) {
      if (measured) {
        sink(k, kEulerTopic, OutputScope::Node,
             makeEuler(e, description_.pose3d->quaternion, frames_.frameId));
      }
      ++k;
    }
    if (description_.accel && measured) {
      sink(k, "accel/filtered", OutputScope::Node,
           makeAccel(e, *description_.accel, frames_.childFrameId));
    }
  }

  /// How many outputs declare() declares (the smoothed ones are numbered after them).
  std::size_t count() const {
    return description_.outputs.size() + 1 + (description_.hasOdometry() ? 1 : 0) +
           (description_.pose3d ? 1 : 0) + (description_.accel ? 1 : 0);
  }

  /// The fixed-lag smoother's outputs (~smoothing_lag, the replay's --smooth-lag), numbered
  /// from count(): its belief on ~state/smoothed and, with a pose, odometry/smoothed (no tf: the
  /// smoothed pose is of a period in the past, the tf tree keeps the filtered one).
  template <class Sink>
  void declareSmoothed(Sink& sink) const {
    sink.template declare<sf_msgs::StateEstimateStamped>(count(), "state/smoothed",
                                                         OutputScope::Private);
    if (description_.hasOdometry()) {
      sink.template declare<nav_msgs::Odometry>(count() + 1, "odometry/smoothed",
                                                OutputScope::Node);
    }
  }

  /// Calls `sink` for the smoothed belief `e` (of the period that ends at e.time), in
  /// declareSmoothed()'s order; the pose only with `measured`, as write().
  template <class Estimate, class Sink>
  void writeSmoothed(const Estimate& e, bool measured, Sink& sink) const {
    sink(count(), "state/smoothed", OutputScope::Private,
         makeStateEstimate(e, description_.method, frames_.frameId));
    if (description_.hasOdometry() && measured) {
      sink(count() + 1, "odometry/smoothed", OutputScope::Node, odometry(e));
    }
  }

  const NodeDescription& description() const { return description_; }
  const OutputFrames& frames() const { return frames_; }

  /// POSE_OUT_3D's Euler angles (makeEuler), beside its odometry.
  static constexpr const char* kEulerTopic = "fused/euler";

 private:
  /// The odometry of `e`: POSE_OUT's planar one or POSE_OUT_3D's.
  template <class Estimate>
  nav_msgs::Odometry odometry(const Estimate& e) const {
    if (description_.pose3d) {
      return makeOdometry3d(e, *description_.pose3d, frames_.frameId, frames_.childFrameId,
                            description_.twist3d);
    }
    return makeOdometry(e, *description_.pose, frames_.frameId, frames_.childFrameId,
                        description_.twist);
  }

  NodeDescription description_;
  OutputFrames frames_;
};

}  // namespace sf_filter
