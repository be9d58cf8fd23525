// The extractor interface: how a DERIVED_INPUTS quantity is taken out of a message.
//
// An extractor kind is one class (one header in config/extractors/, one line in kinds.hpp):
//
//   class MyKind : public ExtractorState {       // one object per input, kept per run
//    public:
//     static constexpr std::array<std::string_view, K> kQuantities{"MY_QUANTITY", ...};
//     static constexpr std::array<bool, K> kAngle{true, ...};  // angle inputs (ANGLE_INPUTS)
//     static constexpr std::array<ExtractorParameter, P> kParameters{...};  // ~parameters
//     static constexpr bool kAbsoluteOnly;              // DIFFERENTIAL refused
//     template <class Member> static constexpr bool fits(int quantity);  // member type check
//     template <int Quantity, bool Differential, class Message, class Member>
//     std::optional<Sample> sample(const Message&, const Member&, const SampleContext&);
//   };
//
// `Member` is the TOPICS_IN entry's field (the member named there), `Message` the whole
// message (its header, its covariance arrays). sample() turns one message into the input's
// value and variance (nullopt: the header's R), or nothing (the message gives no value). The
// object is the kind's state (a previous pose, ...): the node and the replay each keep one per
// input in their InputState (definition/input_state.hpp), so every run starts anew. The node
// and the replay call every kind, and every other input, the same way
// (generated/input_extractors.hpp, DerivedInput and readInput).
// ROS-free and header-only.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sf_config {
namespace extractors {

/// A value and its variance (nullopt: the header's R).
struct Sample {
  double value;
  std::optional<double> variance;
  bool covarianceUnknown = false;  ///< the message's covariance was unknown (counted by the sink)
};

/// A private node parameter of an extractor kind (~name, a double in [minimum, maximum]).
struct ExtractorParameter {
  std::string_view name;
  double defaultValue;
  double minimum;
  double maximum;
  std::string_view meaning;  ///< e.g. "radians in [-pi, pi]", for the error message
};

/// The values of the kinds' parameters a node or replay was given (kept by its InputState; checked
/// against the ranges where they are read, io/extractor_parameters.hpp).
class ParameterValues {
 public:
  /// The value of `p`: the one given, else its default.
  double value(const ExtractorParameter& p) const {
    for (const auto& [name, v] : values_) {
      if (name == p.name) return v;
    }
    return p.defaultValue;
  }
  void set(std::string_view name, double v) {
    for (auto& [n, old] : values_) {
      if (n == name) {
        old = v;
        return;
      }
    }
    values_.emplace_back(std::string(name), v);
  }

 private:
  std::vector<std::pair<std::string, double>> values_;
};

/// What a reader hands an extractor besides the message.
struct SampleContext {
  std::optional<double> variance;  ///< the input's INPUT_COVARIANCE entry or variance field
  double stamp;                    ///< header stamp [s], NaN without a header
  const ParameterValues& parameters;
};

/// The state an extractor object may keep (the base of every kind; stateless kinds add none).
class ExtractorState {
 public:
  virtual ~ExtractorState() = default;
};

}  // namespace extractors
}  // namespace sf_config
