// A measurement vector for one estimation step: values, which entries are present, and
// optional per-entry variances that replace the diagonal of R for this step only.
#pragma once

#include <cmath>
#include <string>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <int M>
struct Measurement {
  Vector<M> value;
  Mask<M> available;       ///< false: the entry is missing this step
  Mask<M> varianceGiven;   ///< true: variance(i) replaces R(i,i) this step
  Vector<M> variance;

  explicit Measurement(Index size = (M == Dynamic ? 0 : M))
      : value(Vector<M>::Zero(size)),
        available(Mask<M>::Constant(size, true)),
        varianceGiven(Mask<M>::Constant(size, false)),
        variance(Vector<M>::Zero(size)) {}

  /// A measurement with every entry present and the configured noise.
  static Measurement complete(const Vector<M>& values) {
    Measurement result(values.size());
    result.value = values;
    return result;
  }

  /// A measurement with every entry missing (the step is a pure time update).
  static Measurement missing(Index size = (M == Dynamic ? 0 : M)) {
    Measurement result(size);
    result.available.setConstant(false);
    return result;
  }

  Index size() const { return value.size(); }
  Index availableCount() const { return available.count(); }
  bool anyAvailable() const { return available.any(); }

  /// Throws InvalidInputError naming the first bad entry; ignores missing entries.
  void validate(Index expectedSize) const {
    if (value.size() != expectedSize || available.size() != expectedSize ||
        varianceGiven.size() != expectedSize || variance.size() != expectedSize) {
      throw InvalidInputError("measurement vector has " + std::to_string(value.size()) +
                              " entries, the filter expects " + std::to_string(expectedSize));
    }
    for (Index i = 0; i < expectedSize; ++i) {
      if (!available(i)) continue;
      if (!std::isfinite(value(i))) {
        throw InvalidInputError("measurement " + std::to_string(i) + " is not finite (" +
                                std::to_string(value(i)) + ")");
      }
      if (varianceGiven(i) && !(std::isfinite(variance(i)) && variance(i) > 0.0)) {
        throw InvalidInputError("variance of measurement " + std::to_string(i) +
                                " must be finite and positive, got " +
                                std::to_string(variance(i)));
      }
    }
  }
};

/// Throws InvalidInputError unless the control vector has the right size and is finite.
template <class Derived>
void validateControl(const Eigen::MatrixBase<Derived>& u, Index expectedSize) {
  if (u.size() != expectedSize) {
    throw InvalidInputError("control vector has " + std::to_string(u.size()) +
                            " entries, the filter expects " + std::to_string(expectedSize));
  }
  for (Index i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u(i))) {
      throw InvalidInputError("control " + std::to_string(i) + " is not finite (" +
                              std::to_string(u(i)) + ")");
    }
  }
}

}  // namespace estimation
