// The particle filter's noise whitening for the measurement sizes 1..6, compiled once
// (particle_filter_steps.hpp); the state-size parts are in the generated sigma_point_steps_*.cpp.
#define SF_ESTIMATION_INSTANTIATING_SIGMA_POINT_STEPS
#include "sf_estimation/particle_filter_steps.hpp"

namespace estimation {
SF_ESTIMATION_NOISE_WHITENING(1)
SF_ESTIMATION_NOISE_WHITENING(2)
SF_ESTIMATION_NOISE_WHITENING(3)
SF_ESTIMATION_NOISE_WHITENING(4)
SF_ESTIMATION_NOISE_WHITENING(5)
SF_ESTIMATION_NOISE_WHITENING(6)
}  // namespace estimation
