#include "sf_estimation/estimator_factory.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "sf_estimation/confidence_weighted_averaging.hpp"
#include "sf_estimation/estimator_adapter.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/moving_average.hpp"
#include "sf_estimation/moving_median.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace estimation {
namespace {

const char* typeName(const Parameter& p) {
  switch (p.index()) {
    case 0:
      return "int";
    case 1:
      return "double";
    case 2:
      return "string";
    case 3:
      return "vector (Eigen::VectorXd)";
    case 4:
      return "matrix (Eigen::MatrixXd)";
    default:
      return "model (FunctionModel)";
  }
}

/// "an integer", "a matrix ...": the article of an expected type in an error message.
std::string article(const std::string& word) {
  return !word.empty() && std::string("aeiou").find(word[0]) != std::string::npos ? "an" : "a";
}

/// Typed, checked access to the parameter map of one method.
class ParameterReader {
 public:
  ParameterReader(std::string method, const ParameterMap& map, std::set<std::string> allowed)
      : method_(std::move(method)), map_(map) {
    for (const auto& entry : map) {
      if (!allowed.count(entry.first)) {
        std::string list;
        for (const auto& name : allowed) list += (list.empty() ? "" : ", ") + name;
        throw ParameterError(method_ + ": unknown parameter '" + entry.first +
                             "' (accepted: " + list + ")");
      }
    }
  }

  bool has(const std::string& name) const { return map_.count(name) != 0; }

  Eigen::MatrixXd matrix(const std::string& name, const std::string& expected) const {
    const Parameter& p = find(name, "matrix " + expected);
    if (const auto* m = std::get_if<Eigen::MatrixXd>(&p)) return *m;
    if (const auto* v = std::get_if<Eigen::VectorXd>(&p)) return *v;
    throw wrongType(name, "matrix " + expected, p);
  }

  Eigen::VectorXd vector(const std::string& name, const std::string& expected) const {
    const Parameter& p = find(name, "vector " + expected);
    if (const auto* v = std::get_if<Eigen::VectorXd>(&p)) return *v;
    if (const auto* m = std::get_if<Eigen::MatrixXd>(&p)) {
      if (m->cols() == 1) return *m;
      throw ParameterError(method_ + ": parameter '" + name + "' must be a vector " + expected +
                           ", got a " + std::to_string(m->rows()) + "x" +
                           std::to_string(m->cols()) + " matrix");
    }
    throw wrongType(name, "vector " + expected, p);
  }

  double number(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    const Parameter& p = map_.at(name);
    if (const auto* d = std::get_if<double>(&p)) return *d;
    if (const auto* i = std::get_if<int>(&p)) return *i;
    throw wrongType(name, "number", p);
  }

  int integer(const std::string& name, int fallback, bool required = false) const {
    if (!has(name)) {
      if (required) throw missing(name, "integer");
      return fallback;
    }
    const Parameter& p = map_.at(name);
    if (const auto* i = std::get_if<int>(&p)) return *i;
    throw wrongType(name, "integer", p);
  }

  /// One of `choices` (a string parameter); `fallback` when the parameter is not given.
  std::string choice(const std::string& name, const std::vector<std::string>& choices,
                     const std::string& fallback) const {
    if (!has(name)) return fallback;
    const Parameter& p = map_.at(name);
    const auto* text = std::get_if<std::string>(&p);
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "'" : ", '") + c + "'";
    if (!text) throw wrongType(name, "string (" + list + ")", p);
    if (std::find(choices.begin(), choices.end(), *text) == choices.end()) {
      throw ParameterError(method_ + ": parameter '" + name + "' is '" + *text + "', expected " +
                           list);
    }
    return *text;
  }

  /// A vector of indices, each an integer-valued finite number (the range is checked by the
  /// filter); empty when the parameter is not given.
  std::vector<Index> indices(const std::string& name) const {
    if (!has(name)) return {};
    const Eigen::VectorXd v = vector(name, "of indices");
    std::vector<Index> result;
    for (Index k = 0; k < v.size(); ++k) {
      if (!std::isfinite(v(k)) || v(k) != std::floor(v(k)) || std::abs(v(k)) > 1e9) {
        throw ParameterError(method_ + ": parameter '" + name + "' entry " + std::to_string(k) +
                             " is not an integer index");
      }
      result.push_back(static_cast<Index>(v(k)));
    }
    return result;
  }

  /// 'angle-states' and 'angle-measurements' (doc/estimation.md, "Angles").
  AngularComponents angles() const {
    return {indices("angle-states"), indices("angle-measurements")};
  }

  FunctionModel model() const {
    const Parameter& p = find("model", "FunctionModel (see makeFunctionModel)");
    if (const auto* m = std::get_if<FunctionModel>(&p)) {
      if (!m->hasTransition() || !m->hasObservation()) {
        throw ParameterError(method_ +
                             ": parameter 'model' has no transition or observation function");
      }
      return *m;
    }
    throw wrongType("model", "FunctionModel", p);
  }

 private:
  const Parameter& find(const std::string& name, const std::string& expected) const {
    auto it = map_.find(name);
    if (it == map_.end()) throw missing(name, expected);
    return it->second;
  }
  ParameterError missing(const std::string& name, const std::string& expected) const {
    return ParameterError(method_ + ": missing parameter '" + name + "' (" + expected + ")");
  }
  ParameterError wrongType(const std::string& name, const std::string& expected,
                           const Parameter& p) const {
    return ParameterError(method_ + ": parameter '" + name + "' must be " + article(expected) +
                          " " + expected + ", got " + typeName(p));
  }

  std::string method_;
  const ParameterMap& map_;
};

/// Q, R, x0, P0 of the Gaussian filters, with x0 = 0 and P0 = I by default.
struct GaussianParameters {
  Eigen::MatrixXd Q, R, P0;
  Eigen::VectorXd x0;

  /// n and m come from the model (or A and H); every matrix is checked against them here so
  /// that an error names the parameter and the size it should have.
  GaussianParameters(const std::string& method, const ParameterReader& in, Index n, Index m) {
    const std::string nn = "(" + std::to_string(n) + "x" + std::to_string(n) + ")";
    Q = in.matrix("Q", nn);
    R = in.matrix("R", "(" + std::to_string(m) + "x" + std::to_string(m) + ")");
    x0 = in.has("x0") ? in.vector("x0", "(" + std::to_string(n) + ")") : Eigen::VectorXd::Zero(n);
    P0 = in.has("P0") ? in.matrix("P0", nn) : Eigen::MatrixXd::Identity(n, n);
    requireSize(method, "Q", Q, n, n);
    requireSize(method, "R", R, m, m);
    requireSize(method, "x0", x0, n, 1);
    requireSize(method, "P0", P0, n, n);
  }
};

template <class Filter>
std::unique_ptr<IEstimator> wrap(Filter filter) {
  return std::make_unique<EstimatorAdapter<Filter>>(std::move(filter));
}

std::unique_ptr<IEstimator> createKalman(const ParameterMap& map) {
  const ParameterReader in(
      "KalmanFilter", map,
      {"A", "B", "H", "Q", "R", "x0", "P0", "angle-states", "angle-measurements"});
  const Eigen::MatrixXd A = in.matrix("A", "(n x n)");
  const Eigen::MatrixXd H = in.matrix("H", "(m x n)");
  const Eigen::MatrixXd B = in.has("B") ? in.matrix("B", "(n x l)") : Eigen::MatrixXd(A.rows(), 0);
  const GaussianParameters g("KalmanFilter", in, A.rows(), H.rows());
  return wrap(KalmanFilter<Dynamic, Dynamic, Dynamic>(A, B, H, g.Q, g.R, g.x0, g.P0, in.angles()));
}

std::unique_ptr<IEstimator> createExtendedKalman(const ParameterMap& map) {
  const ParameterReader in("ExtendedKalmanFilter", map,
                           {"model", "Q", "R", "x0", "P0", "angle-states", "angle-measurements"});
  FunctionModel model = in.model();
  if (!model.hasJacobians()) {
    throw ParameterError(
        "ExtendedKalmanFilter: parameter 'model' has no Jacobians; build it "
        "with makeFunctionModel() from generic lambdas or pass them");
  }
  const GaussianParameters g("ExtendedKalmanFilter", in, model.stateSize(),
                             model.measurementSize());
  return wrap(ExtendedKalmanFilter<FunctionModel>(model, g.Q, g.R, g.x0, g.P0, in.angles()));
}

std::unique_ptr<IEstimator> createUnscentedKalman(const ParameterMap& map) {
  const ParameterReader in("UnscentedKalmanFilter", map,
                           {"model", "Q", "R", "x0", "P0", "alpha", "beta", "kappa", "angle-states",
                            "angle-measurements", "predicted-mean"});
  FunctionModel model = in.model();
  const GaussianParameters g("UnscentedKalmanFilter", in, model.stateSize(),
                             model.measurementSize());
  UnscentedParameters ut;
  ut.alpha = in.number("alpha", ut.alpha);
  ut.beta = in.number("beta", ut.beta);
  ut.kappa = in.number("kappa", ut.kappa);
  if (in.choice("predicted-mean", {"sigma-point-average", "propagated"}, "sigma-point-average") ==
      "propagated") {
    ut.predictedMean = PredictedMean::Propagated;
  }
  return wrap(UnscentedKalmanFilter<FunctionModel>(model, g.Q, g.R, g.x0, g.P0, ut, in.angles()));
}

std::unique_ptr<IEstimator> createParticle(const ParameterMap& map) {
  const ParameterReader in(
      "ParticleFilterSIR", map,
      {"model", "Q", "R", "x0", "P0", "particles", "seed", "resampling-threshold", "angle-states",
       "angle-measurements", "dead-reckoned-states", "proposal"});
  FunctionModel model = in.model();
  const GaussianParameters g("ParticleFilterSIR", in, model.stateSize(), model.measurementSize());
  ParticleFilterParameters pf;
  pf.particles = in.integer("particles", static_cast<int>(pf.particles));
  const int seed = in.integer("seed", static_cast<int>(pf.seed));
  if (seed < 0) throw ParameterError("ParticleFilterSIR: parameter 'seed' must be >= 0");
  pf.seed = static_cast<std::uint64_t>(seed);
  pf.resamplingThreshold = in.number("resampling-threshold", pf.resamplingThreshold);
  pf.sharedDeadReckoning =
      in.choice("dead-reckoned-states", {"per-particle", "shared"}, "per-particle") == "shared";
  if (in.choice("proposal", {"transition", "linearised"}, "transition") == "linearised") {
    pf.proposal = ParticleProposal::Linearised;
  }
  return wrap(ParticleFilterSIR<FunctionModel>(model, g.Q, g.R, g.x0, g.P0, pf, in.angles()));
}

std::unique_ptr<IEstimator> createMovingAverage(const ParameterMap& map) {
  const ParameterReader in("MovingAverage", map, {"input-count", "window-size", "weights"});
  const int inputs = in.integer("input-count", 0, true);
  const int window = in.integer("window-size", 0, true);
  if (in.has("weights")) {
    return wrap(MovingAverage(inputs, window, in.vector("weights", "(window-size)")));
  }
  return wrap(MovingAverage(inputs, window));
}

std::unique_ptr<IEstimator> createMovingMedian(const ParameterMap& map) {
  const ParameterReader in("MovingMedian", map, {"input-count", "window-size"});
  return wrap(MovingMedian(in.integer("input-count", 0, true), in.integer("window-size", 0, true)));
}

std::unique_ptr<IEstimator> createConfidenceWeighted(const ParameterMap& map) {
  const ParameterReader in("ConfidenceWeightedAveraging", map, {"variances"});
  const Eigen::VectorXd variances = in.vector("variances", "(one per input)");
  return wrap(ConfidenceWeightedAveraging(variances.size(), variances));
}

}  // namespace

const std::vector<std::string>& EstimatorFactory::methods() {
  static const std::vector<std::string> names = {
      "KalmanFilter",  "ExtendedKalmanFilter", "UnscentedKalmanFilter",      "ParticleFilterSIR",
      "MovingAverage", "MovingMedian",         "ConfidenceWeightedAveraging"};
  return names;
}

std::unique_ptr<IEstimator> EstimatorFactory::create(const std::string& method,
                                                     const ParameterMap& parameters) {
  if (method == "KalmanFilter") return createKalman(parameters);
  if (method == "ExtendedKalmanFilter") return createExtendedKalman(parameters);
  if (method == "UnscentedKalmanFilter") return createUnscentedKalman(parameters);
  if (method == "ParticleFilterSIR") return createParticle(parameters);
  if (method == "MovingAverage") return createMovingAverage(parameters);
  if (method == "MovingMedian") return createMovingMedian(parameters);
  if (method == "ConfidenceWeightedAveraging") return createConfidenceWeighted(parameters);
  std::string list;
  for (const auto& name : methods()) list += (list.empty() ? "" : ", ") + name;
  throw ParameterError("unknown method '" + method + "' (available: " + list + ")");
}

}  // namespace estimation
