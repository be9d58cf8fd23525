// The YAML file the noise identification writes (doc/tuning.md): a dictionary of private
// parameters that the node loads (rosparam, filter.launch's params) and the replay reads
// (--params), so tuned values need no rebuild. It holds the identified matrices, the period
// they were identified at, and every other entry of the --params file the identification
// started from, so that it alone reproduces the tuned run.
#pragma once

#include <string>
#include <vector>

#include "sf_filter/definition/filter_parameters.hpp"
#include "sf_filter/tuning/noise_tuning.hpp"

namespace sf_filter {

/// A number as YAML 1.1 (rosparam's PyYAML) reads a float: always with a '.' before any
/// exponent ("1.0e-05", not "1e-05", which PyYAML reads as a string).
std::string yamlFloat(double value);

/// The file's text (written by the tools' one writer, AtomicOutput). `comment` lines go at
/// the top; `baseParams` is the --params file the run started from ("" for none): its entries
/// other than those written here are copied. Throws ParameterOverrideError naming that file
/// if it can no longer be read.
std::string tunedParametersYaml(const std::vector<std::string>& comment,
                                const FilterParameters& tuned, const std::vector<FreeEntry>& free,
                                double estimationPeriodSeconds, const std::string& baseParams);

}  // namespace sf_filter
