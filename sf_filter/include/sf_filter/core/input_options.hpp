// Per-input settings of the fusion core beyond the thesis's averaging by arrival time: the
// alignment policy (alignment/alignment_policy.hpp), the Mahalanobis gate and whether the
// input is aligned by its messages' header stamps (doc/alignment_policies.md), and the fault
// handling of doc/reliability.md: the sensor timeout and the plausible range of the values.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "sf_filter/core/alignment/alignment_policy.hpp"

namespace sf_filter {

struct InputOptions {
  AlignmentPolicy alignment;  ///< default AVERAGE
  /// Chi-square threshold (1 degree of freedom) on the squared Mahalanobis distance of the
  /// input's innovation; a value beyond it is treated as missing. Infinite: no gate.
  double gateThreshold = std::numeric_limits<double>::infinity();
  /// Align by the message's header stamp instead of its arrival time.
  bool alignByStamp = false;
  /// Sensor timeout [s]: with no value accepted for longer, the input is timed out (missing
  /// every period; a HOLD or FILL input stops substituting and forgets its history, so that
  /// it never extrapolates stale samples). Infinite: no timeout.
  double timeout = std::numeric_limits<double>::infinity();
  /// Plausible range: a value below `minimum` or above `maximum` is dropped on arrival.
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
  /// The input measures an angle in radians (ANGLE_INPUTS, a derived ROLL, PITCH or YAW):
  /// AVERAGE takes the circular mean, HOLD and FILL extrapolate the unwrapped angle.
  bool angle = false;

  bool gated() const { return std::isfinite(gateThreshold); }
  bool hasTimeout() const { return std::isfinite(timeout); }
  bool hasRange() const { return std::isfinite(minimum) || std::isfinite(maximum); }
  bool inRange(double value) const { return value >= minimum && value <= maximum; }
};

/// What is wrong with the options, empty if nothing.
inline std::string inputOptionsProblem(const InputOptions& o) {
  const std::string policy = alignmentPolicyProblem(o.alignment);
  if (!policy.empty()) return policy;
  if (!(o.gateThreshold > 0.0)) {
    return "gate threshold must be positive (infinite: no gate), got " +
           std::to_string(o.gateThreshold);
  }
  if (!(o.timeout > 0.0)) {
    return "timeout must be positive (infinite: no timeout), got " + std::to_string(o.timeout);
  }
  if (std::isnan(o.minimum) || std::isnan(o.maximum) || !(o.minimum < o.maximum)) {
    return "plausible range: minimum " + std::to_string(o.minimum) + " must be less than maximum " +
           std::to_string(o.maximum);
  }
  return {};
}

}  // namespace sf_filter
