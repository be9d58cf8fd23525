// The inputs' names from the INPUTS records (input_records.hpp), for diagnostics, logs and the
// run-time overrides; a header in the thesis syntax (TOPICS_IN) has none.
#pragma once

#include <array>
#include <string_view>

#include "sf_filter/config/detail/constants.hpp"

namespace sf_config {

#if defined(SF_INPUTS_NAMES)
inline constexpr bool kHasInputRecords = true;
/// The record name of input i.
inline constexpr std::array<std::string_view, kMeasurementSize> kInputNames{SF_INPUTS_NAMES};
#else
inline constexpr bool kHasInputRecords = false;
/// Empty: inputs of the thesis syntax are named by topic and field.
inline constexpr std::array<std::string_view, kMeasurementSize> kInputNames{};
#endif

}  // namespace sf_config
