// EXPECT: OK
// The control case: a layout of vector blocks suits the plain Kalman filter (the cases beside
// this one differ from it only in their rotation block).
#include "sf_estimation/kalman_filter.hpp"

using namespace estimation;

using Layout = manifold::StateLayout<manifold::VectorBlock<1>, manifold::VectorBlock<2>>;
template class estimation::KalmanFilter<3, 2, 0, Layout>;
