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

#include "sf_filter/definition/message_sink.hpp"
#include "sf_filter/definition/node_definition.hpp"

namespace sf_test {

struct Value {
  long input;
  double value;
  std::optional<double> variance;
  double stamp;
};

/// Records what the readers hand over.
class RecordingSink final : public sf_filter::MessageSink {
 public:
  void measurement(estimation::Index input, double, double value, std::optional<double> variance,
                   double stamp) override {
    values.push_back({static_cast<long>(input), value, variance, stamp});
  }
  void control(estimation::Index, double) override {}
  std::optional<double> rotated(estimation::Index, const std::string&, std::uint32_t, std::uint32_t,
                                const std::array<double, 3>&, int) override {
    return std::nullopt;
  }
  std::vector<Value> values;
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

/// Hands `message`, serialized, to `reader` as received at `now`.
template <class M>
void feed(const sf_filter::TopicReader& reader, const M& message, sf_filter::MessageSink& sink,
          double now) {
  const std::vector<std::uint8_t> bytes = serialized(message);
  reader.read(bytes.data(), static_cast<std::uint32_t>(bytes.size()), sink, now);
}

}  // namespace sf_test
