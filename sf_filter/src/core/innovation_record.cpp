#include "sf_filter/core/innovation_record.hpp"

#include <cmath>

namespace sf_filter {

NisSeries::NisSeries(std::size_t window, int maxDofPerPeriod, double tolerance)
    : window_(window, -1.0, tolerance), autocorrelation_(0.0) {
  const std::size_t slots = window * static_cast<std::size_t>(maxDofPerPeriod) *
                                static_cast<std::size_t>(kEffectiveDofSteps) +
                            1;
  if (window > 0 && slots <= kMaxCachedBounds)
    boundsByGridStep_.assign(slots, NisBounds{-1.0, -1.0});
}

NisBounds NisSeries::windowBounds() {
  const double nu = window_.effectiveDegreesOfFreedom();
  const long step = std::lround(nu * kEffectiveDofSteps);
  const auto slot = static_cast<std::size_t>(step);
  const NisBounds* band = nullptr;
  if (slot < boundsByGridStep_.size()) {
    if (boundsByGridStep_[slot].lower < 0.0) boundsByGridStep_[slot] = chiSquareBandPerDof(nu);
    band = &boundsByGridStep_[slot];
  } else {
    if (step != lastGridStep_) {
      lastGridStep_ = step;
      lastBounds_ = chiSquareBandPerDof(nu);
    }
    band = &lastBounds_;
  }
  return meanBounds(*band, window_.degreesOfFreedom(), static_cast<double>(window_.size()));
}

void NisSeries::add(double nis, int dof) {
  if (!enabled() || dof <= 0) return;
  window_.add(nis, dof);
  autocorrelation_.add(nis / dof);
  sum_ += nis;
  dof_ += dof;
  ++periods_;
  if (!window_.full()) return;
  ++judged_;
  if (NisWindow::outside(window_.mean(), windowBounds(), window_.expectedMean(),
                         window_.tolerance())) {
    ++inconsistent_;
  }
}

NisBounds NisSeries::bounds(double alpha) const {
  const double periods = static_cast<double>(periods_);
  return meanBounds(
      chiSquareBandPerDof(effectiveDegreesOfFreedom(dof_, periods, effectivePeriods()), alpha),
      dof_, periods);
}

}  // namespace sf_filter
