// Run-time overrides of the configuration header's numeric settings through private ROS
// parameters. The header's values are the defaults; a parameter of the wrong type or size
// is refused at start with a message naming it. Time parameters are in seconds (REP-103);
// the header macros stay in milliseconds (doc/filter_node.md, "Units").
//
// The parameters are read through a ParameterSource (a ros::NodeHandle's private namespace
// online), so that other sources share the same parsing and checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ros/node_handle.h>
#include <ros/param.h>
#include <xmlrpcpp/XmlRpcValue.h>
#include <Eigen/Core>

#include "sf_filter/core/fusion_core_options.hpp"
#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/input_overrides.hpp"
#include "sf_filter/definition/filter_parameters.hpp"

namespace sf_filter {

/// Thrown for a bad private parameter; the node logs it and exits with status 1.
class ParameterOverrideError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where the private parameters come from.
class ParameterSource {
 public:
  virtual ~ParameterSource() = default;
  /// The value of private parameter `name` if it is set.
  virtual bool get(const std::string& name, XmlRpc::XmlRpcValue& value) const = 0;
  /// The names of the private parameters that are set (first level below the namespace).
  virtual std::vector<std::string> names() const = 0;
};

/// The private parameters of a node on the ROS parameter server.
class RosParameterSource final : public ParameterSource {
 public:
  explicit RosParameterSource(ros::NodeHandle pnh) : pnh_(std::move(pnh)) {}
  bool get(const std::string& name, XmlRpc::XmlRpcValue& value) const override {
    return pnh_.getParam(name, value);
  }
  std::vector<std::string> names() const override {
    std::vector<std::string> all, mine;
    if (!ros::param::getParamNames(all)) return mine;
    const std::string prefix = pnh_.getNamespace() + "/";
    std::set<std::string> seen;
    for (const std::string& n : all) {
      if (n.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string rest = n.substr(prefix.size());
      const std::string first = rest.substr(0, rest.find('/'));
      if (!first.empty() && seen.insert(first).second) mine.push_back(first);
    }
    return mine;
  }

 private:
  ros::NodeHandle pnh_;
};

namespace detail {

/// What a parameter value is, for the error messages: "a string (\"abc\")", "a list of 3".
inline std::string describe(const XmlRpc::XmlRpcValue& v) {
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return std::string("a boolean (") + (static_cast<bool>(v) ? "true" : "false") + ")";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an integer (" + std::to_string(static_cast<int>(v)) + ")";
    case XmlRpc::XmlRpcValue::TypeDouble:
      return "a number (" + std::to_string(static_cast<double>(v)) + ")";
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string (\"" + static_cast<std::string>(v) + "\")";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list of " + std::to_string(v.size());
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "a value of another type";
  }
}

/// `v` as a number; `where` names it in the message ("parameter ~x entry 2").
inline double toDouble(const XmlRpc::XmlRpcValue& v, const std::string& where) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw ParameterOverrideError(where + ": expected a number, found " + describe(v));
}

/// One numeric entry of a per-input list; std::invalid_argument(`expected`) if it is not.
inline double numberEntry(const XmlRpc::XmlRpcValue& v, const char* expected) {
  if (v.getType() != XmlRpc::XmlRpcValue::TypeDouble &&
      v.getType() != XmlRpc::XmlRpcValue::TypeInt) {
    throw std::invalid_argument(std::string(expected) + ", found " + describe(v));
  }
  return toDouble(v, "");
}

}  // namespace detail

/// The largest magnitude of a matrix parameter's entry (Q, R, x0, P0): beyond it sums and
/// products of a period overflow (doc/filter_node.md).
constexpr double kMaxParameterMagnitude = 1e100;

/// Whether `value` is a finite number of magnitude at most kMaxParameterMagnitude: the bound
/// of every matrix parameter's entry and of a pose given at run time (set_pose).
inline bool withinParameterMagnitude(double value) {
  return std::abs(value) <= kMaxParameterMagnitude;
}

/// Reads ~name into `out` (rows x cols) when it is set: a flat row-major list of rows*cols
/// numbers, or a list of rows lists of cols numbers. Returns whether it was set.
template <class Derived>
bool readMatrixParameter(const ParameterSource& pnh, const std::string& name,
                         Eigen::MatrixBase<Derived>& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.get(name, value)) return false;
  const Eigen::Index rows = out.rows(), cols = out.cols();
  const std::string expected = std::to_string(rows * cols) + " numbers (" + std::to_string(rows) +
                               "x" + std::to_string(cols) + ", row-major)";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParameterOverrideError("parameter ~" + name + ": expected a list of " + expected +
                                 ", found " + detail::describe(value));
  }
  Derived result(rows, cols);
  if (value.size() > 0 && value[0].getType() == XmlRpc::XmlRpcValue::TypeArray) {
    if (value.size() != rows) {
      throw ParameterOverrideError("parameter ~" + name + ": expected " + std::to_string(rows) +
                                   " rows, found " + std::to_string(value.size()));
    }
    for (int r = 0; r < value.size(); ++r) {
      if (value[r].getType() != XmlRpc::XmlRpcValue::TypeArray || value[r].size() != cols) {
        throw ParameterOverrideError("parameter ~" + name + ": row " + std::to_string(r) +
                                     " must be a list of " + std::to_string(cols) +
                                     " numbers, found " + detail::describe(value[r]));
      }
      for (int c = 0; c < value[r].size(); ++c) {
        result(r, c) =
            detail::toDouble(value[r][c], "parameter ~" + name + " row " + std::to_string(r) +
                                              " entry " + std::to_string(c));
      }
    }
  } else {
    if (value.size() != rows * cols) {
      throw ParameterOverrideError("parameter ~" + name + ": expected " + expected + ", found " +
                                   std::to_string(value.size()));
    }
    for (int k = 0; k < value.size(); ++k) {
      result(k / cols, k % cols) =
          detail::toDouble(value[k], "parameter ~" + name + " entry " + std::to_string(k));
    }
  }
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < cols; ++c) {
      if (!withinParameterMagnitude(result(r, c))) {
        char text[64];
        std::snprintf(text, sizeof text, "%g", result(r, c));
        throw ParameterOverrideError("parameter ~" + name + " row " + std::to_string(r) +
                                     " column " + std::to_string(c) + ": " + text +
                                     " is not a finite number of magnitude at most 1e100");
      }
    }
  }
  out = result;
  return true;
}

/// Reads a scalar ~name into `out` when set; the type must match (an int is accepted for a
/// double).
template <class T>
bool readScalarParameter(const ParameterSource& pnh, const std::string& name, T& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.get(name, value)) return false;
  if constexpr (std::is_floating_point_v<T>) {
    out = static_cast<T>(detail::toDouble(value, "parameter ~" + name));
  } else if constexpr (std::is_same_v<T, bool>) {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
      throw ParameterOverrideError("parameter ~" + name + ": expected true or false, found " +
                                   detail::describe(value));
    }
    out = static_cast<bool>(value);
  } else {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeInt) {
      throw ParameterOverrideError("parameter ~" + name + ": expected an integer, found " +
                                   detail::describe(value));
    }
    const int v = static_cast<int>(value);
    if (std::is_unsigned_v<T> && v < 0) {
      throw ParameterOverrideError("parameter ~" + name + ": must not be negative");
    }
    out = static_cast<T>(v);
  }
  return true;
}

namespace detail {

/// Calls apply(k, entry) for each entry of the parameter ~name if it is set: a list with one
/// entry per input, or a map from input names (INPUTS records) or indices to entries, for the
/// inputs it names. A std::invalid_argument of apply is reported with the entry named.
inline void forEachInputEntry(const ParameterSource& pnh, const std::string& name,
                              std::size_t inputs, const InputCapabilities& can,
                              const std::function<void(long, XmlRpc::XmlRpcValue&)>& apply) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.get(name, value)) return;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    for (auto& entry : value) {
      try {
        const long k = inputIndexOf(entry.first, can);
        if (k < 0 || k >= static_cast<long>(inputs)) {
          throw std::invalid_argument("input index out of range, expected 0 to " +
                                      std::to_string(static_cast<long>(inputs) - 1));
        }
        apply(k, entry.second);
      } catch (const std::invalid_argument& e) {
        throw ParameterOverrideError("parameter ~" + name + " entry " + entry.first + ": " +
                                     e.what());
      }
    }
    return;
  }
  const std::string expected = std::to_string(inputs) + " entries (one per TOPICS_IN entry)";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParameterOverrideError("parameter ~" + name + ": expected a list of " + expected +
                                 ", found " + detail::describe(value) +
                                 " (or a map from input names or indices to entries)");
  }
  if (static_cast<std::size_t>(value.size()) != inputs) {
    throw ParameterOverrideError("parameter ~" + name + ": expected " + expected + ", found " +
                                 std::to_string(value.size()));
  }
  for (int k = 0; k < value.size(); ++k) {
    try {
      apply(k, value[k]);
    } catch (const std::invalid_argument& e) {
      throw ParameterOverrideError("parameter ~" + name + " entry " + std::to_string(k) + ": " +
                                   e.what());
    }
  }
}

}  // namespace detail

/// A time in seconds (REP-103) checked against the plausible range [minimum, maximum] of
/// its parameter; 0 is also accepted if `zeroAllowed` (it then means "none"). A value above
/// the range that would fit as milliseconds gets the hint of the old unit. Returns it in ms,
/// the unit of the header macros and the core's override checks.
inline double secondsToMs(const std::string& what, double seconds, double minimum, double maximum,
                          bool zeroAllowed) {
  if (std::isfinite(seconds) &&
      ((seconds >= minimum && seconds <= maximum) || (zeroAllowed && seconds == 0.0))) {
    return seconds * 1000.0;
  }
  char range[160];
  std::snprintf(range, sizeof range, "%s must be %s%g .. %g s, found %g", what.c_str(),
                zeroAllowed ? "0 (none) or " : "", minimum, maximum, seconds);
  std::string message = range;
  if (std::isfinite(seconds) && seconds > maximum && seconds / 1000.0 <= maximum) {
    char hint[96];
    std::snprintf(hint, sizeof hint, " (seconds, not milliseconds: %g ms is %g s)", seconds,
                  seconds / 1000.0);
    message += hint;
  }
  throw ParameterOverrideError(message);
}

/// The plausible ranges of the time parameters, in seconds (doc/filter_node.md, "Units").
constexpr double kMinPeriodSeconds = 0.0001, kMaxPeriodSeconds = 10.0;
constexpr double kMaxLagSeconds = 10.0;
constexpr double kMinTimeoutSeconds = 0.0001, kMaxTimeoutSeconds = 60.0;
constexpr double kMaxFutureStampSeconds = 60.0;
constexpr double kMaxTransformTimeoutSeconds = 60.0;
constexpr double kMinDiagnosticPeriodSeconds = 0.01, kMaxDiagnosticPeriodSeconds = 3600.0;
constexpr double kMinSmoothingLagSeconds = 0.001, kMaxSmoothingLagSeconds = 60.0;

/// ~smoothing_lag, --smooth-lag: 0 (off) or a lag within the plausible range, in seconds.
inline double smoothingLagSeconds(const std::string& what, double seconds) {
  return secondsToMs(what, seconds, kMinSmoothingLagSeconds, kMaxSmoothingLagSeconds, true) /
         1000.0;
}
/// A gate of k standard deviations on a scalar input is the chi-square threshold k^2.
constexpr double kMaxGateSigma = 1e6;

/// The estimation period in ms from ~estimation_period [s] or ~frequency [Hz] (not both),
/// or the header's `headerPeriodMs`.
inline double loadPeriodMs(const ParameterSource& pnh, double headerPeriodMs) {
  double seconds = 0.0, hertz = 0.0;
  const bool period = readScalarParameter(pnh, "estimation_period", seconds);
  const bool frequency = readScalarParameter(pnh, "frequency", hertz);
  if (period && frequency) {
    throw ParameterOverrideError(
        "parameters ~estimation_period and ~frequency are both set: give one of them");
  }
  if (frequency) {
    if (!(hertz >= 1.0 / kMaxPeriodSeconds && hertz <= 1.0 / kMinPeriodSeconds)) {
      char text[128];
      std::snprintf(text, sizeof text, "parameter ~frequency: must be %g .. %g Hz, found %g",
                    1.0 / kMaxPeriodSeconds, 1.0 / kMinPeriodSeconds, hertz);
      throw ParameterOverrideError(text);
    }
    return 1000.0 / hertz;
  }
  if (period) {
    return secondsToMs("parameter ~estimation_period", seconds, kMinPeriodSeconds,
                       kMaxPeriodSeconds, false);
  }
  return headerPeriodMs;
}

/// The configuration header's per-input options and maximum measurement lag [ms] with the
/// private parameters applied (doc/configuration.md):
/// Each ~input_* parameter is a list with one entry per input or a map from input names
/// (INPUTS records) or indices to entries, e.g. {gyro_z: 9.0}:
///   ~input_alignment      one policy per input, e.g. ["AVERAGE", "HOLD LAGRANGE 1"]
///   ~input_gate           one chi-square threshold per input, 0 for no gate
///   ~input_gate_sigma     or one threshold in standard deviations per input (k: k^2)
///   ~align_by_stamp       one boolean per input
///   ~max_measurement_lag  s, 0 .. 10
inline void loadInputParameters(const ParameterSource& pnh, std::vector<InputOptions>& inputs,
                                double& maxMeasurementLagMs, const InputCapabilities& can) {
  const std::size_t m = inputs.size();
  detail::forEachInputEntry(pnh, "input_alignment", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    if (v.getType() != XmlRpc::XmlRpcValue::TypeString) {
      throw std::invalid_argument("expected a policy string such as \"HOLD LAGRANGE 1\"");
    }
    overrideAlignment(inputs, k, static_cast<std::string>(v), can);
  });
  XmlRpc::XmlRpcValue unused;
  if (pnh.get("input_gate", unused) && pnh.get("input_gate_sigma", unused)) {
    throw ParameterOverrideError(
        "parameters ~input_gate (chi-square) and ~input_gate_sigma (standard deviations) are "
        "both set: give one of them");
  }
  detail::forEachInputEntry(pnh, "input_gate", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    overrideGate(inputs, k, detail::numberEntry(v, "expected a number (0: no gate)"), can);
  });
  detail::forEachInputEntry(pnh, "input_gate_sigma", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    const double sigma =
        detail::numberEntry(v, "expected a number of standard deviations (0: no gate)");
    if (!(sigma >= 0.0 && sigma <= kMaxGateSigma)) {
      throw std::invalid_argument(
          "expected a number of standard deviations from 0 (no gate) to "
          "1e6, found " +
          std::to_string(sigma));
    }
    overrideGate(inputs, k, sigma * sigma, can);
  });
  detail::forEachInputEntry(pnh, "align_by_stamp", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
      throw std::invalid_argument("expected true or false");
    }
    overrideAlignByStamp(inputs, k, static_cast<bool>(v), can);
  });
  double lagSeconds = 0.0;
  if (readScalarParameter(pnh, "max_measurement_lag", lagSeconds)) {
    maxMeasurementLagMs =
        secondsToMs("parameter ~max_measurement_lag", lagSeconds, 0.0, kMaxLagSeconds, true);
    try {
      checkedLagMs(maxMeasurementLagMs);
    } catch (const std::invalid_argument& e) {
      throw ParameterOverrideError(std::string("parameter ~max_measurement_lag: ") + e.what());
    }
  }
}

/// The node's settings for faults and diagnostics beyond the per-input options.
struct FaultSettings {
  double maxFutureStampMs = kDefaultMaxFutureStampMs;  ///< ~max_future_stamp [s] in ms
  /// ~nis_window [periods], 0: off; not set (-1): kDefaultNisWindowSeconds of periods
  /// (nisWindowPeriods).
  int nisWindow = -1;
  double nisTolerance = 2.0;      ///< ~nis_tolerance, the factor of nis_window.hpp
  double diagnosticPeriod = 1.0;  ///< ~diagnostic_period [s]
  /// ~periods_on_clock_grid: period ends on whole multiples of the period in clock time
  /// (FusionCoreOptions::periodsOnClockGrid).
  bool periodsOnClockGrid = false;
  /// ~unstamped_cadence: a late unstamped value goes where its input's cadence puts it
  /// (FusionCoreOptions::unstampedCadence).
  bool unstampedCadence = false;
};

/// The NIS window's default span. Shorter windows see the regimes of a real robot's noise
/// (standstill, turns, bursts of a slow sensor) one at a time: on the shipped bags, tuned,
/// windows of 15 to 25 s stay within a factor 2 of the expected NIS (doc/tuning.md).
constexpr double kDefaultNisWindowSeconds = 30.0;
constexpr int kMinDefaultNisWindow = 100;

/// The window in periods: ~nis_window if set, else kDefaultNisWindowSeconds of periods of
/// `periodMs`, at least kMinDefaultNisWindow.
inline std::size_t nisWindowPeriods(const FaultSettings& settings, double periodMs) {
  if (settings.nisWindow >= 0) return static_cast<std::size_t>(settings.nisWindow);
  const double periods = std::round(kDefaultNisWindowSeconds * 1000.0 / periodMs);
  return static_cast<std::size_t>(
      std::clamp(periods, static_cast<double>(kMinDefaultNisWindow), 1000000.0));
}

namespace detail {

/// loadFaultParameters()'s per-input entries: ~input_timeout and ~input_range.
inline void loadInputFaultParameters(const ParameterSource& pnh, std::vector<InputOptions>& inputs,
                                     const InputCapabilities& can) {
  const std::size_t m = inputs.size();
  detail::forEachInputEntry(pnh, "input_timeout", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    const double seconds = detail::numberEntry(v, "expected a number of s (0: no timeout)");
    double ms = 0.0;
    try {
      ms = secondsToMs("timeout", seconds, kMinTimeoutSeconds, kMaxTimeoutSeconds, true);
    } catch (const ParameterOverrideError& e) {
      throw std::invalid_argument(e.what());
    }
    overrideTimeout(inputs, k, ms, can);
  });
  detail::forEachInputEntry(pnh, "input_range", m, can, [&](long k, XmlRpc::XmlRpcValue& v) {
    const char* expected = "expected [minimum, maximum] or [] for no range";
    if (v.getType() != XmlRpc::XmlRpcValue::TypeArray || (v.size() != 0 && v.size() != 2)) {
      throw std::invalid_argument(expected);
    }
    if (v.size() == 0) {
      overrideRange(inputs, k, -std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity(), can);
      return;
    }
    overrideRange(inputs, k, detail::numberEntry(v[0], expected),
                  detail::numberEntry(v[1], expected), can);
  });
}

}  // namespace detail

/// Applies the fault parameters (doc/filter_node.md, "Diagnostics"):
///   ~input_timeout      one timeout per input in s, 0 for none
///   ~input_range        one [minimum, maximum] per input, [] for none
///   ~max_future_stamp   s, 0 .. 60, a stamp may be ahead of the clock (.inf: no check)
///   ~nis_window         periods >= 0 the NIS is averaged over (0: not computed; default
///                       30 s of periods)
///   ~nis_tolerance      factor 1 .. 100 (nis_window.hpp), default 2
///   ~diagnostic_period  s, 0.01 .. 3600, between diagnostic messages
///   ~periods_on_clock_grid  true: period ends on multiples of the period in clock time
///   ~unstamped_cadence  true: a late unstamped value is placed by its input's cadence
inline FaultSettings loadFaultParameters(const ParameterSource& pnh,
                                         std::vector<InputOptions>& inputs,
                                         const InputCapabilities& can) {
  detail::loadInputFaultParameters(pnh, inputs, can);
  FaultSettings settings;
  const auto refuse = [](const std::string& name, const std::string& why) {
    throw ParameterOverrideError("parameter ~" + name + ": " + why);
  };
  double futureSeconds = 0.0;
  if (readScalarParameter(pnh, "max_future_stamp", futureSeconds)) {
    settings.maxFutureStampMs = std::isinf(futureSeconds) && futureSeconds > 0.0
                                    ? futureSeconds
                                    : secondsToMs("parameter ~max_future_stamp", futureSeconds, 0.0,
                                                  kMaxFutureStampSeconds, true);
    try {
      checkedFutureStampMs(settings.maxFutureStampMs);
    } catch (const std::invalid_argument& e) {
      refuse("max_future_stamp", e.what());
    }
  }
  if (readScalarParameter(pnh, "nis_window", settings.nisWindow) &&
      !(settings.nisWindow >= 0 && settings.nisWindow <= 1000000)) {
    refuse("nis_window", "expected a number of periods from 0 (off) to 1000000");
  }
  if (readScalarParameter(pnh, "nis_tolerance", settings.nisTolerance) &&
      !(settings.nisTolerance >= 1.0 &&
        settings.nisTolerance <= FusionCoreOptions::kMaxNisTolerance)) {
    char found[32];
    std::snprintf(found, sizeof found, "%g", settings.nisTolerance);
    refuse(
        "nis_tolerance",
        std::string("expected a factor from 1 (the chi-square band alone) to 100, found ") + found);
  }
  if (readScalarParameter(pnh, "diagnostic_period", settings.diagnosticPeriod) &&
      !(settings.diagnosticPeriod >= kMinDiagnosticPeriodSeconds &&
        settings.diagnosticPeriod <= kMaxDiagnosticPeriodSeconds)) {
    refuse("diagnostic_period", "expected a number of seconds from 0.01 to 3600");
  }
  for (const auto& [name, flag] :
       {std::pair<const char*, bool*>{"periods_on_clock_grid", &settings.periodsOnClockGrid},
        {"unstamped_cadence", &settings.unstampedCadence}}) {
    XmlRpc::XmlRpcValue value;
    if (!pnh.get(name, value)) continue;
    if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
      refuse(name, "expected true or false, found " + detail::describe(value));
    }
    *flag = static_cast<bool>(value);
  }
  return settings;
}

/// The node's output settings (doc/filter_node.md, "Private parameters").
struct OutputSettings {
  std::string frameId = "odom";            ///< ~frame_id
  std::string childFrameId = "base_link";  ///< ~child_frame_id
  bool publishTf = true;                   ///< ~publish_tf
  /// ~queue_size: of every subscription and publication. Room for a stall of the spinner
  /// thread: 1000 messages hold 1 s of a 1 kHz sensor (100 lost values in a 160 ms stall of
  /// the soak test on a loaded machine).
  int queueSize = 1000;
  /// ~smoothing_lag [s]: the fixed-lag smoother's lag (0: off), rounded to whole periods; its
  /// estimates go to odometry/smoothed and ~state/smoothed (doc/smoothing.md).
  double smoothingLag = 0.0;
};

namespace detail {

/// ~name, if set, must be of `type`.
inline void requireType(const ParameterSource& pnh, const std::string& name,
                        XmlRpc::XmlRpcValue::Type type, const char* expected) {
  XmlRpc::XmlRpcValue value;
  if (pnh.get(name, value) && value.getType() != type) {
    throw ParameterOverrideError("parameter ~" + name + ": expected " + expected + ", found " +
                                 describe(value));
  }
}

/// ~name as a tf2 frame name (not empty, no leading '/'), or `fallback` if it is not set.
inline std::string frameParameter(const ParameterSource& pnh, const std::string& name,
                                  const std::string& fallback) {
  requireType(pnh, name, XmlRpc::XmlRpcValue::TypeString, "a string");
  XmlRpc::XmlRpcValue value;
  if (!pnh.get(name, value)) return fallback;
  const std::string frame = static_cast<std::string>(value);
  if (frame.empty() || frame.front() == '/') {
    throw ParameterOverrideError("parameter ~" + name + ": '" + frame +
                                 "' is not a tf2 frame name (not empty, no leading '/')");
  }
  return frame;
}

}  // namespace detail

/// ~frame_id, ~child_frame_id, ~publish_tf, ~queue_size, ~smoothing_lag.
inline OutputSettings loadOutputParameters(const ParameterSource& pnh) {
  OutputSettings s;
  s.frameId = detail::frameParameter(pnh, "frame_id", s.frameId);
  s.childFrameId = detail::frameParameter(pnh, "child_frame_id", s.childFrameId);
  detail::requireType(pnh, "publish_tf", XmlRpc::XmlRpcValue::TypeBoolean, "a boolean");
  detail::requireType(pnh, "queue_size", XmlRpc::XmlRpcValue::TypeInt, "an integer");
  XmlRpc::XmlRpcValue value;
  if (pnh.get("publish_tf", value)) s.publishTf = static_cast<bool>(value);
  if (pnh.get("queue_size", value)) s.queueSize = static_cast<int>(value);
  if (s.queueSize < 1 || s.queueSize > 1000000) {
    throw ParameterOverrideError("parameter ~queue_size: expected 1 to 1000000 messages, found " +
                                 std::to_string(s.queueSize));
  }
  if (readScalarParameter(pnh, "smoothing_lag", s.smoothingLag)) {
    s.smoothingLag = smoothingLagSeconds("parameter ~smoothing_lag", s.smoothingLag);
  }
  return s;
}

/// Every private parameter the node reads (doc/filter_node.md, "Private parameters").
inline const std::vector<std::string>& knownParameters() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"estimation_period",
                                  "frequency",
                                  "process_noise_covariance",
                                  "measurement_noise_covariance",
                                  "initial_state",
                                  "initial_error_covariance"};
    n.insert(n.end(), std::begin(kMethodParameterNames), std::end(kMethodParameterNames));
    n.insert(n.end(), {"window_size",
                       "weighting_coefficients",
                       "input_alignment",
                       "input_gate",
                       "input_gate_sigma",
                       "align_by_stamp",
                       "max_measurement_lag",
                       "input_timeout",
                       "input_range",
                       "max_future_stamp",
                       "nis_window",
                       "nis_tolerance",
                       "diagnostic_period",
                       "periods_on_clock_grid",
                       "unstamped_cadence",
                       "frame_id",
                       "child_frame_id",
                       "publish_tf",
                       "queue_size",
                       "smoothing_lag",
                       "base_frame",
                       "transform_timeout",
                       "datum",
                       "gps_yaw_offset"});
    return n;
  }();
  return names;
}

/// One warning line per private parameter the node does not read (a typo, or a name of
/// robot_localization's), with a hint for robot_localization's names; empty if none. `extra`:
/// the node's own further names (its extractor kinds' parameters, extractor_parameters.hpp).
inline std::vector<std::string> unknownParameterWarnings(
    const ParameterSource& pnh, const std::vector<std::string>& extra = {}) {
  static const std::vector<std::string> robotLocalization = {"two_d_mode",
                                                             "world_frame",
                                                             "map_frame",
                                                             "odom_frame",
                                                             "base_link_frame",
                                                             "sensor_timeout",
                                                             "initial_estimate_covariance",
                                                             "print_diagnostics",
                                                             "transform_time_offset",
                                                             "publish_acceleration",
                                                             "use_control",
                                                             "control_config",
                                                             "smooth_lagged_data",
                                                             "history_length",
                                                             "dynamic_process_noise_covariance",
                                                             "predict_to_current_time",
                                                             "permit_corrected_publication",
                                                             "reset_on_time_jump"};
  const auto isRobotLocalization = [&](const std::string& n) {
    if (std::find(robotLocalization.begin(), robotLocalization.end(), n) !=
        robotLocalization.end()) {
      return true;
    }
    for (const char* prefix : {"odom", "imu", "pose", "twist"}) {
      const std::string p = prefix;
      if (n.size() > p.size() && n.compare(0, p.size(), p) == 0 &&
          std::isdigit(static_cast<unsigned char>(n[p.size()]))) {
        return true;
      }
    }
    return false;
  };
  std::vector<std::string> k = knownParameters();
  k.insert(k.end(), extra.begin(), extra.end());
  std::string known;
  for (const std::string& name : k) known += (known.empty() ? "" : ", ") + name;
  std::vector<std::string> lines;
  for (const std::string& n : pnh.names()) {
    if (std::find(k.begin(), k.end(), n) != k.end()) continue;
    std::string line = "unknown private parameter ~" + n + " ignored";
    if (isRobotLocalization(n)) {
      line +=
          " (a robot_localization parameter: this node's topics, fields and model are "
          "compiled in from its configuration header; doc/filter_node.md maps "
          "robot_localization's settings)";
    }
    lines.push_back(line + "; known: " + known);
  }
  return lines;
}

/// The header's parameters with the private ROS parameters applied. `Parameters` is the
/// generated sf_config::Parameters; `makeDefaults(period_ms)` evaluates the header's entries
/// for a period (they may use T).
template <class Parameters, class MakeDefaults>
Parameters loadParameters(const ParameterSource& pnh, MakeDefaults makeDefaults,
                          double headerPeriodMs) {
  loadOutputParameters(pnh);
  Parameters p = makeDefaults(loadPeriodMs(pnh, headerPeriodMs));
  readMatrixParameter(pnh, "process_noise_covariance", p.process_noise_covariance);
  readMatrixParameter(pnh, "measurement_noise_covariance", p.measurement_noise_covariance);
  readMatrixParameter(pnh, "initial_state", p.initial_state);
  readMatrixParameter(pnh, "initial_error_covariance", p.initial_error_covariance);
  forEachMethodParameter(
      p, [&](const char* name, auto& value) { readScalarParameter(pnh, name, value); });
  readScalarParameter(pnh, "window_size", p.window_size);
  XmlRpc::XmlRpcValue value;
  if (pnh.get("weighting_coefficients", value)) {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
      throw ParameterOverrideError(
          "parameter ~weighting_coefficients: expected a list of numbers, found " +
          detail::describe(value));
    }
    p.weighting_coefficients.resize(value.size());
    for (int k = 0; k < value.size(); ++k) {
      p.weighting_coefficients(k) = detail::toDouble(
          value[k], "parameter ~weighting_coefficients entry " + std::to_string(k));
    }
  }
  return p;
}

}  // namespace sf_filter
