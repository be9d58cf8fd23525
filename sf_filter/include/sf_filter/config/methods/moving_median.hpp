// Traits of METHOD MOVING_MEDIAN (thesis section 3.5): included once per pass by
// config/methods.hpp, which explains the passes. Needs WINDOW_SIZE.

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE && METHOD == MOVING_MEDIAN
#define SF_CFG_METHOD_NAME "MOVING_MEDIAN"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_WINDOW
#define SF_CFG_METHOD_NEEDS_WINDOW_SIZE 1
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == MOVING_MEDIAN
#include <sf_estimation/moving_median.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::MovingMedian;
inline Filter makeFilter(const sf_config::Parameters& p) {
  return Filter(sf_config::kMeasurementSize, p.window_size);
}

}  // namespace generated
}  // namespace sf_filter
#endif
