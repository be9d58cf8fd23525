// EXPECT: has an Se2Block
// A plain Kalman filter is linear in R^n: a layout with a rotation is refused at compile time,
// naming the block (kalman_filter.hpp).
#include "sf_estimation/kalman_filter.hpp"

using namespace estimation;

using Layout = manifold::StateLayout<manifold::Se2Block>;
template class estimation::KalmanFilter<3, 2, 0, Layout>;
