// Noise identification from a recording by the prediction-error method (Ljung, "System
// Identification", ch. 7; for Kalman filters e.g. Bar-Shalom et al., "Estimation with
// Applications to Tracking and Navigation", 11.2): the free entries of Q, R and P0 are chosen
// to minimise
//
//   J = sum_k (log det S_k + y_k^T S_k^-1 y_k),
//
// twice the negative log-likelihood of the innovations y_k with covariances S_k over the
// periods with measured inputs (up to a constant), each evaluation one replay of the recorded
// events (event_log.hpp) through a fresh fusion core. A free entry is a diagonal variance,
// optimised as the logarithm of its factor over the starting value within [1/range, range],
// by NLopt's derivative-free BOBYQA (Powell); a correlated off-diagonal entry scales with
// sqrt(f_i f_j), so the correlation stays and every trial matrix is a covariance.
//
// Only for the Kalman filters (KF, EKF, UKF), whose S is their innovation covariance: the
// particle filter's likelihood is a Monte Carlo estimate that changes with every draw, and
// the averaging methods have no model.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/definition/filter_parameters.hpp"
#include "sf_filter/tuning/event_log.hpp"

namespace sf_filter {

/// One free diagonal entry: `matrix` "Q", "R" or "P0", and its index.
struct FreeEntry {
  std::string matrix;
  Index index = 0;
  std::string name() const { return matrix + "." + std::to_string(index); }
};

/// The entries of `list`, a comma-separated list of "Q", "R", "P0" (every non-zero diagonal
/// entry of the matrix) and "Q.i", "R.i", "P0.i" (one diagonal entry). Throws
/// std::invalid_argument naming a bad item, an index out of range, or an entry that is 0 in
/// `start` (a zero variance is structural: it cannot be scaled).
std::vector<FreeEntry> parseFreeEntries(const std::string& list, const FilterParameters& start);

/// Why the noise identification does not apply to a method ("" when it does).
std::string tuningRefusal(const std::string& method);

struct TuningOptions {
  double range = 1000.0;      ///< each variance within [start / range, start * range]
  int maxEvaluations = 2000;  ///< replays at most
  /// The last part of the recording's time span held out by the guard (0: no guard).
  double holdout = 0.3;
  bool keepUnidentified = false;  ///< write entries the recording does not identify
};

struct TuningResult {
  FilterParameters tuned;
  std::vector<double> factors;  ///< per free entry: tuned / start
  std::vector<bool> atBound;    ///< per free entry: ended within 1 % of a bound
  double startCost = 0.0, cost = 0.0;
  int evaluations = 0;
  std::string stop;  ///< NLopt's reason to stop
  /// Periods with an innovation in the replay from the start: 0, and the cost is an empty sum.
  std::uint64_t innovationPeriods = 0;
  /// The highest minus the lowest cost over the start and the replays at other values of
  /// the free entries (-1: there was none).
  double costSpread = -1.0;
};

/// The engine of the header's filter for one set of parameters.
using EngineMaker = std::function<std::unique_ptr<FusionEngine>(const FilterParameters&)>;

/// The prediction-error cost J of `parameters` on `events`; +infinity when a step failed or
/// an innovation covariance was not positive definite.
double predictionErrorCost(const EventLog& events, const EngineMaker& makeEngine,
                           const FilterParameters& parameters);

/// Minimises J over `free` from `start`.
TuningResult tuneNoise(const EventLog& events, const EngineMaker& makeEngine,
                       const FilterParameters& start, const std::vector<FreeEntry>& free,
                       const TuningOptions& options);

/// Why the result identifies nothing and must not be written ("" when it does): no period
/// with a finite innovation, every replay failed, or a cost that did not change by the
/// optimiser's tolerance (1e-4) whatever the free entries (flat: they do not enter it).
std::string identificationRefusal(const TuningResult& result);

/// How the recording identifies one free entry at the tuned values: whether it ended at a
/// bound of the range, and how much the cost rises when the entry alone is divided or
/// multiplied by kIdentificationProbe (a factor-4 span around the optimum).
struct EntryIdentification {
  bool atBound = false;
  double riseDown = 0.0, riseUp = 0.0;
  /// Off the bounds and the cost rising by kIdentifiedRise or more on both sides.
  bool identified() const;
};

/// The probe's factor (the entry at 1/2 and 2 times its tuned value).
constexpr double kIdentificationProbe = 2.0;
/// The rise of J (twice the negative log-likelihood) that a likelihood-ratio test of one
/// parameter needs at 95 % (the chi-square(1) quantile): below it on either side, the
/// recording cannot tell the tuned value from one twice or half as large.
constexpr double kIdentifiedRise = 3.84;

/// Per free entry of `result` (tuned from `start` on `events`), two more replays.
std::vector<EntryIdentification> identifyEntries(const EventLog& events,
                                                 const EngineMaker& makeEngine,
                                                 const FilterParameters& start,
                                                 const std::vector<FreeEntry>& free,
                                                 const TuningResult& result);

/// The cost of `parameters` over the periods estimated after the first `split` events of
/// `events` (the filter runs through the first part): its mean per period with an innovation.
struct HeldOutCost {
  double mean = 0.0;          ///< +infinity when a step failed
  std::uint64_t periods = 0;  ///< 0: the later part has no innovation
};
HeldOutCost heldOutCost(const EventLog& events, std::size_t split, const EngineMaker& makeEngine,
                        const FilterParameters& parameters);

/// `start` with the free entries' variances multiplied by `factors` (correlations kept).
FilterParameters scaledParameters(const FilterParameters& start, const std::vector<FreeEntry>& free,
                                  const std::vector<double>& factors);

}  // namespace sf_filter
