#include "sf_filter/core/innovation_record.hpp"

namespace sf_filter {

void NisSeries::add(double nis, int dof) {
  if (!enabled() || dof <= 0) return;
  window_.add(nis, dof);
  sum_ += nis;
  dof_ += dof;
  ++periods_;
  if (!window_.full()) return;
  ++judged_;
  if (window_.degreesOfFreedom() != cachedDof_) {
    cachedDof_ = window_.degreesOfFreedom();
    cachedBounds_ = window_.bounds();
  }
  if (window_.mean() < cachedBounds_.lower || window_.mean() > cachedBounds_.upper) {
    ++inconsistent_;
  }
}

NisBounds NisSeries::bounds(double alpha) const {
  return chiSquareMeanBounds(dof_, static_cast<double>(periods_), alpha);
}

}  // namespace sf_filter
