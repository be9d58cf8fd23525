// Per-input settings of the fusion core beyond the thesis's averaging by arrival time: the
// alignment policy (alignment/alignment_policy.hpp), the Mahalanobis gate and whether the
// input is aligned by its messages' header stamps. doc/alignment_policies.md explains them.
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

  bool gated() const { return std::isfinite(gateThreshold); }
};

/// What is wrong with the options, empty if nothing.
inline std::string inputOptionsProblem(const InputOptions& o) {
  const std::string policy = alignmentPolicyProblem(o.alignment);
  if (!policy.empty()) return policy;
  if (!(o.gateThreshold > 0.0)) {
    return "gate threshold must be positive (infinite: no gate), got " +
           std::to_string(o.gateThreshold);
  }
  return {};
}

}  // namespace sf_filter
