// The options of a fusion core (fusion_core.hpp) that do not depend on the filter's type, so
// that the code reading them from ROS parameters or the replay's command line is compiled
// once for every configuration header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "sf_filter/core/input_options.hpp"

namespace sf_filter {

struct FusionCoreOptions {
  double period = 0.1;  ///< estimation period [s]
  /// A forward clock jump longer than this many periods is skipped (one estimate) instead
  /// of estimating every missed period, so a stalled clock never floods the output.
  std::uint64_t maxCatchUpPeriods = 100;
  /// One entry per input, or none: every input AVERAGE, by arrival time, without gate.
  std::vector<InputOptions> inputs;
  /// How long after its end a period stays open for stamped values [s] (fusion_core.hpp).
  double maxMeasurementLag = 0.0;
  /// A stamp more than this ahead of the clock reading at arrival is dropped [s] (a sensor
  /// clock far ahead would otherwise block its input: every later stamp looks older).
  /// Infinite: no check.
  double maxFutureStamp = std::numeric_limits<double>::infinity();
  /// Periods over which the NIS is averaged (nis_window.hpp); 0: not computed. Costs one
  /// measurement prediction per period when no gate or FILL needs it anyway.
  std::size_t nisWindow = 0;
};

}  // namespace sf_filter
