#include "sf_filter/definition/filter_parameters.hpp"

#include <string>

#include <sf_estimation/errors.hpp>

namespace sf_filter {

void requireParameterShape(const Eigen::MatrixXd& value, Eigen::Index rows, Eigen::Index cols,
                           const char* name) {
  if (value.rows() == rows && value.cols() == cols) return;
  throw estimation::ParameterError(
      std::string(name) + ": expected " + std::to_string(rows) + "x" + std::to_string(cols) +
      ", found " + std::to_string(value.rows()) + "x" + std::to_string(value.cols()));
}

}  // namespace sf_filter
