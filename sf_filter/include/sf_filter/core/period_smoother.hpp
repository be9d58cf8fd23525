// The offline smoother of a fusion core's run (issue 39), seen through sizes known only at run
// time: it records what the core's filter produced in each period (filtered mean, covariance,
// the control of its time update) and, after the forward run, smooths the record with the
// filter's own backward pass (sf_estimation/rts_smoother.hpp; period_smoother_of.hpp
// implements it for one filter type). Made by FusionEngine::makeSmoother().
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <Eigen/Core>
#include <sf_estimation/angles.hpp>

namespace sf_filter {

/// One recorded period's mean and covariance, viewed in place.
struct PeriodBelief {
  Eigen::Map<const Eigen::VectorXd> state;
  Eigen::Map<const Eigen::MatrixXd> covariance;
};

/// A fixed- or dynamic-size mean and covariance viewed as a PeriodBelief.
template <class X, class P>
PeriodBelief viewOf(const X& x, const P& covariance) {
  const auto n = x.size();
  return {Eigen::Map<const Eigen::VectorXd>(x.data(), n),
          Eigen::Map<const Eigen::MatrixXd>(covariance.data(), n, n)};
}

/// What a smoother reports instead of a NIS (it has no innovation of its own): how far it moved
/// a period's filtered mean, in the filtered standard deviations. Over the states i with a
/// filtered variance, meanSquare = mean_i (xs_i - xf_i)^2 / Pf_ii (angle states' difference
/// wrapped). The correction xs - xf of a consistent smoother has the covariance Pf - Ps (it is
/// independent of the smoothed error), so its expectation is expected = mean_i (1 - Ps_ii /
/// Pf_ii): a correction far above sqrt(expected) over many periods says the later readings
/// disagree with the filter more than its covariance allows, as a high NIS does.
struct SmoothingCorrection {
  double meanSquare = 0.0;
  double expected = 0.0;
  /// States with a filtered variance (0: nothing to report, a belief without uncertainty).
  int states = 0;
};

/// The correction of `smoothed` against `filtered`; `angles(i)`: whether state i is an angle.
template <class Angles>
SmoothingCorrection smoothingCorrection(const PeriodBelief& filtered, const PeriodBelief& smoothed,
                                        const Angles& angles) {
  SmoothingCorrection c;
  for (Eigen::Index i = 0; i < filtered.state.size(); ++i) {
    const double var = filtered.covariance(i, i);
    if (!(var > 0.0)) continue;
    double d = smoothed.state(i) - filtered.state(i);
    if (angles(i)) d = estimation::wrapAngle(d);
    c.meanSquare += d * d / var;
    c.expected += 1.0 - smoothed.covariance(i, i) / var;
    ++c.states;
  }
  if (c.states > 0) {
    c.meanSquare /= c.states;
    c.expected /= c.states;
  }
  return c;
}

/// The corrections of a run's smoothed periods summed (those with states > 0): the run's RMS
/// correction is sqrt(meanSquare / periods), its expectation sqrt(expected / periods).
struct SmoothingCorrectionTotal {
  double meanSquare = 0.0;
  double expected = 0.0;
  std::uint64_t periods = 0;
  void add(const SmoothingCorrection& c) {
    if (c.states == 0) return;
    meanSquare += c.meanSquare;
    expected += c.expected;
    ++periods;
  }
  double rms() const { return periods ? std::sqrt(meanSquare / periods) : 0.0; }
  double expectedRms() const { return periods ? std::sqrt(expected / periods) : 0.0; }
};

/// The batch MAP smoother's outcome (sf_estimation/batch_map_smoother.hpp's report).
struct BatchOutcome {
  int iterations = 0;        ///< the most any segment took
  int halvings = 0;          ///< step halvings of the safeguard
  double initialCost = 0.0;  ///< the cost of the filtered track
  double cost = 0.0;         ///< the cost of the smoothed track
  bool converged = false;
};

class PeriodSmoother {
 public:
  virtual ~PeriodSmoother() = default;

  /// Records the belief of the period the core has just estimated. A period that the filter
  /// did not reach by its time update from the previously recorded one (the first, a rejected
  /// step, a filter restart, a clock reset before it) starts a new segment: the backward pass
  /// does not link it to its predecessor.
  virtual void record() = 0;
  /// The backward pass over everything recorded (throws estimation::NumericalError).
  virtual void smooth() = 0;

  virtual std::size_t periods() const = 0;
  /// Segments of the record (1 for an uninterrupted run).
  virtual std::size_t segments() const = 0;
  virtual PeriodBelief filtered(std::size_t period) const = 0;
  /// Valid after smooth().
  virtual PeriodBelief smoothed(std::size_t period) const = 0;
  /// Memory of one period: the record and its smoothed result.
  virtual std::size_t bytesPerPeriod() const = 0;
  /// Valid after smooth(): how far the pass moved period k (SmoothingCorrection).
  virtual SmoothingCorrection correction(std::size_t period) const = 0;
  /// The batch smoother's outcome, valid after smooth(); nullopt for the RTS pass.
  virtual std::optional<BatchOutcome> batchOutcome() const { return std::nullopt; }
};

}  // namespace sf_filter
