// Kalman filter (thesis Algorithm 3.1) for the linear model x' = A x + B u, z = H x.
#pragma once

#include <type_traits>

#include "sf_estimation/abstract_kalman_filter.hpp"
#include "sf_estimation/kalman_correction.hpp"
#include "sf_estimation/manifold/se2.hpp"
#include "sf_estimation/manifold/state_layout.hpp"
#include "sf_estimation/measurement_prediction.hpp"

namespace estimation {

namespace kalman_layout {

template <class>
inline constexpr bool kRefused = false;

/// A block of the plain Kalman filter's layout: x' = A x + B u is linear in R^n, so only vector
/// blocks fit; a rotation is refused at compile time, by name (doc/manifolds.md).
template <class Block, class = void>
struct Accepted {
  static_assert(Block::IsFlat,
                "KalmanFilter: the state layout has a block that is not a VectorBlock; a linear "
                "Kalman filter holds vector entries only: use ManifoldExtendedKalmanFilter or "
                "ManifoldUnscentedKalmanFilter");
};
template <class V>
struct Accepted<manifold::So2Block, V> {
  static_assert(kRefused<V>,
                "KalmanFilter: the state layout has an So2Block (an SO(2) angle), which a linear "
                "Kalman filter cannot hold: use ManifoldExtendedKalmanFilter or "
                "ManifoldUnscentedKalmanFilter");
};
template <class V>
struct Accepted<manifold::So3Block, V> {
  static_assert(kRefused<V>,
                "KalmanFilter: the state layout has an So3Block (an SO(3) unit quaternion), which "
                "a linear Kalman filter cannot hold: use ManifoldExtendedKalmanFilter or "
                "ManifoldUnscentedKalmanFilter");
};
template <class V>
struct Accepted<manifold::Se2Block, V> {
  static_assert(kRefused<V>,
                "KalmanFilter: the state layout has an Se2Block (an SE(2) pose), which a linear "
                "Kalman filter cannot hold: use ManifoldExtendedKalmanFilter or "
                "ManifoldUnscentedKalmanFilter");
};

/// Whether Layout (void: N plain entries) suits a KalmanFilter of N states; each block is
/// checked above, so that the first error names the refused block.
template <class Layout, int N>
struct Check {
  static constexpr bool value = std::is_void_v<Layout>;
};
template <int N, class... Blocks>
struct Check<manifold::StateLayout<Blocks...>, N> {
  static constexpr bool value =
      ((sizeof(Accepted<Blocks>) > 0) && ...) && manifold::StateLayout<Blocks...>::StoredSize == N;
};

}  // namespace kalman_layout

/// out = A x + B u. Without controls B is N x 0, and Eigen's product over its empty (null)
/// storage offsets a null pointer, undefined behaviour the sanitizer build reports (N = 3): then
/// it is not formed, and the empty product's +0 is added as the full expression adds it (a -0
/// entry of A x becomes +0), so both forms give the same bits.
template <int N, int L>
void linearTransition(const Matrix<N, N>& A, const Vector<N>& x, const Matrix<N, L>& B,
                      const Vector<L>& u, Vector<N>& out) {
  if constexpr (L == 0) {
    out.noalias() = A * x;
    out.array() += 0.0;
  } else {
    out = A * x + B * u;
  }
}

/// Layout: the state's layout (manifold/state_layout.hpp) when given; it must be flat (vector
/// blocks only) and of N entries. void, the default, is N plain entries for any N.
template <int N, int M, int L = 0, class Layout = void>
class KalmanFilter : public AbstractKalmanFilter<N, M, L> {
  static_assert(kalman_layout::Check<Layout, N>::value,
                "KalmanFilter: Layout must be a StateLayout of vector blocks of N entries");
  using Base = AbstractKalmanFilter<N, M, L>;

 public:
  KalmanFilter(const Matrix<N, N>& A, const Matrix<N, L>& B, const Matrix<M, N>& H,
               const Matrix<N, N>& Q, const Matrix<M, M>& R, const Vector<N>& x0,
               const Matrix<N, N>& P0, const AngularComponents& angles = {})
      : Base("KalmanFilter", Q, R, x0, P0, B.cols(), angles), A_(A), B_(B), H_(H) {
    requireSize(this->method_, "A", A, this->stateSize(), this->stateSize());
    requireSize(this->method_, "B", B, this->stateSize(), this->controlSize());
    requireSize(this->method_, "H", H, this->measurementSize(), this->stateSize());
  }

  /// Without x0 and P0: the state starts at zero with identity covariance.
  KalmanFilter(const Matrix<N, N>& A, const Matrix<N, L>& B, const Matrix<M, N>& H,
               const Matrix<N, N>& Q, const Matrix<M, M>& R)
      : KalmanFilter(A, B, H, Q, R, Vector<N>::Zero(Q.rows()),
                     Matrix<N, N>::Identity(Q.rows(), Q.rows())) {}

  /// Time update with the last control, then correction with the present entries of z.
  void estimate(const Measurement<M>& z) {
    z.validate(this->measurementSize());
    Vector<N> x(this->stateSize());
    Matrix<N, N> P(this->stateSize(), this->stateSize());
    predict(x, P);
    if (z.anyAvailable()) {
      Vector<M> y = z.value - H_ * x;
      this->angleMeasurements_.wrap(y);
      Matrix<M, N> H = H_;
      neutraliseMissing(z, y, H);
      Matrix<M, M> R(z.size(), z.size());
      effectiveMeasurementNoise(this->R_, z, R);
      linearCorrection<N, M>(x, P, H, y, R);
    }
    this->commit(x, P);
  }

  /// z^ = H x(k|k-1) and H P(k|k-1) H^T for the next step with the current control; the
  /// filter is unchanged.
  void predictMeasurement(MeasurementPrediction<M>& out) const {
    Vector<N> x(this->stateSize());
    Matrix<N, N> P(this->stateSize(), this->stateSize());
    predict(x, P);
    out.mean = H_ * x;
    this->angleMeasurements_.wrap(out.mean);
    projectCovariance<N, M>(H_, P, out.covariance);
    out.noise = this->R_;
    out.angular = this->angleMeasurements_.mask();
  }

  const Matrix<N, N>& transitionMatrix() const { return A_; }
  const Matrix<N, L>& controlMatrix() const { return B_; }
  const Matrix<M, N>& observationMatrix() const { return H_; }

 private:
  /// Time update of the current belief: x(k|k-1) = A x + B u, P(k|k-1) = A P A^T + Q.
  void predict(Vector<N>& x, Matrix<N, N>& P) const {
    linearTransition<N, L>(A_, this->x_, B_, this->u_, x);
    propagateCovariance<N>(A_, this->P_, this->Q_, P);
  }

  Matrix<N, N> A_;
  Matrix<N, L> B_;
  Matrix<M, N> H_;
};

}  // namespace estimation
