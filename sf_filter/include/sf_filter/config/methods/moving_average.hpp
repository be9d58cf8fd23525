// Traits of METHOD MOVING_AVERAGE (thesis section 3.5): included once per pass by
// config/methods.hpp, which explains the passes. Needs WINDOW_SIZE; its own macro:
// WEIGHTING_COEFFICIENTS (one weight per measurement of the window; equal weights otherwise).

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE && METHOD == MOVING_AVERAGE
#define SF_CFG_METHOD_NAME "MOVING_AVERAGE"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_WINDOW
#define SF_CFG_METHOD_NEEDS_WINDOW_SIZE 1

#elif SF_METHOD_PART == SF_METHOD_PART_MACROS && METHOD != MOVING_AVERAGE
#if defined(WEIGHTING_COEFFICIENTS)
#error WEIGHTING_COEFFICIENTS is only used by MOVING_AVERAGE: remove it or change METHOD
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif

#elif SF_METHOD_PART == SF_METHOD_PART_CHECKS && METHOD == MOVING_AVERAGE
#if defined(WEIGHTING_COEFFICIENTS)
SF_PP_CHECK_VECTOR("WEIGHTING_COEFFICIENTS", WINDOW_SIZE,
                   "one weight per measurement of the window, WINDOW_SIZE = "
                   SF_PP_STR(WINDOW_SIZE), "(0.5)(0.3)(0.2)", WEIGHTING_COEFFICIENTS)
#endif
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == MOVING_AVERAGE
#include <sf_estimation/moving_average.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::MovingAverage;
inline Filter makeFilter(const sf_config::Parameters& p) {
  if (p.weighting_coefficients.size() > 0) {
    return Filter(sf_config::kMeasurementSize, p.window_size, p.weighting_coefficients);
  }
  return Filter(sf_config::kMeasurementSize, p.window_size);
}

}  // namespace generated
}  // namespace sf_filter
#endif
