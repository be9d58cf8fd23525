// Spatial alignment (FRAME_ALIGNED_INPUTS) in the offline replay: the online node's
// FrameAligner without a ROS master. The transforms come from the bag itself, /tf_static and
// /tf, fed by BagReplay into a tf2::BufferCore the way a tf2 listener would have received
// them while the bag played: the static ones before anything else (rosbag play latches
// them), the dynamic ones in recorded order. Vectors are rotated by the same
// rotateVector() as online; a value that cannot be rotated is dropped and counted.
#pragma once

#include <console_bridge/console.h>

#include <array>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>

#include "sf_filter/io/vector_rotation.hpp"

namespace sf_filter {

namespace replay_detail {

/// While it lives, tf2's TF_REPEATED_DATA warnings (a dynamic transform with the stamp of one
/// its frame already has: overlapping bags, or a transform recorded twice) are counted in
/// `count` instead of printed, one line each (1000-3000 lines for two overlapping bags); tf2's
/// other messages go to the handler that was in place.
class RepeatedDataCounter final : public console_bridge::OutputHandler {
 public:
  explicit RepeatedDataCounter(std::uint64_t& count)
      : count_(count), previous_(console_bridge::getOutputHandler()) {
    console_bridge::useOutputHandler(this);
  }
  RepeatedDataCounter(const RepeatedDataCounter&) = delete;
  RepeatedDataCounter& operator=(const RepeatedDataCounter&) = delete;
  ~RepeatedDataCounter() override { console_bridge::useOutputHandler(previous_); }

  void log(const std::string& text, console_bridge::LogLevel level, const char* filename,
           int line) override {
    if (text.rfind("TF_REPEATED_DATA", 0) == 0) {
      ++count_;
    } else if (previous_ != nullptr) {
      previous_->log(text, level, filename, line);
    }
  }

 private:
  std::uint64_t& count_;
  console_bridge::OutputHandler* previous_;
};

}  // namespace replay_detail

class ReplayFrameAligner {
 public:
  /// Authority recorded with the bag's transforms (tf2 keeps one per transform).
  static constexpr const char* kAuthority = "bag";

  /// `inputs`: a name per measurement input ("topic member"), used in the messages.
  ReplayFrameAligner(std::string baseFrame, std::vector<std::string> inputs)
      : baseFrame_(std::move(baseFrame)), names_(std::move(inputs)), dropped_(names_.size(), 0) {}

  ReplayFrameAligner(const ReplayFrameAligner&) = delete;
  ReplayFrameAligner& operator=(const ReplayFrameAligner&) = delete;

  /// The transforms of one /tf (isStatic false) or /tf_static message. A transform tf2
  /// refuses (empty or equal frames, NaN, a stamp its frame has already) is counted and
  /// otherwise ignored, as a listener does; repeated stamps are counted apart, not logged.
  void addTransforms(const tf2_msgs::TFMessage& msg, bool isStatic) {
    const replay_detail::RepeatedDataCounter counter(repeatedTransforms_);
    for (const auto& t : msg.transforms) {
      try {
        if (buffer_.setTransform(t, kAuthority, isStatic)) {
          ++transforms_;
        } else {
          ++rejectedTransforms_;
        }
      } catch (const tf2::TransformException&) {
        ++rejectedTransforms_;
      }
    }
  }

  /// Component `axis` (0 x, 1 y, 2 z) of `vector`, given in `frame` at `stamp`, rotated into
  /// the base frame; nullopt (value dropped, counted, the first drop per input reported on
  /// stderr) when the bag's transforms do not connect the frames at that time.
  std::optional<double> align(std::size_t input, const std::string& frame, const ros::Time& stamp,
                              const std::array<double, 3>& vector, int axis) {
    geometry_msgs::Vector3 v;
    v.x = vector[0];
    v.y = vector[1];
    v.z = vector[2];
    std::string error;
    const auto rotated = rotateVector(buffer_, v, frame, baseFrame_, stamp, &error);
    if (!rotated) {
      if (dropped_.at(input)++ == 0) {
        std::cerr << "input " << input << " (" << names_.at(input) << "): no transform from frame '"
                  << frame << "' into '" << baseFrame_ << "' in the bag's /tf_static and /tf at "
                  << stamp << ", value dropped (counted in the summary): " << error << std::endl;
      }
      return std::nullopt;
    }
    return axis == 0 ? rotated->x : axis == 1 ? rotated->y : rotated->z;
  }

  /// Values of `input` dropped because they could not be rotated.
  std::uint64_t dropped(std::size_t input) const { return dropped_.at(input); }
  std::uint64_t droppedTotal() const {
    std::uint64_t sum = 0;
    for (std::uint64_t d : dropped_) sum += d;
    return sum;
  }
  /// Transforms taken from the bag, and those tf2 refused.
  std::uint64_t transforms() const { return transforms_; }
  std::uint64_t rejectedTransforms() const { return rejectedTransforms_; }
  /// Of those, the ones tf2 ignored for a stamp their frame had already (TF_REPEATED_DATA).
  std::uint64_t repeatedTransforms() const { return repeatedTransforms_; }
  const std::string& baseFrame() const { return baseFrame_; }
  const tf2::BufferCore& buffer() const { return buffer_; }

 private:
  tf2::BufferCore buffer_;  // default cache of 10 s of dynamic transforms, as a listener's
  std::string baseFrame_;
  std::vector<std::string> names_;
  std::vector<std::uint64_t> dropped_;
  std::uint64_t transforms_ = 0;
  std::uint64_t rejectedTransforms_ = 0;
  std::uint64_t repeatedTransforms_ = 0;
};

}  // namespace sf_filter
