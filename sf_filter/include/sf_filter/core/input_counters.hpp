// What happened to the values of one input: received, used in an estimate, or dropped and why.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "sf_filter/core/stamp_delay.hpp"

namespace sf_filter {

/// The largest variance a value may carry (the variance field of its message): a larger one is
/// dropped as bad variance. 1e100 says "no information" as well as infinity would, and the
/// average of up to 2^32 values per period (their variances summed) cannot overflow.
constexpr double kMaxVariance = 1e100;

/// Why a value was refused by the fusion core (None: accepted).
enum class Rejection {
  None,
  NonFinite,
  BadVariance,
  OutOfRange,
  OutOfOrder,
  DuplicateStamp,
  FutureStamp,
  TooLate,
  UnknownInput,
  NonFiniteCovariance,   ///< a covariance block (addMeasurementBlock) with a non-finite entry
  AsymmetricCovariance,  ///< ... asymmetric beyond estimation::kSymmetryTolerance
  IndefiniteCovariance   ///< ... not positive definite
};

inline const char* toString(Rejection r) {
  static constexpr const char* kReasons[] = {
      "accepted",                                             // None
      "value is not finite",                                  // NonFinite
      "variance is not finite, positive and at most 1e100",   // BadVariance
      "value outside the input's plausible range",            // OutOfRange
      "timestamp runs backwards",                             // OutOfOrder
      "timestamp equal to the previous value's (duplicate)",  // DuplicateStamp
      "timestamp too far ahead of the clock",                 // FutureStamp
      "stamped in a period already estimated (later than the maximum measurement lag)",  // TooLate
      "unknown input index",                                                // UnknownInput
      "covariance block has a non-finite entry",                            // NonFiniteCovariance
      "covariance block is not symmetric (relative asymmetry above 1e-9)",  // AsymmetricCovariance
      "covariance block is not positive definite",                          // IndefiniteCovariance
  };
  static_assert(
      std::size(kReasons) == static_cast<std::size_t>(Rejection::IndefiniteCovariance) + 1,
      "one name per value");
  const auto i = static_cast<std::size_t>(r);
  return i < std::size(kReasons) ? kReasons[i] : "?";
}

struct InputCounters {
  std::uint64_t received = 0;     ///< values handed to the core
  std::uint64_t used = 0;         ///< values that entered an estimate
  std::uint64_t nonFinite = 0;    ///< dropped: NaN or infinite value
  std::uint64_t badVariance = 0;  ///< dropped: variance field zero, negative, NaN or > kMaxVariance
  std::uint64_t outOfRange = 0;   ///< dropped: value outside the plausible range
  std::uint64_t outOfOrder = 0;   ///< dropped: stamp older than the previous one of this input
  std::uint64_t duplicate = 0;    ///< dropped: stamp equal to the previous one of this input
  std::uint64_t future = 0;       ///< dropped: stamp ahead of the clock by more than allowed
  std::uint64_t late = 0;         ///< dropped: stamp in a period already estimated
  /// dropped: the message's covariance block is no covariance (not finite, asymmetric beyond
  /// estimation::kSymmetryTolerance, not positive definite); every value of the message
  std::uint64_t badCovariance = 0;
  std::uint64_t gated = 0;            ///< values of periods whose value failed the gate
  std::uint64_t superseded = 0;       ///< LAST, SAMPLED: values replaced by a newer one in a period
  std::uint64_t substituted = 0;      ///< periods given a HOLD or FILL substitute (not values)
  std::uint64_t aheadOfClock = 0;     ///< stamps beyond the open periods, used in the newest one
  std::uint64_t timedOutPeriods = 0;  ///< periods estimated while the input was timed out
  /// Unstamped values the input's cadence found sent in an earlier period than the one they
  /// went to (a stalled delivery: kept at their arrival because that period was estimated
  /// already, or ~unstamped_cadence is off). Where one was, the estimates from its period on
  /// may differ from the offline replay's, which places it by its recorded time (issue 38 D10).
  std::uint64_t placedLate = 0;
  /// The time the cadence says the first of them was sent (NaN: none); kept across resets.
  double firstPlacedLate = std::numeric_limits<double>::quiet_NaN();
  double lastArrival = std::numeric_limits<double>::quiet_NaN();
  /// Arrival of the newest value that reached the filter (NaN: none since the start or the
  /// last reset): set when its period is estimated, for a value that passed the checks on
  /// arrival, was not late and passed the gate. The sensor timeout counts from it.
  double lastAccepted = std::numeric_limits<double>::quiet_NaN();
  double lastStamp = -std::numeric_limits<double>::infinity();
  /// Stamp-to-arrival delays of the stamped values that passed the order checks (the ones a
  /// lag decides about), over the whole run: kept across resets.
  StampDelays delays;

  /// Values refused on arrival. received = used + superseded + gated + dropped() + the
  /// values waiting in periods not yet estimated.
  std::uint64_t dropped() const {
    return nonFinite + badVariance + outOfRange + outOfOrder + duplicate + future + late +
           badCovariance;
  }
};

/// The non-zero drop counts by reason, e.g. "2 not finite, 1 out of range" ("none" if none).
inline std::string dropReasons(const InputCounters& c) {
  const std::pair<const char*, std::uint64_t> reasons[] = {{"not finite", c.nonFinite},
                                                           {"bad variance", c.badVariance},
                                                           {"out of range", c.outOfRange},
                                                           {"out of order", c.outOfOrder},
                                                           {"duplicate stamp", c.duplicate},
                                                           {"future stamp", c.future},
                                                           {"late", c.late},
                                                           {"bad covariance", c.badCovariance}};
  std::string text;
  for (const auto& r : reasons) {
    if (r.second == 0) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(r.second) + " " + r.first;
  }
  return text.empty() ? "none" : text;
}

/// The ~max_measurement_lag (`parameter`) that would keep the late values of delays `d` when
/// the lag is `lag` [s]: the one keeping 99 %, or all if that is not longer than `lag`; "" if
/// neither is.
inline std::string lagAdvice(const StampDelays& d, double lag,
                             const char* parameter = "~max_measurement_lag") {
  char text[160];
  const double keeps99 = lagKeeping99(d);
  const double keepsAll = std::ceil(1e3 * d.bound(1.0) - 1e-9) / 1e3;
  if (keeps99 > lag) {
    std::snprintf(text, sizeof text, "%s %g would keep 99 %% (now %g)", parameter, keeps99, lag);
  } else if (keepsAll > lag) {
    std::snprintf(text, sizeof text, "%s %g would keep all (now %g)", parameter, keepsAll, lag);
  } else {
    return {};
  }
  return text;
}

/// Input `index` (`name`)'s values dropped as later than the maximum measurement lag `lag` [s],
/// with their stamp-to-arrival delays and the lag that would keep them (doc/filter_node.md,
/// "Late values"), e.g. "input 2 (imu/data angular_velocity.z): 31 % of values dropped as late
/// (652 of 2100): stamp-to-arrival delay median 25 ms, p95 34 ms; ~max_measurement_lag 0.036
/// would keep 99 % (now 0.02)". The replay names its option (`parameter`).
inline std::string lateAdvice(std::size_t index, const std::string& name, const InputCounters& c,
                              double lag, const char* parameter = "~max_measurement_lag") {
  const double share =
      c.received ? 100.0 * static_cast<double>(c.late) / static_cast<double>(c.received) : 0.0;
  char head[64];
  std::snprintf(head, sizeof head, "%.0f %% of values dropped as late (", share);
  const std::string advice = lagAdvice(c.delays, lag, parameter);
  return "input " + std::to_string(index) + " (" + name + "): " + head + std::to_string(c.late) +
         " of " + std::to_string(c.received) + "): stamp-to-arrival delay " +
         delayFigures(c.delays) + (advice.empty() ? "" : "; " + advice);
}

}  // namespace sf_filter
