// The check of a measurement's given covariances, compiled once for the dynamic size and the
// measurement sizes 1..6 (measurement.hpp).
#define SF_ESTIMATION_INSTANTIATING_MEASUREMENT_CHECKS
#include "sf_estimation/measurement.hpp"

namespace estimation {
#define SF_ESTIMATION_MEASUREMENT_CHECK(M) \
  template void Measurement<M>::validateCovariances() const;
SF_ESTIMATION_FOR_CHECKED_MEASUREMENT_SIZES(SF_ESTIMATION_MEASUREMENT_CHECK)
}  // namespace estimation

namespace estimation {
namespace detail {

void refuseInputSize(const char* what, Index size, Index expected) {
  throw InvalidInputError(std::string(what) + " vector has " + std::to_string(size) +
                          " entries, the filter expects " + std::to_string(expected));
}

void refuseNonFiniteInput(const char* what, Index i, double value) {
  throw InvalidInputError(std::string(what) + " " + std::to_string(i) + " is not finite (" +
                          std::to_string(value) + ")");
}

void refuseMeasurementVariance(Index i, double variance) {
  throw InvalidInputError("variance of measurement " + std::to_string(i) +
                          " must be finite and positive, got " + std::to_string(variance));
}

}  // namespace detail
}  // namespace estimation
