// The fusion core seen through sizes known only at run time: the boundary between the code a
// configuration header generates (the filter on fixed-size types, inside FusionCore<Filter>)
// and the code compiled once for every header (the ROS node, the bag replay, diagnostics,
// parameters, writers). fusion_engine_of.hpp implements it for one FusionCore; the estimation
// step itself stays on the fixed-size, allocation-free path, only its results are handed out
// through Eigen::Map views of the core's own storage.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <sf_estimation/numerical_repairs.hpp>

#include "sf_filter/core/fusion_statistics.hpp"
#include "sf_filter/core/innovation_record.hpp"
#include "sf_filter/core/input_counters.hpp"
#include "sf_filter/core/input_options.hpp"
#include "sf_filter/core/lagged_smoother.hpp"
#include "sf_filter/core/nis_window.hpp"
#include "sf_filter/core/period_smoother.hpp"

namespace sf_filter {

using estimation::Index;

/// What advanceTo() observed about the clock.
enum class ClockEvent { Normal, Started, JumpedBackwards, SkippedGap };

/// One period's estimate, viewed in place (valid until the core estimates again).
struct EstimateRef {
  double time;  ///< end of the estimated period
  Eigen::Map<const Eigen::VectorXd> state;
  Eigen::Map<const Eigen::MatrixXd> covariance;
  Index presentInputs;      ///< inputs with a measured value (not gated) in the period
  Index substitutedInputs;  ///< inputs given a HOLD or FILL substitute
  bool stepFailed;          ///< the step was rejected: the last good estimate (fusion_core.hpp)
  bool filterReset;         ///< ... and the filter restarted from its initial belief
};

/// A non-owning, allocation-free callback for the estimates of advanceTo().
class EstimateCallback {
 public:
  template <class F>
  EstimateCallback(F& f)  // NOLINT: implicit from any callable, like std::function_ref
      : object_(&f), call_([](void* o, const EstimateRef& e) { (*static_cast<F*>(o))(e); }) {}
  void operator()(const EstimateRef& e) const { call_(object_, e); }

 private:
  void* object_;
  void (*call_)(void*, const EstimateRef&);
};

class FusionEngine {
 public:
  virtual ~FusionEngine() = default;

  /// FusionCore::advanceTo: estimates every period that ended, handing each to `onEstimate`.
  virtual ClockEvent advanceTo(double now, EstimateCallback onEstimate) = 0;
  virtual Rejection addMeasurement(Index input, double now, double value,
                                   std::optional<double> variance, double stamp) = 0;
  /// Values of one message with their covariance block (FusionCoreBase::addMeasurementBlock).
  virtual Rejection addMeasurementBlock(const Index* inputs, const double* values,
                                        const double* covariance, int count, double now,
                                        double stamp) = 0;
  virtual Rejection addControl(Index control, double value) = 0;
  virtual void reset() = 0;
  /// Replaces the pose part of the current belief (set_pose, initialpose): the state
  /// variables `indices` (x, y, heading) get `xyYaw`, their 3 x 3 covariance block
  /// `covariance`, and their correlations with the other state variables become 0. False
  /// (belief unchanged) when the filter cannot be re-initialised (particle filter, averaging
  /// methods); throws estimation::ParameterError for a covariance that is not a covariance.
  virtual bool setPose(const std::array<int, 3>& indices, const std::array<double, 3>& xyYaw,
                       const Eigen::Matrix3d& covariance) = 0;

  virtual EstimateRef lastEstimate() const = 0;
  /// Every counter of the core, copied into `out` (allocation-free once `out` has held as many
  /// inputs): the node refreshes one snapshot per period.
  virtual void fillStatistics(FusionStatistics& out) const = 0;
  /// The same as a new snapshot.
  FusionStatistics statistics() const {
    FusionStatistics s;
    fillStatistics(s);
    return s;
  }
  virtual const InputOptions& inputOptions(Index input) const = 0;
  virtual Index inputCount() const = 0;
  virtual bool timedOut(Index input) const = 0;
  virtual double clock() const = 0;
  virtual const NisWindow& nis() const = 0;
  /// The NIS of the run, overall and per input, and the prediction-error cost.
  virtual const InnovationRecord& innovations() const = 0;
  virtual std::uint64_t periodsDue(double now) const = 0;
  /// FusionCore::runTo: advanceTo for a clock that ran to `now`, every period estimated up to
  /// `maxPeriods`.
  virtual ClockEvent runTo(double now, std::uint64_t maxPeriods, EstimateCallback onEstimate) = 0;
  /// FusionCore::skipGap: crosses a forward gap to `now` with one estimate.
  virtual ClockEvent skipGap(double now, EstimateCallback onEstimate) = 0;
  virtual double period() const = 0;
  virtual std::uint64_t maxCatchUpPeriods() const = 0;
  virtual double maxMeasurementLag() const = 0;

  /// An offline smoother of this core's run (period_smoother.hpp), which records the periods
  /// it is told to and keeps a reference to the core; null for a filter without one.
  virtual std::unique_ptr<PeriodSmoother> makeSmoother() const { return nullptr; }
  /// An offline smoother giving the batch MAP track of this core's run
  /// (batch_period_smoother_of.hpp; it records each period's measurement too); null for a
  /// filter without one.
  virtual std::unique_ptr<PeriodSmoother> makeBatchSmoother() const { return nullptr; }
  /// An online smoother with a lag of `lagPeriods` periods (lagged_smoother.hpp), fed by the
  /// caller after each estimate; nullptr for a filter without a smoother.
  virtual std::unique_ptr<LaggedSmoother> makeLaggedSmoother(std::size_t lagPeriods) const {
    (void)lagPeriods;
    return nullptr;
  }

  /// The filter's own description ("extended Kalman filter", ...) and sizes.
  virtual std::string filterDescription() const = 0;
  virtual Index stateSize() const = 0;
  virtual Index measurementSize() const = 0;
  virtual Index controlSize() const = 0;
};

}  // namespace sf_filter
