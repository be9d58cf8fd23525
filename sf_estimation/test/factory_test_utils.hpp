// The factory's answer to a parameter map, for the tests of its parameter checks.
#pragma once

#include <string>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_factory.hpp"

namespace sftest {

/// The ParameterError's message when the factory refuses `map` for `method`, else "accepted".
inline std::string refusal(const std::string& method, const estimation::ParameterMap& map) {
  try {
    estimation::EstimatorFactory::create(method, map);
  } catch (const estimation::ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace sftest
