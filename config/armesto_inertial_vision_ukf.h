// Armesto et al.'s MR-UKF: config/armesto_inertial_vision_ekf.h's 19-state inertial+vision model,
// the same Q, R and inputs, with the unscented filter (UKF-M: the mean propagated by the model
// itself, the sigma points on SO(3), the library's default spreads). The paper's UKF spreads
// its sigma points by kappa over whole standard deviations; doc/armesto.md found that the
// spread does not change the library-level MR-UKF's costs on BROAD.
#define METHOD UNSCENTED_KALMAN_FILTER
#include "armesto_inertial_vision_ekf.h"
