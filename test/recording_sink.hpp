// Test helpers for the code a configuration header generates: a MessageSink that records what
// the topic readers hand over, and feeding a reader one serialized message
// (test/derived_inputs_test.cpp, test/gps_input_test.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/serialization.h>

#include "sf_filter/definition/input_state.hpp"
#include "sf_filter/definition/message_sink.hpp"
#include "sf_filter/definition/node_definition.hpp"

namespace sf_test {

struct Value {
  long input;
  double value;
  std::optional<double> variance;
  double stamp;
};

/// The inputs of one measurementBlock and their covariance (row-major).
struct Block {
  std::vector<long> inputs;
  std::vector<double> covariance;
};

/// Records what the readers hand over.
class RecordingSink final : public sf_filter::MessageSink {
 public:
  void measurement(estimation::Index input, double, double value, std::optional<double> variance,
                   double stamp) override {
    values.push_back({static_cast<long>(input), value, variance, stamp});
  }
  /// Records the block, then its values alone with their variances (MessageSink's default).
  void measurementBlock(const estimation::Index* inputs, const double* values,
                        const double* covariance, int count, double now, double stamp) override {
    Block b;
    for (int r = 0; r < count; ++r) {
      b.inputs.push_back(static_cast<long>(inputs[r]));
      for (int c = 0; c < count; ++c) b.covariance.push_back(covariance[r * count + c]);
    }
    blocks.push_back(b);
    MessageSink::measurementBlock(inputs, values, covariance, count, now, stamp);
  }
  void control(estimation::Index, double) override {}
  std::optional<double> rotated(estimation::Index, const std::string&, std::uint32_t, std::uint32_t,
                                const std::array<double, 3>&, int) override {
    return std::nullopt;
  }
  std::vector<Value> values;
  std::vector<Block> blocks;
  sf_filter::InputState state;  ///< what the readers keep between messages
};

template <class M>
std::vector<std::uint8_t> serialized(const M& message) {
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(message));
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, message);
  return bytes;
}

inline const sf_filter::TopicReader& readerOf(const sf_filter::NodeDefinition& d,
                                              const std::string& topic) {
  for (const auto& r : d.topics) {
    if (r.topic == topic) return r;
  }
  throw std::runtime_error("no reader for " + topic);
}

/// Hands `message`, serialized, to `reader` as received at `now` (a Sink with its InputState
/// `state`).
template <class M, class Sink>
void feed(const sf_filter::TopicReader& reader, const M& message, Sink& sink, double now) {
  const std::vector<std::uint8_t> bytes = serialized(message);
  reader.read(bytes.data(), static_cast<std::uint32_t>(bytes.size()), sink, sink.state, now);
}

}  // namespace sf_test
