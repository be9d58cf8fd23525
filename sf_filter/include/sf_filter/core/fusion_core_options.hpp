// The options of a fusion core (fusion_core.hpp) that do not depend on the filter's type, so
// that the code reading them from ROS parameters or the replay's command line is compiled
// once for every configuration header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "sf_filter/core/input_options.hpp"

namespace sf_filter {

struct FusionCoreOptions {
  /// Bounds of period [s]: 0.1 ms .. 1 h (a period outside them is a unit mistake: 1e-6 meant
  /// as ms, 50 meant as ms, and would load a core or never estimate).
  static constexpr double kMinPeriod = 1e-4;
  static constexpr double kMaxPeriod = 3600.0;
  /// Upper bound of maxCatchUpPeriods: one advanceTo() never estimates more periods.
  static constexpr std::uint64_t kMaxCatchUpLimit = 100000;
  /// Upper bound of maxQueuedPeriods (the ring of open periods holds one slot per period).
  static constexpr std::uint64_t kMaxQueuedLimit = 100000;
  static constexpr double kMaxNisTolerance = 100.0;

  double period = 0.1;  ///< estimation period [s], kMinPeriod .. kMaxPeriod
  /// A forward clock jump longer than this many periods is skipped (one estimate) instead
  /// of estimating every missed period, so a stalled clock never floods the output.
  /// 1 .. kMaxCatchUpLimit.
  std::uint64_t maxCatchUpPeriods = 100;
  /// How many periods beyond the clock's current one can hold values that arrived ahead of
  /// the clock (a stalled clock whose values kept coming: fusion_core.hpp, "Clock stalls"). A
  /// forward jump of the clock estimates those periods one by one even beyond
  /// maxCatchUpPeriods; a value further ahead goes into the last of them (counted as
  /// InputCounters::aheadOfClock). 0 .. kMaxQueuedLimit; the ring of open periods has this
  /// many slots more (a few kB each).
  std::uint64_t maxQueuedPeriods = 1000;
  /// Where the periods lie. false: the schedule starts one maxMeasurementLag before the first
  /// clock reading (the node's first /clock, the replay's first message), so their phase is
  /// that reading's. true: period ends lie on whole multiples of the period in clock time, the
  /// same online and offline whenever the first readings fall into one period: a node whose
  /// first /clock came a few ms after the bag's first message then places every stamped value
  /// in the period the replay does (a phase shift of 3 ms moved a 6-minute skid-steer track by
  /// up to 0.28 m, doc/real_robot.md).
  bool periodsOnClockGrid = false;
  /// Where a value without a stamp, aligned by arrival, goes when it arrives late. false: the
  /// period of its arrival. true: a value arriving more than half its input's cadence (the
  /// median of its recent arrival intervals) after the time the cadence predicts (the previous
  /// value's placement plus that interval), in a later period, goes to the predicted time if
  /// every other input that delivered anything was silent from then until this value's
  /// arrival (a stalled delivery, not a skipped value) and that period is still open
  /// (maxMeasurementLag keeps periods open). A node stalled under load reads the backlog of
  /// such an input after roscpp's clock already jumped past the period it was sent in; placed
  /// at its arrival it joins the next period's value (issue 38 D10, doc/reliability.md). The
  /// offline replay, whose arrivals are the recorded times, uses the same rule.
  bool unstampedCadence = false;
  /// One entry per input, or none: every input AVERAGE, by arrival time, without gate.
  std::vector<InputOptions> inputs;
  /// How long after its end a period stays open for stamped values [s] (fusion_core.hpp).
  double maxMeasurementLag = 0.0;
  /// A stamp more than this ahead of the clock reading at arrival is dropped [s] (a sensor
  /// clock far ahead would otherwise block its input: every later stamp looks older).
  /// Infinite: no check.
  double maxFutureStamp = std::numeric_limits<double>::infinity();
  /// Periods over which the NIS is averaged (nis_window.hpp); 0: not computed. Costs one
  /// measurement prediction per period when no gate or FILL needs it anyway.
  std::size_t nisWindow = 0;
  /// How far from its expected value a window's mean NIS outside its chi-square band must
  /// also be to count as inconsistent: a factor >= 1 (nis_window.hpp; 1: the band alone).
  double nisTolerance = 2.0;
  /// A step the estimator rejects (EstimationError) leaves the filter as it was: the period's
  /// estimate is the last good one, flagged Estimate::stepFailed (for the Kalman-type
  /// filters with its covariance inflated by Q: the period passed without a time update). Only
  /// after this many rejected steps in a row does the filter restart from its initial belief (a
  /// fault that waiting does not mend); counted by filterResets(). At least 1 (1: restart at
  /// once).
  std::uint64_t maxConsecutiveFailures = 10;
  /// A state variable that starts at an input's first reading (INITIAL_STATE_FROM_INPUTS).
  struct FirstReading {
    int state = 0;
    int input = 0;
  };
  /// State variables set, before the step of the first period in which their input has a
  /// measured value (after the start and after every reset), to that value; their covariance
  /// is kept, so the step still weighs the reading once. Only filters that can replace their
  /// belief (the Kalman family); others start from the initial state (fusion_core.hpp).
  std::vector<FirstReading> initialFromInputs;
};

}  // namespace sf_filter
