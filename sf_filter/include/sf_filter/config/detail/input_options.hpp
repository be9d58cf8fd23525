// The fusion core's per-input options (sf_filter/core/input_options.hpp) as the configuration
// header sets them: alignment policy, gate and alignment by stamp (input_alignment.hpp), sensor
// timeout and plausible range (input_faults.hpp), and whether it is an angle (angles.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "sf_filter/config/detail/angles.hpp"
#include "sf_filter/config/detail/input_alignment.hpp"
#include "sf_filter/config/detail/input_faults.hpp"
#include "sf_filter/core/input_options.hpp"

namespace sf_config {

/// One entry per TOPICS_IN entry.
inline std::vector<::sf_filter::InputOptions> defaultInputOptions() {
  std::vector<::sf_filter::InputOptions> inputs(static_cast<std::size_t>(kMeasurementSize));
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    inputs[i].alignment = kInputAlignment[i];
    inputs[i].gateThreshold = kGateThresholds[i];
    inputs[i].alignByStamp = kAlignByStamp[i];
    inputs[i].timeout = kInputTimeoutsMs[i] / 1000.0;
    inputs[i].minimum = kInputRanges[i].minimum;
    inputs[i].maximum = kInputRanges[i].maximum;
    inputs[i].angle = kAngleInputs[i];
  }
  return inputs;
}

}  // namespace sf_config
