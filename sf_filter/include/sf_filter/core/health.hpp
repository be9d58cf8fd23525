// The diagnostic rules of a fusion node (doc/filter_node.md, "Diagnostics"), ROS-free: from
// what the fusion core counted between two reports they give each input's and the
// estimation's level (OK / WARN / ERROR), a message that says why, and the key values. The
// node turns them into diagnostic_msgs/DiagnosticStatus; the rules are unit-tested here.
//
// Input (per TOPICS_IN entry), over the interval since the previous report:
//   ERROR  values arrived but every one was dropped on arrival (the sensor sends garbage)
//   WARN   timed out (no value accepted for longer than its timeout), or some values were
//          dropped (late ones with their stamp-to-arrival delays and the ~max_measurement_lag
//          that would keep them), or some failed the Mahalanobis gate
//   OK     otherwise
// Estimation:
//   ERROR  an estimation step failed (the last good estimate was kept; after
//          FusionCore::Options::maxConsecutiveFailures in a row the filter was reset), or the
//          covariance is not finite
//   WARN   the clock jumped backwards (filter reset); the filter repaired its numbers
//          (covariance made positive semi-definite, particle weights all vanished, UKF
//          sigma spread widened: numerical_repairs.hpp); the NIS window is full and its mean
//          lies outside the chi-square bounds (filter inconsistent: what that tells and what to
//          check, nisAdvice); the mean
//          estimation step took longer than the period; ROS time did not advance since the
//          previous report (a paused bag or simulation: no estimates)
//   OK     otherwise
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <sf_estimation/numerical_repairs.hpp>

#include "sf_filter/core/estimation_totals.hpp"
#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/nis_window.hpp"

namespace sf_filter {

namespace health_detail {
inline std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}
}  // namespace health_detail

enum class HealthLevel { Ok = 0, Warn = 1, Error = 2 };

struct HealthStatus {
  HealthLevel level = HealthLevel::Ok;
  std::string message;  ///< the reasons for the level, "; "-separated ("ok" when OK)
  std::vector<std::pair<std::string, std::string>> values;

  /// Raises the level to at least `l` and adds `why` to the message.
  void raise(HealthLevel l, const std::string& why) {
    if (l > level) level = l;
    message += (message.empty() ? "" : "; ") + why;
  }
  void add(const std::string& key, const std::string& value) { values.emplace_back(key, value); }
  void add(const std::string& key, std::uint64_t value) { add(key, std::to_string(value)); }
  void add(const std::string& key, double value) { add(key, health_detail::format(value)); }
  /// The value of `key` ("" if absent).
  std::string value(const std::string& key) const {
    for (const auto& kv : values) {
      if (kv.first == key) return kv.second;
    }
    return {};
  }
};

/// What an input did in one interval between reports.
struct InputInterval {
  InputCounters now, before;
  double clock = 0.0;       ///< the core's clock at the report
  double interval = 0.0;    ///< clock time since the previous report (<= 0: unknown)
  double sinceStart = 0.0;  ///< clock time since the schedule (re)started
  bool timedOut = false;
  double maxMeasurementLag = 0.0;  ///< [s], named in the advice about late values
};

namespace health_detail {
/// " (3 late: stamp-to-arrival delay median 25 ms, p95 34 ms; ~max_measurement_lag 0.036
/// would keep 99 % (now 0.02))" for `late` > 0 values dropped as late, else "".
inline std::string lateReason(const InputInterval& in, std::uint64_t late) {
  if (late == 0) return {};
  const std::string advice = lagAdvice(in.now.delays, in.maxMeasurementLag);
  return " (" + std::to_string(late) + " late: stamp-to-arrival delay " +
         delayFigures(in.now.delays) + (advice.empty() ? "" : "; " + advice) + ")";
}
/// A time on the clock to the millisecond (ROS times are ~1e9 s), "never" if NaN.
inline std::string stampText(double t) {
  if (std::isnan(t)) return "never";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", t);
  return text;
}
/// A delay quantile [ms] for the report, "n/a" before the first stamped value.
inline std::string delayMs(const StampDelays& d, double q) {
  return d.count() ? format(1e3 * d.quantile(q)) : std::string("n/a");
}
}  // namespace health_detail

inline HealthStatus inputHealth(const InputOptions& o, const InputInterval& in) {
  const InputCounters &c = in.now, &b = in.before;
  HealthStatus s;
  const std::uint64_t received = c.received - b.received;
  const std::uint64_t dropped = c.dropped() - b.dropped();
  const std::uint64_t gated = c.gated - b.gated;
  const double age = std::isnan(c.lastAccepted) ? in.sinceStart : in.clock - c.lastAccepted;
  if (received > 0 && dropped == received) {
    s.raise(HealthLevel::Error, "all " + std::to_string(received) + " values dropped" +
                                    health_detail::lateReason(in, c.late - b.late));
  } else if (dropped > 0) {
    s.raise(HealthLevel::Warn, std::to_string(dropped) + " values dropped" +
                                   health_detail::lateReason(in, c.late - b.late));
  }
  if (in.timedOut) {
    s.raise(HealthLevel::Warn, "timed out: no value for " + health_detail::format(age) +
                                   " s (timeout " + health_detail::format(o.timeout) + " s)");
  }
  if (gated > 0) s.raise(HealthLevel::Warn, std::to_string(gated) + " values gated");
  if (s.message.empty()) s.message = "ok";
  s.add("observed rate [Hz]",
        in.interval > 0.0 ? health_detail::format(static_cast<double>(received) / in.interval)
                          : std::string("n/a"));
  s.add("last arrival age [s]", std::isnan(c.lastArrival)
                                    ? std::string("never")
                                    : health_detail::format(in.clock - c.lastArrival));
  s.add("last accepted age [s]",
        std::isnan(c.lastAccepted) ? std::string("never") : health_detail::format(age));
  s.add("timed out", std::string(in.timedOut ? "true" : "false"));
  s.add("timeout [s]", o.hasTimeout() ? health_detail::format(o.timeout) : std::string("none"));
  s.add("received", c.received);
  s.add("used", c.used);
  s.add("dropped", c.dropped());
  s.add("dropped: not finite", c.nonFinite);
  s.add("dropped: bad variance", c.badVariance);
  s.add("dropped: out of range", c.outOfRange);
  s.add("dropped: out of order", c.outOfOrder);
  s.add("dropped: duplicate stamp", c.duplicate);
  s.add("dropped: future stamp", c.future);
  s.add("dropped: late", c.late);
  s.add("dropped: bad covariance", c.badCovariance);
  s.add("stamp-to-arrival delay median [ms]", health_detail::delayMs(c.delays, 0.5));
  s.add("stamp-to-arrival delay p95 [ms]", health_detail::delayMs(c.delays, 0.95));
  s.add("gated", c.gated);
  s.add("superseded", c.superseded);
  s.add("substituted", c.substituted);
  s.add("timed-out periods", c.timedOutPeriods);
  s.add("placed late", c.placedLate);
  s.add("first placed late, sent at [s]", health_detail::stampText(c.firstPlacedLate));
  return s;
}

struct EstimationInterval {
  EstimationTotals now, before;
  double interval = 0.0;  ///< clock time since the previous report (<= 0: unknown)
  double period = 0.1;    ///< estimation period [s]
  double maxStepSeconds = 0.0;
  double covarianceTrace = 0.0;
  std::string lastFailure;
  bool clockStopped = false;  ///< ROS time did not advance since the previous report
  double clock = 0.0;         ///< ROS time at the report
};

namespace health_detail {

/// The problems of the interval, worst first: failed steps, a covariance not finite, clock
/// jumps, numerical repairs, an inconsistent NIS, slow steps, a stopped clock.
inline void raiseEstimationProblems(HealthStatus& s, const EstimationInterval& e,
                                    const NisWindow& nis, std::uint64_t steps, double stepSeconds) {
  const EstimationTotals &c = e.now, &b = e.before;
  if (c.estimationFailures > b.estimationFailures) {
    const std::uint64_t resets = c.filterResets - b.filterResets;
    s.raise(HealthLevel::Error, std::to_string(c.estimationFailures - b.estimationFailures) +
                                    " estimation steps failed, " +
                                    (resets > 0 ? "filter reset " + std::to_string(resets) +
                                                      " times after repeated failures"
                                                : std::string("last good estimate kept")) +
                                    ": " + e.lastFailure);
  }
  if (!std::isfinite(e.covarianceTrace)) s.raise(HealthLevel::Error, "covariance not finite");
  if (c.clockResets > b.clockResets) {
    s.raise(HealthLevel::Warn, "clock jumped backwards: filter reset");
  }
  if (c.repairs.total() > b.repairs.total()) {
    s.raise(HealthLevel::Warn,
            std::to_string(c.repairs.total() - b.repairs.total()) +
                " numerical repairs by the filter (covariance, particle weights or sigma spread)");
  }
  if (nis.inconsistent()) {
    const NisBounds bounds = nis.bounds();
    s.raise(HealthLevel::Warn,
            "filter inconsistent: NIS mean " + format(nis.mean()) + " outside [" +
                format(bounds.lower) + ", " + format(bounds.upper) + "] and more than a factor " +
                format(nis.tolerance()) + " from its expected " + format(nis.expectedMean()) +
                " (" + nisAdvice(nis.mean() > bounds.upper) + ")");
  }
  if (steps > 0 && stepSeconds > e.period) {
    s.raise(HealthLevel::Warn, "estimation step takes longer than the period");
  }
  if (e.clockStopped) {
    s.raise(HealthLevel::Warn, "clock stopped at " + format(e.clock) + " s: no estimates");
  }
}

/// The NIS window's values (with the window on).
inline void addNisValues(HealthStatus& s, const NisWindow& nis, std::uint64_t nisFailures) {
  s.add("NIS window [periods]", static_cast<std::uint64_t>(nis.size()));
  s.add("NIS degrees of freedom", static_cast<std::uint64_t>(nis.degreesOfFreedom()));
  s.add("NIS mean", nis.mean());
  if (nis.size() > 0) {
    s.add("NIS lag-1 autocorrelation", nis.autocorrelation());
    s.add("NIS effective periods", nis.effectivePeriods());
    const NisBounds bounds = nis.bounds();
    s.add("NIS lower bound (2.5 %)", bounds.lower);
    s.add("NIS upper bound (97.5 %)", bounds.upper);
    s.add("NIS expected mean", nis.expectedMean());
    s.add("NIS tolerance factor", nis.tolerance());
  }
  s.add("NIS consistent", std::string(!nis.full()          ? "not judged (window not full)"
                                      : nis.inconsistent() ? "false"
                                                           : "true"));
  s.add("NIS not computable", nisFailures);
}

}  // namespace health_detail

inline HealthStatus estimationHealth(const EstimationInterval& e, const NisWindow& nis) {
  const EstimationTotals &c = e.now, &b = e.before;
  HealthStatus s;
  const std::uint64_t steps = c.estimates - b.estimates;
  const double stepSeconds = steps ? (c.estimatorSeconds - b.estimatorSeconds) / steps : 0.0;
  health_detail::raiseEstimationProblems(s, e, nis, steps, stepSeconds);
  if (s.message.empty()) s.message = "ok";
  s.add("estimates", c.estimates);
  s.add("estimation time per step [us]", 1e6 * stepSeconds);
  s.add("longest step [us]", 1e6 * e.maxStepSeconds);
  s.add("covariance trace", e.covarianceTrace);
  if (nis.enabled()) health_detail::addNisValues(s, nis, c.nisFailures);
  s.add("clock resets", c.clockResets);
  s.add("estimation failures", c.estimationFailures);
  s.add("filter resets", c.filterResets);
  s.add("last failure", e.lastFailure.empty() ? std::string("none") : e.lastFailure);
  s.add("control values dropped", c.controlNonFinite);
  s.add("numerical repairs", c.repairs.total());
  s.add("repairs: covariance", c.repairs.covariance);
  s.add("repairs: particle weights", c.repairs.weights);
  s.add("repairs: sigma spread", c.repairs.sigmaSpread);
  return s;
}

}  // namespace sf_filter
