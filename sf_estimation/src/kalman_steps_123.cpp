// Explicit instantiations of the Kalman steps for state sizes 1 2 3 (kalman_correction.hpp).
#define SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS
#include "sf_estimation/kalman_correction.hpp"

namespace estimation {
SF_ESTIMATION_KALMAN_STEPS(1)
SF_ESTIMATION_KALMAN_STEPS(2)
SF_ESTIMATION_KALMAN_STEPS(3)
}  // namespace estimation
