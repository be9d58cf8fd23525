// How one input is aligned to the estimation periods (doc/alignment_policies.md):
//
//   AVERAGE                      mean of the period's values, missing without one (thesis 4.3.4;
//                                the default)
//   LAST                         the newest value of the period, missing without one
//   SAMPLED                      Armesto et al.'s multi-rate sampler: the sample of the period
//                                (the newest if there are several), missing without one
//   HOLD primitive order [var]   the newest value; without one, the multi-rate hold's
//                                extrapolation of the history (Armesto et al., Algorithm 1)
//   FILL omega N [var]           the newest value; without one, Wang et al.'s Bezier filling
//                                from the last N samples and the filter's predicted measurement
//
// `var` is the variance the filter uses for a HOLD or FILL substitute (default: R, like a
// measurement; Wang et al. use a larger one for held values, Remark 6.1). The text form above
// is what the runtime parameters and the replay's --align option take.
#pragma once

#include <cmath>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sf_filter/core/alignment/hold_primitives.hpp"
#include "sf_filter/core/alignment/sample_history.hpp"

namespace sf_filter {

enum class AlignmentKind { Average, Last, Sampled, Hold, Fill };

inline const char* toString(AlignmentKind k) {
  static constexpr const char* kNames[] = {"AVERAGE", "LAST", "SAMPLED", "HOLD", "FILL"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(AlignmentKind::Fill) + 1,
                "one name per value");
  const auto i = static_cast<std::size_t>(k);
  return i < std::size(kNames) ? kNames[i] : "?";
}

struct AlignmentPolicy {
  AlignmentKind kind = AlignmentKind::Average;
  HoldPrimitive primitive = HoldPrimitive::Lagrange;  ///< HOLD
  int order = 0;                                      ///< HOLD: 0 zero-order, 1 first-order, ...
  double omega = 0.0;                                 ///< FILL: tuning parameter omega [s]
  int samples = 0;                                    ///< FILL: stored samples N
  std::optional<double> variance;  ///< HOLD, FILL: variance of a substitute (none: R)

  static constexpr AlignmentPolicy average() { return AlignmentPolicy{}; }
  static constexpr AlignmentPolicy last() { return of(AlignmentKind::Last); }
  static constexpr AlignmentPolicy sampled() { return of(AlignmentKind::Sampled); }
  static constexpr AlignmentPolicy hold(HoldPrimitive primitive, int order,
                                        std::optional<double> variance = std::nullopt) {
    return AlignmentPolicy{AlignmentKind::Hold, primitive, order, 0.0, 0, variance};
  }
  static constexpr AlignmentPolicy fill(double omega, int samples,
                                        std::optional<double> variance = std::nullopt) {
    return AlignmentPolicy{
        AlignmentKind::Fill, HoldPrimitive::Lagrange, 0, omega, samples, variance};
  }

  /// HOLD and FILL put a substitute in place of a missing value.
  constexpr bool substitutes() const {
    return kind == AlignmentKind::Hold || kind == AlignmentKind::Fill;
  }
  /// FILL needs the filter's predicted measurement.
  constexpr bool needsPrediction() const { return kind == AlignmentKind::Fill; }
  /// Samples a policy keeps across periods (0: none).
  constexpr int historyLength() const {
    return kind == AlignmentKind::Hold ? order + 1 : kind == AlignmentKind::Fill ? samples : 0;
  }

 private:
  static constexpr AlignmentPolicy of(AlignmentKind kind) {
    AlignmentPolicy p;
    p.kind = kind;
    return p;
  }
};

inline bool operator==(const AlignmentPolicy& a, const AlignmentPolicy& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case AlignmentKind::Hold:
      return a.primitive == b.primitive && a.order == b.order && a.variance == b.variance;
    case AlignmentKind::Fill:
      return a.omega == b.omega && a.samples == b.samples && a.variance == b.variance;
    default:
      return true;
  }
}

/// The text form, e.g. "HOLD TAYLOR 2", "FILL 0.001 5 0.1".
inline std::string toString(const AlignmentPolicy& p) {
  std::ostringstream os;
  os << toString(p.kind);
  if (p.kind == AlignmentKind::Hold) os << ' ' << toString(p.primitive) << ' ' << p.order;
  if (p.kind == AlignmentKind::Fill) os << ' ' << p.omega << ' ' << p.samples;
  if (p.substitutes() && p.variance) os << ' ' << *p.variance;
  return os.str();
}

/// What is wrong with a policy's numbers, empty if nothing.
inline std::string alignmentPolicyProblem(const AlignmentPolicy& p) {
  if (p.kind == AlignmentKind::Hold && !(p.order >= 0 && p.order <= kMaxHoldOrder)) {
    return "HOLD order " + std::to_string(p.order) + " is out of range, expected 0 to " +
           std::to_string(kMaxHoldOrder);
  }
  if (p.kind == AlignmentKind::Fill) {
    if (!(p.omega > 0.0 && std::isfinite(p.omega))) {
      return "FILL omega must be a positive number of seconds, got " + std::to_string(p.omega);
    }
    if (!(p.samples >= 1 && p.samples <= SampleHistory::kCapacity)) {
      return "FILL N (stored samples) " + std::to_string(p.samples) +
             " is out of range, expected 1 to " + std::to_string(SampleHistory::kCapacity);
    }
  }
  if (p.substitutes() && p.variance && !(*p.variance > 0.0 && std::isfinite(*p.variance))) {
    return std::string(toString(p.kind)) + " variance must be positive and finite, got " +
           std::to_string(*p.variance);
  }
  return {};
}

namespace policy_detail {

inline double parseNumber(const std::string& token, const std::string& what,
                          const std::string& text) {
  const char* begin = token.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0') {
    throw std::invalid_argument("alignment policy '" + text + "': " + what + " '" + token +
                                "' is not a number");
  }
  return value;
}

inline int parseInteger(const std::string& token, const std::string& what,
                        const std::string& text) {
  const double value = parseNumber(token, what, text);
  if (value != std::floor(value) || std::abs(value) > 1e6) {
    throw std::invalid_argument("alignment policy '" + text + "': " + what + " '" + token +
                                "' is not an integer");
  }
  return static_cast<int>(value);
}

}  // namespace policy_detail

/// Parses the text form (words separated by blanks, names in capitals). Throws
/// std::invalid_argument with a message that quotes the text and says what was expected.
inline AlignmentPolicy parseAlignmentPolicy(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  const std::string usage =
      "expected AVERAGE, LAST, SAMPLED, 'HOLD <LAGRANGE|BEZIER|TAYLOR> <order> [variance]' or "
      "'FILL <omega> <N> [variance]'";
  if (words.empty()) throw std::invalid_argument("alignment policy is empty: " + usage);
  const std::string& name = words[0];
  const auto arguments = [&](std::size_t min, std::size_t max) {
    if (words.size() < min + 1 || words.size() > max + 1) {
      throw std::invalid_argument(
          "alignment policy '" + text + "': " + name + " takes " +
          (min == max ? std::to_string(min) : std::to_string(min) + " or " + std::to_string(max)) +
          " arguments; " + usage);
    }
  };
  const auto variance = [&](std::size_t index) -> std::optional<double> {
    if (words.size() <= index) return std::nullopt;
    return policy_detail::parseNumber(words[index], "variance", text);
  };
  AlignmentPolicy p;
  if (name == "AVERAGE") {
    arguments(0, 0);
  } else if (name == "LAST") {
    arguments(0, 0);
    p = AlignmentPolicy::last();
  } else if (name == "SAMPLED") {
    arguments(0, 0);
    p = AlignmentPolicy::sampled();
  } else if (name == "HOLD") {
    arguments(2, 3);
    HoldPrimitive primitive;
    if (words[1] == "LAGRANGE") {
      primitive = HoldPrimitive::Lagrange;
    } else if (words[1] == "BEZIER") {
      primitive = HoldPrimitive::Bezier;
    } else if (words[1] == "TAYLOR") {
      primitive = HoldPrimitive::Taylor;
    } else {
      throw std::invalid_argument("alignment policy '" + text + "': unknown hold primitive '" +
                                  words[1] + "', expected LAGRANGE, BEZIER or TAYLOR");
    }
    p = AlignmentPolicy::hold(primitive, policy_detail::parseInteger(words[2], "order", text),
                              variance(3));
  } else if (name == "FILL") {
    arguments(2, 3);
    p = AlignmentPolicy::fill(policy_detail::parseNumber(words[1], "omega", text),
                              policy_detail::parseInteger(words[2], "N", text), variance(3));
  } else {
    throw std::invalid_argument("unknown alignment policy '" + text + "': " + usage);
  }
  const std::string problem = alignmentPolicyProblem(p);
  if (!problem.empty()) throw std::invalid_argument("alignment policy '" + text + "': " + problem);
  return p;
}

}  // namespace sf_filter
