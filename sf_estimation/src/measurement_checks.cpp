// The check of a measurement's given covariances, compiled once for the dynamic size and the
// measurement sizes 1..6 (measurement.hpp).
#define SF_ESTIMATION_INSTANTIATING_MEASUREMENT_CHECKS
#include "sf_estimation/measurement.hpp"

namespace estimation {
#define SF_ESTIMATION_MEASUREMENT_CHECK(M) \
  template void Measurement<M>::validateCovariances() const;
SF_ESTIMATION_FOR_CHECKED_MEASUREMENT_SIZES(SF_ESTIMATION_MEASUREMENT_CHECK)
}  // namespace estimation
