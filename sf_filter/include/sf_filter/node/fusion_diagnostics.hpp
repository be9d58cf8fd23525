// The fusion node's diagnostics: one diagnostic_msgs/DiagnosticStatus per input and one for
// the estimation on /diagnostics, through diagnostic_updater, with the levels, messages and
// values of core/health.hpp. Reports are driven by a wall-clock timer so that they keep
// coming when ROS time stops (a paused bag, a simulation that hangs): a frozen clock is
// itself something to see.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/health.hpp"
#include "sf_filter/core/lagged_smoother.hpp"

namespace sf_filter {

/// Values of the inputs lost before they reach the fusion core (FusionEngine counts only what
/// it is given): a value that cannot be rotated into the base frame, a message of another
/// type. `count(i)`: lost so far for input i; `reason(i)`: why, for the report.
struct InputLossSource {
  std::function<std::uint64_t(std::size_t)> count;
  std::function<std::string(std::size_t)> reason;
  /// ERROR whenever values were lost in the interval; otherwise ERROR only when none of the
  /// input's values reached the core in it, WARN when some did.
  bool alwaysError = false;
};

class FusionDiagnostics {
 public:
  /// `inputNames`: "topic field" per input; `period`: seconds between reports, from start() on.
  /// The statuses are named after `pnh`'s namespace, the node's or nodelet's name (in a nodelet
  /// manager ros::this_node is the manager).
  FusionDiagnostics(ros::NodeHandle nh, ros::NodeHandle pnh, const FusionEngine& core,
                    const std::vector<std::string>& inputNames, double period)
      : core_(core), updater_(nh, pnh, pnh.getNamespace()), before_(inputNames.size()) {
    updater_.setHardwareID("none");  // a software component
    for (std::size_t i = 0; i < inputNames.size(); ++i) {
      updater_.add(
          "input " + std::to_string(i) + " (" + inputNames[i] + ")",
          [this, i](diagnostic_updater::DiagnosticStatusWrapper& s) { reportInput(i, s); });
    }
    updater_.add("estimation",
                 [this](diagnostic_updater::DiagnosticStatusWrapper& s) { reportEstimation(s); });
    timer_ = nh.createWallTimer(
        ros::WallDuration(period), [this](const ros::WallTimerEvent&) { update(); }, false, false);
  }

  /// Starts the periodic reports (the node does once its clock runs).
  void start() { timer_.start(); }

  /// Makes the input reports show the values `source` loses before the core.
  void addLossSource(InputLossSource source) {
    lossBefore_.emplace_back(before_.size(), 0);
    lossSources_.push_back(std::move(source));
  }

  /// Adds `key` with the current `value()` to every estimation report (counters kept by the
  /// node, not the core: pose resets, say).
  void addEstimationValue(std::string key, std::function<std::string()> value) {
    estimationValues_.emplace_back(std::move(key), std::move(value));
  }

  /// ~smoothing_lag: adds to the estimation reports the fixed-lag smoother's lag (seconds and
  /// periods), the periods and bytes it holds, and what stands for its NIS (it has no innovation
  /// of its own): how far it moved the newest lagged period's filtered mean, in filtered
  /// standard deviations, beside that correction's expectation for a consistent smoother, and
  /// the same over every period it smoothed (SmoothingCorrection, doc/smoothing.md).
  /// `smoother` must outlive the reports.
  void addSmoother(const LaggedSmoother& smoother) {
    using health_detail::format;
    const LaggedSmoother* s = &smoother;
    const double period = core_.period();
    addEstimationValue("smoothing lag [s]",
                       [s, period] { return format(static_cast<double>(s->lag()) * period); });
    addEstimationValue("smoothing lag [periods]", [s] { return std::to_string(s->lag()); });
    addEstimationValue("smoothing periods held", [s] { return std::to_string(s->periodsHeld()); });
    addEstimationValue("smoothing bytes held", [s] { return std::to_string(s->bytes()); });
    addEstimationValue("smoothing correction, last period [sd]",
                       [s] { return format(std::sqrt(s->lastCorrection().meanSquare)); });
    addEstimationValue("smoothing correction expected, last period [sd]",
                       [s] { return format(std::sqrt(s->lastCorrection().expected)); });
    addEstimationValue("smoothing correction RMS [sd]",
                       [s] { return format(s->corrections().rms()); });
    addEstimationValue("smoothing correction expected RMS [sd]",
                       [s] { return format(s->corrections().expectedRms()); });
    addEstimationValue("smoothing correction periods",
                       [s] { return std::to_string(s->corrections().periods); });
  }

  /// Adds `key` with `value(i)` to input i's reports where it is not empty (counters kept by
  /// the node: covariances that fell back to the header's R, say).
  void addInputValue(std::string key, std::function<std::string(std::size_t)> value) {
    inputValues_.emplace_back(std::move(key), std::move(value));
  }

  /// Publishes one report now.
  void update() {
    core_.fillStatistics(now_);  // one snapshot for every status of the report
    updater_.force_update();
    for (std::size_t j = 0; j < lossSources_.size(); ++j) {
      for (std::size_t i = 0; i < before_.size(); ++i) {
        lossBefore_[j][i] = lossSources_[j].count(i);
      }
    }
    // The intervals of the next report start here.
    before_ = now_.inputs;
    beforeEstimation_ = totals();
    previousClock_ = now_.clock;
    previousRosTime_ = ros::Time::now().toSec();
    previousResets_ = now_.clockResets;
  }

 private:
  static void fill(const HealthStatus& h, diagnostic_updater::DiagnosticStatusWrapper& s) {
    static const unsigned char kLevels[] = {diagnostic_msgs::DiagnosticStatus::OK,
                                            diagnostic_msgs::DiagnosticStatus::WARN,
                                            diagnostic_msgs::DiagnosticStatus::ERROR};
    s.summary(kLevels[static_cast<int>(h.level)], h.message);
    for (const auto& kv : h.values) s.add(kv.first, kv.second);
  }

  /// Clock time since the previous report; unknown (0) before the first and across a clock
  /// reset.
  double interval() const {
    if (std::isnan(previousClock_) || now_.clockResets != previousResets_) return 0.0;
    return now_.clock - previousClock_;
  }

  void reportInput(std::size_t i, diagnostic_updater::DiagnosticStatusWrapper& s) const {
    const auto input = static_cast<Index>(i);
    InputInterval in;
    in.now = now_.inputs[i];
    in.before = before_[i];
    in.clock = now_.clock;
    in.interval = interval();
    in.sinceStart = now_.clock - now_.startTime;
    in.timedOut = core_.timedOut(input);
    in.maxMeasurementLag = core_.maxMeasurementLag();
    fill(inputHealth(core_.inputOptions(input), in), s);
    for (std::size_t j = 0; j < lossSources_.size(); ++j) {
      const InputLossSource& source = lossSources_[j];
      const std::uint64_t total = source.count(i);
      const std::uint64_t lost = total - lossBefore_[j][i];
      if (lost == 0) continue;
      const bool noneArrived = in.now.received == in.before.received;
      s.mergeSummary(source.alwaysError || noneArrived ? diagnostic_msgs::DiagnosticStatus::ERROR
                                                       : diagnostic_msgs::DiagnosticStatus::WARN,
                     (noneArrived ? "every value dropped: " : "values dropped: ") +
                         source.reason(i) + " (" + std::to_string(lost) +
                         " since the last report)");
      s.add("dropped before the filter", std::to_string(total));
    }
    for (const auto& kv : inputValues_) {
      const std::string value = kv.second(i);
      if (!value.empty()) s.add(kv.first, value);
    }
  }

  EstimationTotals totals() const { return now_; }  // the estimation part of the snapshot

  void reportEstimation(diagnostic_updater::DiagnosticStatusWrapper& s) const {
    EstimationInterval e;
    e.now = totals();
    e.before = beforeEstimation_;
    e.interval = interval();
    e.period = core_.period();
    e.maxStepSeconds = now_.maxStepSeconds;
    e.covarianceTrace = core_.lastEstimate().covariance.trace();
    e.lastFailure = now_.lastFailure;
    e.clock = ros::Time::now().toSec();
    e.clockStopped = !std::isnan(previousRosTime_) && e.clock == previousRosTime_;
    fill(estimationHealth(e, core_.nis()), s);
    for (const auto& kv : estimationValues_) s.add(kv.first, kv.second());
  }

  const FusionEngine& core_;
  diagnostic_updater::Updater updater_;
  FusionStatistics now_;  ///< the core's counters at this report (update())
  std::vector<InputCounters> before_;
  std::vector<InputLossSource> lossSources_;
  std::vector<std::vector<std::uint64_t>> lossBefore_;  ///< per source, per input
  std::vector<std::pair<std::string, std::function<std::string()>>> estimationValues_;
  std::vector<std::pair<std::string, std::function<std::string(std::size_t)>>> inputValues_;
  EstimationTotals beforeEstimation_;
  double previousClock_ = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no report yet
  double previousRosTime_ = std::numeric_limits<double>::quiet_NaN();
  std::uint64_t previousResets_ = 0;
  ros::WallTimer timer_;
};

}  // namespace sf_filter
