#include "sf_filter/tuning/noise_tuning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlopt.hpp>

#include "sf_filter/config/methods.hpp"

namespace sf_filter {

namespace {

Eigen::MatrixXd& matrixOf(FilterParameters& p, const std::string& name) {
  if (name == "Q") return p.process_noise_covariance;
  if (name == "R") return p.measurement_noise_covariance;
  return p.initial_error_covariance;
}

const Eigen::MatrixXd& matrixOf(const FilterParameters& p, const std::string& name) {
  return matrixOf(const_cast<FilterParameters&>(p), name);  // NOLINT: read-only use
}

/// A penalty far above any cost of a run that works, finite so that BOBYQA's quadratic
/// models stay finite.
constexpr double kFailedRunCost = 1e100;

}  // namespace

std::string tuningRefusal(const std::string& method) {
  // The methods that can be tuned ("") or why not, from their traits headers.
#define SF_METHOD_TUNING(name, refusal) \
  if (method == #name) return refusal;
#define SF_METHOD_PART SF_METHOD_PART_TUNING
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_TUNING
  return "the noise identification needs a model with a predicted measurement and its "
         "covariance (KF, EKF, UKF); method " +
         method + " has none";
}

std::vector<FreeEntry> parseFreeEntries(const std::string& list, const FilterParameters& start) {
  std::vector<FreeEntry> free;
  auto add = [&](const FreeEntry& e) {
    for (const FreeEntry& f : free) {
      if (f.matrix == e.matrix && f.index == e.index) return;  // named twice: once
    }
    free.push_back(e);
  };
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t dot = item.find('.');
    const std::string matrix = item.substr(0, dot);
    if (matrix != "Q" && matrix != "R" && matrix != "P0") {
      throw std::invalid_argument("--free: '" + item +
                                  "' is not Q, R, P0 or one of their diagonal entries "
                                  "(Q.i, R.i, P0.i)");
    }
    const Eigen::MatrixXd& m = matrixOf(start, matrix);
    if (dot == std::string::npos) {
      for (Index i = 0; i < m.rows(); ++i) {
        if (m(i, i) > 0.0) add({matrix, i});
      }
      continue;
    }
    std::size_t used = 0;
    long index = -1;
    try {
      index = std::stol(item.substr(dot + 1), &used);
    } catch (const std::logic_error&) {
      used = 0;
    }
    if (used == 0 || used != item.size() - dot - 1 || index < 0 || index >= m.rows()) {
      throw std::invalid_argument("--free: '" + item + "': " + matrix + " has diagonal entries " +
                                  matrix + ".0 .. " + matrix + "." + std::to_string(m.rows() - 1));
    }
    if (!(m(index, index) > 0.0)) {
      throw std::invalid_argument("--free: " + item +
                                  " is 0 in the configuration: a zero variance is structural and "
                                  "cannot be scaled; give it a positive start value with --params");
    }
    add({matrix, static_cast<Index>(index)});
  }
  if (free.empty()) throw std::invalid_argument("--free '" + list + "': no free entry");
  return free;
}

FilterParameters scaledParameters(const FilterParameters& start, const std::vector<FreeEntry>& free,
                                  const std::vector<double>& factors) {
  FilterParameters p = start;
  for (const char* name : {"Q", "R", "P0"}) {
    const Eigen::MatrixXd& from = matrixOf(start, name);
    Eigen::VectorXd root = Eigen::VectorXd::Ones(from.rows());
    for (std::size_t k = 0; k < free.size(); ++k) {
      if (free[k].matrix == name) root(free[k].index) = std::sqrt(factors[k]);
    }
    matrixOf(p, name) = root.asDiagonal() * from * root.asDiagonal();
  }
  return p;
}

namespace {

/// The cost of one replay and the periods with an innovation it summed over.
struct ReplayCost {
  double cost = kFailedRunCost;
  std::uint64_t periods = 0;
};

ReplayCost replayCost(const EventLog& events, const EngineMaker& makeEngine,
                      const FilterParameters& parameters) {
  std::unique_ptr<FusionEngine> engine;
  try {
    engine = makeEngine(parameters);
  } catch (const std::exception&) {
    return {};  // the filter refused the matrices (should not happen: covariances)
  }
  auto ignore = [](const EstimateRef&) {};
  events.replay(*engine, ignore);
  const double cost = engine->innovations().predictionErrorCost();
  const FusionStatistics statistics = engine->statistics();
  if (statistics.estimationFailures > 0 || statistics.nisFailures > 0 || !std::isfinite(cost)) {
    return {};
  }
  return {cost, engine->innovations().overall().periods()};
}

/// A change of the cost by 1e-4 is far below what the data can tell apart (a likelihood-ratio
/// test needs a change of about 4 for one parameter): the optimiser's tolerance, and the
/// spread below which the cost is flat.
constexpr double kCostTolerance = 1e-4;

/// The optimiser's objective: the cost at the factors exp(theta), and the lowest and highest
/// cost at a trial point other than the start (theta = 0).
struct Objective {
  const EventLog& events;
  const EngineMaker& makeEngine;
  const FilterParameters& start;
  const std::vector<FreeEntry>& free;
  int evaluations = 0;
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -std::numeric_limits<double>::infinity();

  static double evaluate(const std::vector<double>& theta, std::vector<double>&, void* data) {
    auto& o = *static_cast<Objective*>(data);
    ++o.evaluations;
    std::vector<double> factors(theta.size());
    bool moved = false;
    for (std::size_t k = 0; k < theta.size(); ++k) {
      factors[k] = std::exp(theta[k]);
      moved = moved || theta[k] != 0.0;
    }
    const double cost =
        replayCost(o.events, o.makeEngine, scaledParameters(o.start, o.free, factors)).cost;
    if (moved) {
      o.lowest = std::min(o.lowest, cost);
      o.highest = std::max(o.highest, cost);
    }
    return cost;
  }
};

/// The optimiser's reason to stop, in words.
std::string stopReason(nlopt::result r) {
  switch (r) {
    case nlopt::FTOL_REACHED:
      return "the cost changed by less than 1e-4";
    case nlopt::XTOL_REACHED:
      return "the factors changed by less than 0.01 %";
    case nlopt::MAXEVAL_REACHED:
      return "the maximum number of replays was reached";
    default:
      return "NLopt result " + std::to_string(static_cast<int>(r));
  }
}

/// Minimises the objective from theta = 0 within +-log(range); the optimiser's reason to stop.
std::string minimise(Objective& objective, const TuningOptions& options, std::vector<double>& theta,
                     double& best) {
  const auto n = static_cast<unsigned>(theta.size());
  // BOBYQA models the cost by a quadratic through 2n + 1 points and needs n >= 2; one free
  // entry is a line search, which Nelder-Mead does without a model.
  nlopt::opt opt(n >= 2 ? nlopt::LN_BOBYQA : nlopt::LN_NELDERMEAD, n);
  const double bound = std::log(options.range);
  opt.set_lower_bounds(std::vector<double>(n, -bound));
  opt.set_upper_bounds(std::vector<double>(n, bound));
  opt.set_min_objective(&Objective::evaluate, &objective);
  // 1e-4 in log is a factor of 1.0001.
  opt.set_ftol_abs(kCostTolerance);
  opt.set_xtol_abs(1e-4);
  opt.set_maxeval(options.maxEvaluations);
  opt.set_initial_step(std::vector<double>(n, std::min(1.0, bound / 2.0)));
  try {
    return stopReason(opt.optimize(theta, best));
  } catch (const nlopt::roundoff_limited&) {
    return "rounding errors limited the progress (the result is the best point found)";
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("the optimiser failed: ") + e.what());
  }
}

}  // namespace

double predictionErrorCost(const EventLog& events, const EngineMaker& makeEngine,
                           const FilterParameters& parameters) {
  return replayCost(events, makeEngine, parameters).cost;
}

TuningResult tuneNoise(const EventLog& events, const EngineMaker& makeEngine,
                       const FilterParameters& start, const std::vector<FreeEntry>& free,
                       const TuningOptions& options) {
  if (!(options.range > 1.0)) throw std::invalid_argument("--tune-range must be above 1");
  if (options.maxEvaluations < 1) throw std::invalid_argument("--max-evaluations must be >= 1");
  const auto n = static_cast<unsigned>(free.size());
  TuningResult result;
  const ReplayCost atStart = replayCost(events, makeEngine, start);
  result.startCost = atStart.cost;
  result.innovationPeriods = atStart.periods;
  std::vector<double> theta(n, 0.0);
  Objective objective{events, makeEngine, start, free};
  if (atStart.periods == 0) {
    result.stop = "no period with an innovation: nothing to minimise";
  } else {
    double best = result.startCost;
    result.stop = minimise(objective, options, theta, best);
  }
  result.evaluations = objective.evaluations;
  if (objective.highest >= objective.lowest) {
    result.costSpread = std::max(objective.highest, result.startCost) -
                        std::min(objective.lowest, result.startCost);
  }
  const double bound = std::log(options.range);
  result.factors.resize(n);
  result.atBound.resize(n);
  for (unsigned k = 0; k < n; ++k) {
    result.factors[k] = std::exp(theta[k]);
    result.atBound[k] = std::abs(theta[k]) > bound - std::log(1.01);
  }
  result.tuned = scaledParameters(start, free, result.factors);
  result.cost = predictionErrorCost(events, makeEngine, result.tuned);
  return result;
}

bool EntryIdentification::identified() const {
  return !atBound && riseDown >= kIdentifiedRise && riseUp >= kIdentifiedRise;
}

std::vector<EntryIdentification> identifyEntries(const EventLog& events,
                                                 const EngineMaker& makeEngine,
                                                 const FilterParameters& start,
                                                 const std::vector<FreeEntry>& free,
                                                 const TuningResult& result) {
  std::vector<EntryIdentification> out(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) {
    std::vector<double> probe = result.factors;
    out[k].atBound = result.atBound[k];
    probe[k] = result.factors[k] / kIdentificationProbe;
    out[k].riseDown =
        predictionErrorCost(events, makeEngine, scaledParameters(start, free, probe)) - result.cost;
    probe[k] = result.factors[k] * kIdentificationProbe;
    out[k].riseUp =
        predictionErrorCost(events, makeEngine, scaledParameters(start, free, probe)) - result.cost;
  }
  return out;
}

HeldOutCost heldOutCost(const EventLog& events, std::size_t split, const EngineMaker& makeEngine,
                        const FilterParameters& parameters) {
  std::unique_ptr<FusionEngine> engine;
  try {
    engine = makeEngine(parameters);
  } catch (const std::exception&) {
    return {std::numeric_limits<double>::infinity(), 0};
  }
  auto ignore = [](const EstimateRef&) {};
  ReplayClock clock;
  events.replay(*engine, ignore, clock, 0, split);
  const double before = engine->innovations().predictionErrorCost();
  const std::uint64_t periodsBefore = engine->innovations().overall().periods();
  events.replay(*engine, ignore, clock, split, events.size());
  const FusionStatistics statistics = engine->statistics();
  HeldOutCost held;
  held.periods = engine->innovations().overall().periods() - periodsBefore;
  const double cost = engine->innovations().predictionErrorCost() - before;
  const bool failed = statistics.estimationFailures > 0 || statistics.nisFailures > 0;
  held.mean = failed || !std::isfinite(cost) ? std::numeric_limits<double>::infinity()
              : held.periods > 0             ? cost / static_cast<double>(held.periods)
                                             : 0.0;
  return held;
}

std::string identificationRefusal(const TuningResult& r) {
  if (r.innovationPeriods == 0) {
    return "the recording identifies nothing: no period has a finite innovation (no "
           "estimated period had a measured value: every value dropped, or none in a period "
           "that ended within the recording; the replay's summary above counts them)";
  }
  if (r.startCost >= kFailedRunCost && r.cost >= kFailedRunCost) {
    return "the recording identifies nothing: every replay failed (a failed step, or an "
           "innovation covariance that was not positive definite)";
  }
  if (r.costSpread >= 0.0 && r.costSpread < kCostTolerance) {
    char spread[64];
    std::snprintf(spread, sizeof spread, "%.3g", r.costSpread);
    return std::string(
               "the recording does not identify the free entries: the cost stayed "
               "within ") +
           spread + " (below 1e-4) over " + std::to_string(r.evaluations) +
           " replays with other values of them (the cost is flat in them)";
  }
  return "";
}

}  // namespace sf_filter
