// Angles in the state and in the measurements (a heading, a compass reading). An angle lives
// on a circle: theta and theta + 2 pi are the same value, so differences are wrapped to
// (-pi, pi] and means are taken on the circle. Which entries are angles is declared once per
// filter (AngularComponents); the filters then
//   - wrap the innovation of every angle measurement (KF, EKF, UKF, PF likelihood, gates),
//   - wrap the angle states of every committed estimate (and of every particle),
//   - average angle rows of sigma points and particles on the circle and wrap their
//     deviations in covariances (UKF, PF).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

/// Indices of the state variables and of the measurements that are angles in radians.
struct AngularComponents {
  std::vector<Index> states;
  std::vector<Index> measurements;

  bool empty() const { return states.empty() && measurements.empty(); }
};

/// a wrapped to (-pi, pi]; NaN for a non-finite a. Exact for |a| <= 3 pi (one subtraction),
/// remainder() beyond, so a huge angle cannot loop.
inline double wrapAngle(double a) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kTwoPi = 2.0 * kPi;
  if (a > kPi) {
    a = a - kTwoPi <= kPi ? a - kTwoPi : std::remainder(a, kTwoPi);
  } else if (a <= -kPi) {
    a = a + kTwoPi > -kPi ? a + kTwoPi : std::remainder(a, kTwoPi);
  }
  if (a <= -kPi) a += kTwoPi;  // remainder() gives [-pi, pi]
  return a;
}

/// Throws ParameterError naming `method` and `what` for an index of `indices` outside
/// [0, size) or listed twice. Compiled once in the library (src/angles.cpp), for masks of
/// every size.
void requireAngleIndices(const std::vector<Index>& indices, Index size, const std::string& method,
                         const std::string& what);

/// Which entries of a vector of size Rows are angles, as a mask built once at construction
/// (a step then only tests booleans, and nothing is done when no entry is an angle).
template <int Rows>
class AngleMask {
 public:
  explicit AngleMask(Index size = (Rows == Dynamic ? 0 : Rows))
      : angular_(Mask<Rows>::Constant(size, false)) {}

  /// Throws ParameterError naming `method` and `what` ("states", "measurements") for an
  /// index outside [0, size) or listed twice.
  AngleMask(const std::vector<Index>& indices, Index size, const std::string& method,
            const std::string& what)
      : AngleMask(size) {
    requireAngleIndices(indices, size, method, what);
    for (const Index i : indices) angular_(i) = true;
    any_ = !indices.empty();
  }

  bool any() const { return any_; }
  bool operator()(Index i) const { return any_ && angular_(i); }
  Index size() const { return angular_.size(); }
  const Mask<Rows>& mask() const { return angular_; }

  /// Wraps the angle entries of a vector (or of every column of a matrix) to (-pi, pi].
  template <class Derived>
  void wrap(Eigen::MatrixBase<Derived>& v) const {
    if (!any_) return;
    for (Index i = 0; i < angular_.size(); ++i) {
      if (!angular_(i)) continue;
      for (Index c = 0; c < v.cols(); ++c) v(i, c) = wrapAngle(v(i, c));
    }
  }

 private:
  Mask<Rows> angular_;
  bool any_ = false;
};

/// atan2(sum w_i sin a_i, sum w_i cos a_i): the direction of the weighted resultant, the
/// circular mean of angles with non-negative weights (particles). 0 when the resultant is zero
/// (angles spread evenly around the circle have no mean direction).
template <class Angles, class Weights>
double circularMean(const Angles& angles, const Weights& weights) {
  double s = 0.0, c = 0.0;
  for (Index i = 0; i < angles.size(); ++i) {
    s += weights(i) * std::sin(angles(i));
    c += weights(i) * std::cos(angles(i));
  }
  return std::atan2(s, c);
}

/// reference + sum w_i wrap(a_i - reference), wrapped: the weighted mean of the angles'
/// deviations from a reference angle, i.e. the mean on the circle in the chart centred at
/// the reference. Used for sigma points (reference: the central point), whose weights may be
/// negative and whose weighted resultant sum w_i (cos, sin) a_i is only 1 - sigma^2 / 2 to
/// second order: for a variance past 2 rad^2 it points backwards and atan2 would flip the
/// mean by pi, while the deviations are exact.
template <class Angles, class Weights>
double meanAround(double reference, const Angles& angles, const Weights& weights) {
  double sum = 0.0;
  for (Index i = 0; i < angles.size(); ++i) sum += weights(i) * wrapAngle(angles(i) - reference);
  return wrapAngle(reference + sum);
}

}  // namespace estimation
