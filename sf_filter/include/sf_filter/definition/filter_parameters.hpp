// The numeric parameters of a configuration header with sizes known at run time: what the
// prebuilt node reads from private ROS parameters and the replay from its command line,
// before the header's own code turns them into its fixed-size filter.
#pragma once

#include <Eigen/Core>

#include "sf_filter/config/methods.hpp"

namespace sf_filter {

/// Same members and meaning as the generated sf_config::Parameters (config/detail/parameters.hpp).
struct FilterParameters {
  double estimation_period_ms = 100.0;
  Eigen::MatrixXd process_noise_covariance;      ///< Q, n x n
  Eigen::MatrixXd measurement_noise_covariance;  ///< R, m x m
  Eigen::VectorXd initial_state;                 ///< x0, n
  Eigen::MatrixXd initial_error_covariance;      ///< P0, n x n
  // Each method's own parameters (SF_METHOD_PARAMETER in its traits header, config/methods/).
#define SF_METHOD_PARAMETER(type, name, fallback, header_default) type name = fallback;
#define SF_METHOD_PART SF_METHOD_PART_PARAMETERS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_PARAMETER
  int window_size = 1;
  Eigen::VectorXd weighting_coefficients;  ///< empty: equal weights
};

/// The names of the methods' own parameters, in the order of their members.
inline constexpr const char* kMethodParameterNames[] = {
#define SF_METHOD_PARAMETER(type, name, fallback, header_default) #name,
#define SF_METHOD_PART SF_METHOD_PART_PARAMETERS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_PARAMETER
};

/// f(name, member) for each method's own parameter of `p` (a FilterParameters or the
/// generated sf_config::Parameters, which have the same members).
template <class Parameters, class F>
void forEachMethodParameter(Parameters& p, F&& f) {
#define SF_METHOD_PARAMETER(type, name, fallback, header_default) f(#name, p.name);
#define SF_METHOD_PART SF_METHOD_PART_PARAMETERS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_PARAMETER
}

/// Copies each method's own parameter from `from` to `to` (between FilterParameters and the
/// generated sf_config::Parameters).
template <class To, class From>
void copyMethodParameters(To& to, const From& from) {
#define SF_METHOD_PARAMETER(type, name, fallback, header_default) to.name = from.name;
#define SF_METHOD_PART SF_METHOD_PART_PARAMETERS
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART
#undef SF_METHOD_PARAMETER
}

/// Throws estimation::ParameterError "<name>: expected RxC, found rxc" unless `value` is
/// rows x cols (sf_filter/src/definition/filter_parameters.cpp).
void requireParameterShape(const Eigen::MatrixXd& value, Eigen::Index rows, Eigen::Index cols,
                           const char* name);

}  // namespace sf_filter
