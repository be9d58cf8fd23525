// Run-time overrides of the configuration header's numeric settings through private ROS
// parameters. The header's values are the defaults; a parameter of the wrong type or size
// is refused at start with a message naming it.
#pragma once

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>
#include <Eigen/Core>

#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/input_overrides.hpp"

namespace sf_filter {

/// Thrown for a bad private parameter; the node logs it and exits with status 1.
class ParameterOverrideError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

/// Reads ~name into `out` (rows x cols) when it is set: a flat row-major list of rows*cols
/// numbers, or a list of rows lists of cols numbers. Returns whether it was set.
template <class Derived>
bool readMatrixParameter(const ros::NodeHandle& pnh, const std::string& name,
                         Eigen::MatrixBase<Derived>& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return false;
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
  out = result;
  return true;
}

/// Reads a scalar ~name into `out` when set; the type must match (an int is accepted for a
/// double).
template <class T>
bool readScalarParameter(const ros::NodeHandle& pnh, const std::string& name, T& out) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return false;
  if constexpr (std::is_floating_point_v<T>) {
    out = static_cast<T>(detail::toDouble(value, "parameter ~" + name));
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

/// Calls apply(k, entry) for each entry of the list parameter ~name if it is set; it must have
/// one entry per input. A std::invalid_argument of apply is reported with the entry named.
inline void forEachInputEntry(const ros::NodeHandle& pnh, const std::string& name,
                              std::size_t inputs,
                              const std::function<void(long, XmlRpc::XmlRpcValue&)>& apply) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return;
  const std::string expected = std::to_string(inputs) + " entries (one per TOPICS_IN entry)";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParameterOverrideError("parameter ~" + name + ": expected a list of " + expected +
                                 ", found " + detail::describe(value));
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

/// The configuration header's per-input options and maximum measurement lag [ms] with the
/// private parameters applied (doc/configuration.md):
///   ~input_alignment      one policy per input, e.g. ["AVERAGE", "HOLD LAGRANGE 1", "FILL 0.001
///   5"] ~input_gate           one chi-square threshold per input, 0 for no gate ~align_by_stamp
///   one boolean per input ~max_measurement_lag  ms >= 0
inline void loadInputParameters(const ros::NodeHandle& pnh, std::vector<InputOptions>& inputs,
                                double& maxMeasurementLagMs, const InputCapabilities& can) {
  const std::size_t m = inputs.size();
  detail::forEachInputEntry(pnh, "input_alignment", m, [&](long k, XmlRpc::XmlRpcValue& v) {
    if (v.getType() != XmlRpc::XmlRpcValue::TypeString) {
      throw std::invalid_argument("expected a policy string such as \"HOLD LAGRANGE 1\"");
    }
    overrideAlignment(inputs, k, static_cast<std::string>(v), can);
  });
  detail::forEachInputEntry(pnh, "input_gate", m, [&](long k, XmlRpc::XmlRpcValue& v) {
    overrideGate(inputs, k, detail::numberEntry(v, "expected a number (0: no gate)"), can);
  });
  detail::forEachInputEntry(pnh, "align_by_stamp", m, [&](long k, XmlRpc::XmlRpcValue& v) {
    if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
      throw std::invalid_argument("expected true or false");
    }
    overrideAlignByStamp(inputs, k, static_cast<bool>(v), can);
  });
  if (readScalarParameter(pnh, "max_measurement_lag", maxMeasurementLagMs)) {
    try {
      checkedLagMs(maxMeasurementLagMs);
    } catch (const std::invalid_argument& e) {
      throw ParameterOverrideError(std::string("parameter ~max_measurement_lag: ") + e.what());
    }
  }
}

/// The node's settings for faults and diagnostics beyond the per-input options.
struct FaultSettings {
  double maxFutureStampMs = kDefaultMaxFutureStampMs;  ///< ~max_future_stamp
  int nisWindow = 100;                                 ///< ~nis_window [periods], 0: off
  double diagnosticPeriod = 1.0;                       ///< ~diagnostic_period [s]
};

/// Applies the fault parameters (doc/filter_node.md, "Diagnostics"):
///   ~input_timeout      one timeout per input in ms, 0 for none
///   ~input_range        one [minimum, maximum] per input, [] for none
///   ~max_future_stamp   ms >= 0 a stamp may be ahead of the clock
///   ~nis_window         periods >= 0 the NIS is averaged over (0: not computed)
///   ~diagnostic_period  s > 0 between diagnostic messages
inline FaultSettings loadFaultParameters(const ros::NodeHandle& pnh,
                                         std::vector<InputOptions>& inputs,
                                         const InputCapabilities& can) {
  const std::size_t m = inputs.size();
  detail::forEachInputEntry(pnh, "input_timeout", m, [&](long k, XmlRpc::XmlRpcValue& v) {
    overrideTimeout(inputs, k, detail::numberEntry(v, "expected a number of ms (0: no timeout)"),
                    can);
  });
  detail::forEachInputEntry(pnh, "input_range", m, [&](long k, XmlRpc::XmlRpcValue& v) {
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
  FaultSettings settings;
  const auto refuse = [](const std::string& name, const std::string& why) {
    throw ParameterOverrideError("parameter ~" + name + ": " + why);
  };
  if (readScalarParameter(pnh, "max_future_stamp", settings.maxFutureStampMs)) {
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
  if (readScalarParameter(pnh, "diagnostic_period", settings.diagnosticPeriod) &&
      !(settings.diagnosticPeriod > 0.0 && settings.diagnosticPeriod <= 3600.0)) {
    refuse("diagnostic_period", "expected a number of seconds > 0 (at most 3600)");
  }
  return settings;
}

namespace detail {

/// ~name, if set, must be of `type`. For the parameters FusionNode reads with
/// NodeHandle::param(), which would silently use the default for a value of another type.
inline void requireType(const ros::NodeHandle& pnh, const std::string& name,
                        XmlRpc::XmlRpcValue::Type type, const char* expected) {
  XmlRpc::XmlRpcValue value;
  if (pnh.getParam(name, value) && value.getType() != type) {
    throw ParameterOverrideError("parameter ~" + name + ": expected " + expected + ", found " +
                                 describe(value));
  }
}

}  // namespace detail

/// The header's parameters with the private ROS parameters applied. `Parameters` is the
/// generated sf_config::Parameters; `makeDefaults(period_ms)` evaluates the header's entries
/// for a period (they may use T).
template <class Parameters, class MakeDefaults>
Parameters loadParameters(const ros::NodeHandle& pnh, MakeDefaults makeDefaults,
                          double headerPeriodMs) {
  detail::requireType(pnh, "frame_id", XmlRpc::XmlRpcValue::TypeString, "a string");
  detail::requireType(pnh, "child_frame_id", XmlRpc::XmlRpcValue::TypeString, "a string");
  detail::requireType(pnh, "publish_tf", XmlRpc::XmlRpcValue::TypeBoolean, "a boolean");
  detail::requireType(pnh, "queue_size", XmlRpc::XmlRpcValue::TypeInt, "an integer");
  double period = headerPeriodMs;
  readScalarParameter(pnh, "estimation_period", period);
  if (!(period > 0.0)) {
    throw ParameterOverrideError("parameter ~estimation_period: must be a positive number of ms");
  }
  Parameters p = makeDefaults(period);
  readMatrixParameter(pnh, "process_noise_covariance", p.process_noise_covariance);
  readMatrixParameter(pnh, "measurement_noise_covariance", p.measurement_noise_covariance);
  readMatrixParameter(pnh, "initial_state", p.initial_state);
  readMatrixParameter(pnh, "initial_error_covariance", p.initial_error_covariance);
  readScalarParameter(pnh, "number_of_particles", p.number_of_particles);
  readScalarParameter(pnh, "random_seed", p.random_seed);
  readScalarParameter(pnh, "resampling_threshold", p.resampling_threshold);
  readScalarParameter(pnh, "ukf_alpha", p.ukf_alpha);
  readScalarParameter(pnh, "ukf_beta", p.ukf_beta);
  readScalarParameter(pnh, "ukf_kappa", p.ukf_kappa);
  readScalarParameter(pnh, "window_size", p.window_size);
  if (pnh.hasParam("weighting_coefficients")) {
    XmlRpc::XmlRpcValue value;
    pnh.getParam("weighting_coefficients", value);
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
