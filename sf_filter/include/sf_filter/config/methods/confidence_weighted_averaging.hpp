// Traits of METHOD CONFIDENCE_WEIGHTED_AVERAGING (thesis section 3.5): included once per pass
// by config/methods.hpp, which explains the passes. One estimate (n = 1) from all inputs,
// each weighted by the inverse of its variance, the diagonal of MEASUREMENT_NOISE_COVARIANCE.

// clang-format off
#if SF_METHOD_PART == SF_METHOD_PART_DECLARE && METHOD == CONFIDENCE_WEIGHTED_AVERAGING
#define SF_CFG_METHOD_NAME "CONFIDENCE_WEIGHTED_AVERAGING"
#define SF_CFG_METHOD_KIND SF_METHOD_KIND_WINDOW
#define SF_CFG_METHOD_TAKES_R 1
#define SF_CFG_METHOD_STATE_SIZE 1
#define SF_CFG_METHOD_STATE_SIZE_WHY "n = 1 for CONFIDENCE_WEIGHTED_AVERAGING"
// clang-format on

#elif SF_METHOD_PART == SF_METHOD_PART_BINDING && METHOD == CONFIDENCE_WEIGHTED_AVERAGING
#include <sf_estimation/confidence_weighted_averaging.hpp>

namespace sf_filter {
namespace generated {

using Filter = estimation::ConfidenceWeightedAveraging;
inline Filter makeFilter(const sf_config::Parameters& p) {
  return Filter(sf_config::kMeasurementSize, p.measurement_noise_covariance.diagonal());
}

}  // namespace generated
}  // namespace sf_filter
#endif
