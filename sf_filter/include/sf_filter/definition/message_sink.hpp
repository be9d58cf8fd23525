// How the code generated from a configuration header reads messages without ROS's node
// machinery: the prebuilt node and replay receive each message of a topic as serialized
// bytes (roscpp's ShapeShifter online, rosbag offline) and hand them to the topic's reader,
// which deserializes its own message type and gives every configured field to a MessageSink.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <sf_estimation/types.hpp>

namespace sf_filter {

class InputState;  // definition/input_state.hpp: what reading keeps between messages

/// Receives what a topic reader takes out of one message.
class MessageSink {
 public:
  virtual ~MessageSink() = default;
  /// A value of measurement input `input` received at `now` with the variance its message
  /// carried (if any) and its header stamp in seconds (NaN: the message has no header).
  virtual void measurement(estimation::Index input, double now, double value,
                           std::optional<double> variance, double stamp) = 0;
  /// The values of `count` inputs read from one message with the message's covariance block of
  /// them (row-major count x count; INPUT_COVARIANCE_BLOCK). By default each value alone with
  /// its variance; the node and the replay hand the block to the fusion core.
  virtual void measurementBlock(const estimation::Index* inputs, const double* values,
                                const double* covariance, int count, double now, double stamp) {
    for (int k = 0; k < count; ++k) {
      measurement(inputs[k], now, values[k], covariance[k * count + k], stamp);
    }
  }
  virtual void control(estimation::Index control, double value) = 0;
  /// Component `axis` (0 x, 1 y, 2 z) of `vector`, given in `frame` at the stamp
  /// (sec, nsec), rotated into the node's base frame (FRAME_ALIGNED_INPUTS); nullopt when it
  /// cannot be rotated (dropped and counted by the sink).
  virtual std::optional<double> rotated(estimation::Index input, const std::string& frame,
                                        std::uint32_t sec, std::uint32_t nsec,
                                        const std::array<double, 3>& vector, int axis) = 0;
};

/// One subscribed topic: its message type and the reader of its serialized messages.
struct TopicReader {
  std::string topic;
  std::string datatype;  ///< e.g. "sensor_msgs/Imu"
  std::string md5sum;
  std::string definition;  ///< the full message definition (rosbag connection header)
  bool controls = false;   ///< the topic feeds TOPICS_IN_CTRL, not TOPICS_IN
  /// Deserializes one message and hands every input read from it to `sink`, the extractors
  /// keeping their state in `state`. Throws std::runtime_error when the bytes are not a
  /// message of this type.
  void (*read)(const std::uint8_t* data, std::uint32_t size, MessageSink& sink, InputState& state,
               double now) = nullptr;
};

/// Why two configured topics cannot both resolve (remaps applied) onto topic `resolved`, read
/// as message types `earlier` and `later`: the type message, empty when the types are the
/// same (then both read every message). Without the check a remap of odom onto imu/data made
/// the replay read imu/data as Imu only and the odometry receive nothing. Compiled once in
/// the core library (sf_filter/src/definition/node_definition.cpp), for the node and the
/// replay alike.
std::string topicTypeClash(const std::string& resolved, const std::string& earlier,
                           const std::string& later);

/// readers.push_back(reader), compiled once in the core library
/// (sf_filter/src/definition/node_definition.cpp) instead of in every header's unit.
void appendTopicReader(std::vector<TopicReader>& readers, TopicReader reader);

}  // namespace sf_filter
