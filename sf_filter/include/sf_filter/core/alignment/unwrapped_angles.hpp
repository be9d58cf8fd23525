// HOLD and FILL of an angle input (ANGLE_INPUTS, a derived ROLL, PITCH or YAW) extrapolate the
// angle, not its wrapped readings: a heading turning through +-pi reads 3.04, then -3.04, and a
// polynomial through those numbers would swing back across the circle. Before extrapolating,
// each older sample is moved by a multiple of 2 pi to lie within pi of its newer neighbour
// (the newest stays as read), so the history is the continuous angle; the caller wraps the
// extrapolated value to (-pi, pi]. Unwrapping at each use, not when storing, keeps the stored
// values bounded however often the robot turns.
#pragma once

#include <array>

#include <sf_estimation/angles.hpp>

#include "sf_filter/core/alignment/sample_history.hpp"

namespace sf_filter {

/// `angle` moved by a multiple of 2 pi to lie within pi of `reference`.
inline double unwrappedAngle(double angle, double reference) {
  return reference + estimation::wrapAngle(angle - reference);
}

/// The history with every sample unwrapped against its newer neighbour (same times, same
/// length).
inline SampleHistory unwrappedAngles(const SampleHistory& h) {
  std::array<double, SampleHistory::kCapacity> value{};
  for (int age = 0; age < h.size(); ++age) {
    const auto a = static_cast<std::size_t>(age);
    value[a] = age == 0 ? h[0].value : unwrappedAngle(h[age].value, value[a - 1]);
  }
  SampleHistory out(h.length());
  for (int age = h.size() - 1; age >= 0; --age) {
    out.push(h[age].time, value[static_cast<std::size_t>(age)]);
  }
  return out;
}

}  // namespace sf_filter
