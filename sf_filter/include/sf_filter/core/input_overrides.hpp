// Run-time changes of the per-input options that the configuration header set: the node's
// private parameters (~input_alignment, ~input_gate, ~align_by_stamp, ~input_timeout,
// ~input_range, ~max_future_stamp) and the replay's options (--align, --gate,
// --align-by-stamp) go through these checks, so both refuse the same mistakes. Each throws
// std::invalid_argument saying what is wrong with the value; the caller adds which parameter or
// option it came from.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sf_filter/core/alignment/alignment_policy.hpp"
#include "sf_filter/core/input_options.hpp"

namespace sf_filter {

/// What the inputs can do, from the configuration.
struct InputCapabilities {
  bool canPredict = false;         ///< the method predicts its measurement (gates, FILL)
  std::vector<bool> hasStamp;      ///< per input: its message type has header.stamp
  std::vector<std::string> names;  ///< per input, for messages, e.g. "wheel data"
  /// Per input, the name overrides may give instead of its index: its INPUTS record name
  /// (doc/configuration.md); empty for a header in the thesis syntax (TOPICS_IN).
  std::vector<std::string> keys;

  std::string describe(std::size_t input) const {
    return "input " + std::to_string(input) +
           (input < names.size() ? " (" + names[input] + ")" : std::string());
  }
};

/// The input an override names: its index ("2") or its INPUTS record name ("gyro_z"). Throws
/// std::invalid_argument for anything else, listing the names there are.
inline long inputIndexOf(const std::string& text, const InputCapabilities& can) {
  for (std::size_t i = 0; i < can.keys.size(); ++i) {
    if (!can.keys[i].empty() && can.keys[i] == text) return static_cast<long>(i);
  }
  std::size_t used = 0;
  long index = -1;
  try {
    index = std::stol(text, &used);
  } catch (const std::logic_error&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    std::string known;
    for (const std::string& key : can.keys) known += (known.empty() ? "" : ", ") + key;
    throw std::invalid_argument(
        "input '" + text + "' is neither an input index nor " +
        (known.empty() ? std::string("an input name (this header has no INPUTS records)")
                       : "one of the input names " + known));
  }
  return index;
}

namespace override_detail {
inline void checkIndex(const std::vector<InputOptions>& inputs, long input) {
  if (input < 0 || input >= static_cast<long>(inputs.size())) {
    throw std::invalid_argument("input index " + std::to_string(input) +
                                " is out of range, expected 0 to " +
                                std::to_string(static_cast<long>(inputs.size()) - 1));
  }
}

/// `value` for a setting that is a finite number > 0 or 0 for "off" (returned as infinity);
/// anything else is refused with `rule` (what the setting must be) naming the input.
inline double positiveOrOff(const std::vector<InputOptions>& inputs, long input, double value,
                            const InputCapabilities& can, const char* rule) {
  checkIndex(inputs, input);
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(can.describe(static_cast<std::size_t>(input)) + ": " + rule +
                                ", got " + std::to_string(value));
  }
  return value > 0.0 ? value : std::numeric_limits<double>::infinity();
}

/// Refuses `what` (a FILL policy, a gate) for a method without a predicted measurement.
inline void requirePrediction(const InputCapabilities& can, long input, const std::string& what,
                              const char* hint = "") {
  if (!can.canPredict) {
    throw std::invalid_argument(can.describe(static_cast<std::size_t>(input)) + ": " + what +
                                " needs the predicted measurement of the filter, which this "
                                "method does not give" +
                                hint);
  }
}
}  // namespace override_detail

/// Sets input `input`'s policy from its text form (alignment_policy.hpp).
inline void overrideAlignment(std::vector<InputOptions>& inputs, long input,
                              const std::string& text, const InputCapabilities& can) {
  override_detail::checkIndex(inputs, input);
  const AlignmentPolicy policy = parseAlignmentPolicy(text);
  if (policy.needsPrediction()) override_detail::requirePrediction(can, input, "FILL");
  inputs[static_cast<std::size_t>(input)].alignment = policy;
}

/// Sets input `input`'s gate: a chi-square threshold > 0, or 0 for no gate.
inline void overrideGate(std::vector<InputOptions>& inputs, long input, double threshold,
                         const InputCapabilities& can) {
  const double gate = override_detail::positiveOrOff(
      inputs, input, threshold, can,
      "gate threshold must be a finite number > 0, or 0 for no gate");
  if (std::isfinite(gate))
    override_detail::requirePrediction(can, input, "a gate", " (0: no gate)");
  inputs[static_cast<std::size_t>(input)].gateThreshold = gate;
}

/// Aligns input `input` by header stamp (true) or arrival time (false).
inline void overrideAlignByStamp(std::vector<InputOptions>& inputs, long input, bool byStamp,
                                 const InputCapabilities& can) {
  override_detail::checkIndex(inputs, input);
  const auto i = static_cast<std::size_t>(input);
  if (byStamp && !(i < can.hasStamp.size() && can.hasStamp[i])) {
    throw std::invalid_argument(can.describe(i) +
                                ": its message type has no header.stamp to align by");
  }
  inputs[i].alignByStamp = byStamp;
}

/// Sets input `input`'s sensor timeout: a finite number of ms > 0, or 0 for no timeout.
inline void overrideTimeout(std::vector<InputOptions>& inputs, long input, double timeoutMs,
                            const InputCapabilities& can) {
  const double timeout = override_detail::positiveOrOff(
      inputs, input, timeoutMs, can,
      "timeout must be a finite number of ms > 0, or 0 for no timeout");
  inputs[static_cast<std::size_t>(input)].timeout = timeout / 1000.0;  // infinity stays off
}

/// Sets input `input`'s plausible range [minimum, maximum] (infinite bounds allowed; both
/// infinite: no range). minimum < maximum.
inline void overrideRange(std::vector<InputOptions>& inputs, long input, double minimum,
                          double maximum, const InputCapabilities& can) {
  override_detail::checkIndex(inputs, input);
  if (std::isnan(minimum) || std::isnan(maximum) || !(minimum < maximum)) {
    throw std::invalid_argument(can.describe(static_cast<std::size_t>(input)) +
                                ": plausible range needs minimum < maximum, got [" +
                                std::to_string(minimum) + ", " + std::to_string(maximum) + "]");
  }
  inputs[static_cast<std::size_t>(input)].minimum = minimum;
  inputs[static_cast<std::size_t>(input)].maximum = maximum;
}

/// The node's and the replay's tolerance for stamps ahead of the clock [ms] (the core's own
/// default is no check): generous for clocks synchronised by NTP, tight enough that a sensor
/// whose clock runs far ahead is noticed instead of blocking its input.
constexpr double kDefaultMaxFutureStampMs = 500.0;

/// How far ahead of the clock a stamp may be, in ms: >= 0 (infinite: no check).
inline double checkedFutureStampMs(double ms) {
  if (!(ms >= 0.0)) {
    throw std::invalid_argument("maximum future stamp must be a number of ms >= 0, got " +
                                std::to_string(ms));
  }
  return ms;
}

/// A maximum measurement lag in ms: finite and >= 0.
inline double checkedLagMs(double lagMs) {
  if (!(lagMs >= 0.0) || !std::isfinite(lagMs)) {
    throw std::invalid_argument("maximum measurement lag must be a number of ms >= 0, got " +
                                std::to_string(lagMs));
  }
  return lagMs;
}

}  // namespace sf_filter
