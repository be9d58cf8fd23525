#include "sf_filter/definition/filter_parameters.hpp"

#include <string>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/parameter_checks.hpp>

namespace sf_filter {

void requireParameterShape(const Eigen::MatrixXd& value, Eigen::Index rows, Eigen::Index cols,
                           const char* name) {
  if (value.rows() == rows && value.cols() == cols) return;
  throw estimation::ParameterError(std::string(name) + ": expected " +
                                   estimation::sizeText(rows, cols) + ", found " +
                                   estimation::sizeText(value.rows(), value.cols()));
}

}  // namespace sf_filter
