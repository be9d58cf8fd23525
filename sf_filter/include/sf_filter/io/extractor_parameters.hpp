// The extractor kinds' private parameters (config/extractors/extractor.hpp, e.g.
// ~magnetic_declination of MAGNETIC_YAW inputs), read through a ParameterSource like the node's
// other parameters (ros_parameters.hpp): by the online node from the parameter server and by
// the replay from --params. Only the parameters of the kinds a header's inputs are read by
// exist for its node (NodeDefinition::extractorParameters); each is a double checked against
// its kind's range.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/io/ros_parameters.hpp"

namespace sf_filter {

/// The values of `parameters` that `pnh` sets (the others keep their defaults). Throws
/// ParameterOverrideError for a value that is not a number or out of its range.
inline sf_config::extractors::ParameterValues loadExtractorParameters(
    const ParameterSource& pnh,
    const std::vector<sf_config::extractors::ExtractorParameter>& parameters) {
  sf_config::extractors::ParameterValues values;
  for (const sf_config::extractors::ExtractorParameter& p : parameters) {
    const std::string name(p.name);
    double v = p.defaultValue;
    if (!readScalarParameter(pnh, name, v)) continue;
    if (!(v >= p.minimum && v <= p.maximum)) {
      std::ostringstream message;
      message << "parameter ~" << name << ": expected " << p.meaning << ", found " << v;
      throw ParameterOverrideError(message.str());
    }
    values.set(p.name, v);
  }
  return values;
}

/// The names of `parameters`, for unknownParameterWarnings.
inline std::vector<std::string> extractorParameterNames(
    const std::vector<sf_config::extractors::ExtractorParameter>& parameters) {
  std::vector<std::string> names;
  for (const auto& p : parameters) names.emplace_back(p.name);
  return names;
}

}  // namespace sf_filter
