#include "sf_filter/core/nis_window.hpp"

#include <boost/math/distributions/chi_squared.hpp>

namespace sf_filter {

NisBounds chiSquareMeanBounds(long dof, double periods, double alpha) {
  const boost::math::chi_squared chi2(static_cast<double>(dof));
  return {boost::math::quantile(chi2, alpha / 2.0) / periods,
          boost::math::quantile(chi2, 1.0 - alpha / 2.0) / periods};
}

NisBounds NisWindow::bounds(double alpha) const {
  return chiSquareMeanBounds(dofSum_, static_cast<double>(size_), alpha);
}

}  // namespace sf_filter
