// The numeric parameters of a configuration header with sizes known at run time: what the
// prebuilt node reads from private ROS parameters and the replay from its command line,
// before the header's own code turns them into its fixed-size filter.
#pragma once

#include <Eigen/Core>

namespace sf_filter {

/// Same members and meaning as the generated sf_config::Parameters (config/detail/parameters.hpp).
struct FilterParameters {
  double estimation_period_ms = 100.0;
  Eigen::MatrixXd process_noise_covariance;      ///< Q, n x n
  Eigen::MatrixXd measurement_noise_covariance;  ///< R, m x m
  Eigen::VectorXd initial_state;                 ///< x0, n
  Eigen::MatrixXd initial_error_covariance;      ///< P0, n x n
  int number_of_particles = 1000;
  unsigned random_seed = 42;
  double resampling_threshold = 0.5;
  double ukf_alpha = 1e-3;
  double ukf_beta = 2.0;
  double ukf_kappa = 0.0;
  bool ukf_propagated_mean = false;
  int window_size = 1;
  Eigen::VectorXd weighting_coefficients;  ///< empty: equal weights
};

/// Throws estimation::ParameterError "<name>: expected RxC, found rxc" unless `value` is
/// rows x cols (sf_filter/src/definition/filter_parameters.cpp).
void requireParameterShape(const Eigen::MatrixXd& value, Eigen::Index rows, Eigen::Index cols,
                           const char* name);

}  // namespace sf_filter
