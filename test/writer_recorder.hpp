// EstimateWriter's sink in the tests (test/estimate_writer_test.cpp,
// test/pose_3d_output_test.cpp): what the writer declares and writes, in order, and the
// messages of the types Kept; and a hand-made estimate in the fields the writer reads.
#pragma once

#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "sf_filter/io/estimate_writer.hpp"

namespace sf_test {

struct Estimate {
  double time = 0.0;
  Eigen::VectorXd state;
  Eigen::MatrixXd covariance;
  long presentInputs = 1;
};

template <class... Kept>
struct WriterRecorder {
  std::vector<std::string> declared, written;
  std::tuple<std::vector<Kept>...> messages;

  /// The written messages of type Message, in order.
  template <class Message>
  const std::vector<Message>& of() const {
    return std::get<std::vector<Message>>(messages);
  }

  template <class Message>
  void declare(std::size_t k, const std::string& topic, sf_filter::OutputScope scope) {
    declared.push_back(std::to_string(k) + " " + topic +
                       (scope == sf_filter::OutputScope::Private ? " private" : ""));
  }
  template <class Message>
  void operator()(std::size_t k, const std::string& topic, sf_filter::OutputScope,
                  const Message& m) {
    written.push_back(std::to_string(k) + " " + topic);
    if constexpr ((std::is_same_v<Message, Kept> || ...)) {
      std::get<std::vector<Message>>(messages).push_back(m);
    }
  }
};

}  // namespace sf_test
