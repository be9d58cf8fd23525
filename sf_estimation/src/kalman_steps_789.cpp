// Explicit instantiations of the Kalman steps for state sizes 7 8 9 (kalman_correction.hpp).
#define SF_ESTIMATION_INSTANTIATING_KALMAN_STEPS
#include "sf_estimation/kalman_correction.hpp"

namespace estimation {
SF_ESTIMATION_KALMAN_STEPS(7)
SF_ESTIMATION_KALMAN_STEPS(8)
SF_ESTIMATION_KALMAN_STEPS(9)
}  // namespace estimation
