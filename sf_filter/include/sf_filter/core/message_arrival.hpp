// The clock reading at which the online node counts an input message.
#pragma once

#include <algorithm>

namespace sf_filter {

/// The reading for a message received at `receipt` when the clock now reads `now` and the
/// core last read `coreClock` (all in seconds of ROS time). The receipt time is when roscpp's
/// receiving thread read the message: on a loaded machine the callback runs periods later,
/// and the value must count for the period the offline replay gives it. A receipt time of 0
/// means the clock was not valid then (simulated time before roscpp's first /clock); `now`
/// stands in. The reading is never before `coreClock`: the node's own /clock subscription can
/// start the schedule while roscpp's clock, kept by another thread, still reads 0, and a
/// reading of 0 would count as time running backwards and reset the filter.
inline double messageArrival(double receipt, double now, double coreClock) {
  return std::max(receipt != 0.0 ? receipt : now, coreClock);
}

}  // namespace sf_filter
