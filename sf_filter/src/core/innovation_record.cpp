#include "sf_filter/core/innovation_record.hpp"

namespace sf_filter {

NisSeries::NisSeries(std::size_t window, int maxDofPerPeriod) : window_(window) {
  const std::size_t slots = window * static_cast<std::size_t>(maxDofPerPeriod) + 1;
  if (window > 0 && slots <= kMaxCachedBounds) boundsByDof_.assign(slots, NisBounds{-1.0, -1.0});
}

const NisBounds& NisSeries::windowBounds(long dof) {
  const auto slot = static_cast<std::size_t>(dof);
  if (slot < boundsByDof_.size()) {
    if (boundsByDof_[slot].lower < 0.0) boundsByDof_[slot] = window_.bounds();
    return boundsByDof_[slot];
  }
  if (dof != lastDof_) {
    lastDof_ = dof;
    lastBounds_ = window_.bounds();
  }
  return lastBounds_;
}

void NisSeries::add(double nis, int dof) {
  if (!enabled() || dof <= 0) return;
  window_.add(nis, dof);
  sum_ += nis;
  dof_ += dof;
  ++periods_;
  if (!window_.full()) return;
  ++judged_;
  const NisBounds& b = windowBounds(window_.degreesOfFreedom());
  if (window_.mean() < b.lower || window_.mean() > b.upper) ++inconsistent_;
}

NisBounds NisSeries::bounds(double alpha) const {
  return chiSquareMeanBounds(dof_, static_cast<double>(periods_), alpha);
}

}  // namespace sf_filter
