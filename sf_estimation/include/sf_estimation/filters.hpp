// Every estimation method of the library, for code that chooses among them at compile time
// (the fusion node's filter binding, and the node units' precompiled prelude).
#pragma once

#include "sf_estimation/confidence_weighted_averaging.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/moving_average.hpp"
#include "sf_estimation/moving_median.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
