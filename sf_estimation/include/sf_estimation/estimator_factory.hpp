// Builds any method of the library from a map of named parameters (thesis section 4.3.3),
// with sizes known only at run time. The parameter table is in doc/estimation.md.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "sf_estimation/estimator.hpp"
#include "sf_estimation/function_model.hpp"

namespace estimation {

using Parameter = std::variant<int, double, std::string, Eigen::VectorXd, Eigen::MatrixXd, FunctionModel>;
using ParameterMap = std::map<std::string, Parameter>;

class EstimatorFactory {
 public:
  /// Names accepted by create(): KalmanFilter, ExtendedKalmanFilter, UnscentedKalmanFilter,
  /// ParticleFilterSIR, MovingAverage, MovingMedian, ConfidenceWeightedAveraging.
  static const std::vector<std::string>& methods();

  /// Throws ParameterError naming the method and the parameter when one is missing, unknown,
  /// of the wrong type or of the wrong size.
  static std::unique_ptr<IEstimator> create(const std::string& method, const ParameterMap& parameters);
};

}  // namespace estimation
