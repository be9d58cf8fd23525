// The online (fixed-lag) smoother of a fusion core's run (issue 39), seen through sizes known
// only at run time: after each estimated period, the smoothed belief of the period that lies a
// fixed number of periods in the past, given everything up to now
// (sf_estimation/fixed_lag_smoother.hpp; lagged_smoother_of.hpp implements it for one filter
// type). Its memory is fixed (lag + 1 periods) and its cost per period grows with the lag only.
// Made by FusionEngine::makeLaggedSmoother().
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include <sf_estimation/types.hpp>

#include "sf_filter/core/period_smoother.hpp"

namespace sf_filter {

using estimation::Index;

/// A smoothed belief, the end time of the period it estimates and that period's inputs with a
/// measured value.
struct LaggedBelief {
  double time;
  Index presentInputs;
  PeriodBelief belief;
};

class LaggedSmoother {
 public:
  virtual ~LaggedSmoother() = default;

  /// Adds the period the core has just estimated. Returns the smoothed belief of the period
  /// lag() periods before it (valid until the next call), nullopt while fewer periods were
  /// added, and nullopt (counted in failures()) when the smoother refused the period: an
  /// indefinite prediction from a corrupt belief; the smoother then starts anew from the next.
  virtual std::optional<LaggedBelief> add() = 0;

  /// The lag in periods.
  virtual std::size_t lag() const = 0;
  /// Periods held now (at most lag() + 1).
  virtual std::size_t periodsHeld() const = 0;
  /// Segments begun (1 for an uninterrupted run; a rejected step, a restart, a clock reset or
  /// a refused period begins one).
  virtual std::size_t segments() const = 0;
  virtual std::uint64_t failures() const = 0;
  /// The fixed memory of the held periods.
  virtual std::size_t bytes() const = 0;
  /// How far the smoother moved the newest smoothed period (states 0 before the first), and
  /// the sum over every period it smoothed (SmoothingCorrection: what stands for a NIS).
  virtual SmoothingCorrection lastCorrection() const = 0;
  virtual const SmoothingCorrectionTotal& corrections() const = 0;
};

}  // namespace sf_filter
