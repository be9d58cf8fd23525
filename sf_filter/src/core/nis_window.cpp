#include "sf_filter/core/nis_window.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>

namespace sf_filter {

double effectiveDegreesOfFreedom(long dof, double periods, double effectivePeriods) {
  const double nu = static_cast<double>(dof) * effectivePeriods / periods;
  return std::max(1.0, std::round(nu * kEffectiveDofSteps)) / kEffectiveDofSteps;
}

NisBounds chiSquareBandPerDof(double effectiveDof, double alpha) {
  const boost::math::chi_squared chi2(effectiveDof);
  return {boost::math::quantile(chi2, alpha / 2.0) / effectiveDof,
          boost::math::quantile(chi2, 1.0 - alpha / 2.0) / effectiveDof};
}

NisBounds NisWindow::bounds(double alpha) const {
  return meanBounds(chiSquareBandPerDof(effectiveDegreesOfFreedom(), alpha), dofSum_,
                    static_cast<double>(size_));
}

}  // namespace sf_filter
