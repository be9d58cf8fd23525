// Time of the size-only Kalman steps the library compiles once (kalman_steps_N.cpp): one
// covariance time update P = A P A^T + Q and one linear correction with M of N states measured,
// at the sizes of the shipped headers (nav3ctrl: 7 states, 4 measurements; the Husky GPS
// header: 8 states) and at 8 x 6, the largest of the grid. At 8 states Eigen would evaluate the
// products with its matrix-matrix kernel unless the threshold of sf_estimation's target
// (EIGEN_CACHEFRIENDLY_PRODUCT_THRESHOLD) is raised: doc/build_cost.md, "Eigen's fixed-size
// products".
#include <benchmark/benchmark.h>

#include "sf_estimation/kalman_correction.hpp"

namespace {

using namespace estimation;

template <int N, int M>
void KalmanSteps(benchmark::State& state) {
  // A chain of position-velocity pairs with period 0.1 s; the first M states are measured.
  Matrix<N, N> A = Matrix<N, N>::Identity();
  for (int i = 0; i + 1 < N; i += 2) A(i, i + 1) = 0.1;
  const Matrix<N, N> Q = 0.01 * Matrix<N, N>::Identity();
  Matrix<M, N> H = Matrix<M, N>::Zero();
  for (int i = 0; i < M; ++i) H(i, i) = 1.0;
  const Matrix<M, M> R = 0.1 * Matrix<M, M>::Identity();
  const Vector<M> innovation = Vector<M>::Constant(0.01);
  Vector<N> x = Vector<N>::Zero();
  Matrix<N, N> P = Matrix<N, N>::Identity();
  Matrix<N, N> next;
  for (auto _ : state) {
    propagateCovariance<N>(A, P, Q, next);
    P = next;
    linearCorrection<N, M>(x, P, H, innovation, R);
    benchmark::DoNotOptimize(P.data());
    benchmark::ClobberMemory();
  }
}

}  // namespace

BENCHMARK(KalmanSteps<7, 4>);
BENCHMARK(KalmanSteps<8, 3>);
BENCHMARK(KalmanSteps<8, 6>);
