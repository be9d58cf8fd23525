// Helpers shared by the tests of the window and averaging estimators (moving average, moving
// median, confidence-weighted averaging): measurements written as lists with NaN for a
// missing entry.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "sf_estimation/measurement.hpp"
#include "sf_estimation/types.hpp"

namespace sftest {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline const double kMissing = std::nan("");  // marks a missing entry for measurementOf()

/// A measurement whose NaN entries are missing.
inline estimation::Measurement<estimation::Dynamic> measurementOf(std::vector<double> values) {
  estimation::Measurement<estimation::Dynamic> z(static_cast<estimation::Index>(values.size()));
  for (estimation::Index i = 0; i < z.size(); ++i) {
    const double v = values[static_cast<std::size_t>(i)];
    z.available(i) = !std::isnan(v);
    z.value(i) = std::isnan(v) ? 0.0 : v;
  }
  return z;
}

}  // namespace sftest
