#include "sf_filter/core/nis_window.hpp"

#include <boost/math/distributions/chi_squared.hpp>

namespace sf_filter {

NisBounds NisWindow::bounds(double alpha) const {
  const boost::math::chi_squared chi2(static_cast<double>(dofSum_));
  const double k = static_cast<double>(size_);
  return {boost::math::quantile(chi2, alpha / 2.0) / k,
          boost::math::quantile(chi2, 1.0 - alpha / 2.0) / k};
}

}  // namespace sf_filter
