// The offline smoother of a fusion core's run (issue 39), seen through sizes known only at run
// time: it records what the core's filter produced in each period (filtered mean, covariance,
// the control of its time update) and, after the forward run, smooths the record with the
// filter's own backward pass (sf_estimation/rts_smoother.hpp; period_smoother_of.hpp
// implements it for one filter type). Made by FusionEngine::makeSmoother().
#pragma once

#include <cstddef>
#include <optional>

#include <Eigen/Core>

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
  /// The batch smoother's outcome, valid after smooth(); nullopt for the RTS pass.
  virtual std::optional<BatchOutcome> batchOutcome() const { return std::nullopt; }
};

}  // namespace sf_filter
