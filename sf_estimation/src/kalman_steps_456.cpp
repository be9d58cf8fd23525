// Explicit instantiations of the Kalman steps for state sizes 4 5 6 (kalman_correction.hpp).
#define SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS
#include "sf_estimation/kalman_correction.hpp"

namespace estimation {
SF_ESTIMATION_KALMAN_STEPS(4)
SF_ESTIMATION_KALMAN_STEPS(5)
SF_ESTIMATION_KALMAN_STEPS(6)
}  // namespace estimation
