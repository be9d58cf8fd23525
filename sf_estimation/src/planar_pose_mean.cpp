#include "sf_estimation/planar_pose_mean.hpp"

#include <string>

#include "sf_estimation/errors.hpp"

namespace estimation {

void requirePlanarPose(const std::string& method, const PlanarPoseIndices& k, Index size,
                       bool headingIsAngle) {
  const Index entries[3] = {k.x, k.y, k.heading};
  const char* names[3] = {"x", "y", "heading"};
  for (int e = 0; e < 3; ++e) {
    if (entries[e] < 0 || entries[e] >= size) {
      throw ParameterError(method + ": planar pose " + names[e] + " index " +
                           std::to_string(entries[e]) + " is out of range [0, " +
                           std::to_string(size) + ")");
    }
  }
  if (k.x == k.y || k.x == k.heading || k.y == k.heading) {
    throw ParameterError(method + ": planar pose indices (" + std::to_string(k.x) + ", " +
                         std::to_string(k.y) + ", " + std::to_string(k.heading) +
                         ") are not three different states");
  }
  if (!headingIsAngle) {
    throw ParameterError(method + ": planar pose heading x[" + std::to_string(k.heading) +
                         "] is not an angle state (declare it in angle-states)");
  }
}

}  // namespace estimation
