// The Kalman steps' plain-loop products (small_products.hpp): hand-computed results, the
// summation order they promise (exact bits), and Eigen's own products at the shapes the
// steps use, fixed and dynamic, single rows (stored row-major by Eigen) and odd row counts.
#include <cstdlib>

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "sf_estimation/small_products.hpp"

namespace {

using estimation::Index;
using estimation::Matrix;
using estimation::multiply;
using estimation::Store;

TEST(SmallProducts, HandComputedTwoByTwo) {
  Matrix<2, 2> a, b;
  a << 1, 2, 3, 4;
  b << 5, 6, 7, 8;
  Matrix<2, 2> out;
  multiply<Store::Assign>(a, b, out);
  EXPECT_EQ(out(0, 0), 19.0);
  EXPECT_EQ(out(0, 1), 22.0);
  EXPECT_EQ(out(1, 0), 43.0);
  EXPECT_EQ(out(1, 1), 50.0);
  multiply<Store::Assign, true>(a, b, out);  // a b^T
  EXPECT_EQ(out(0, 0), 17.0);
  EXPECT_EQ(out(0, 1), 23.0);
  EXPECT_EQ(out(1, 0), 39.0);
  EXPECT_EQ(out(1, 1), 53.0);
  out.setConstant(100.0);
  multiply<Store::Add>(a, b, out);
  EXPECT_EQ(out(1, 0), 143.0);
  out.setConstant(100.0);
  multiply<Store::Subtract, true>(a, b, out);
  EXPECT_EQ(out(0, 1), 77.0);
}

// Every entry is the in-order sum over the inner index, added to the destination afterwards:
// the same bits as this loop, for every row (paired or the odd last one).
template <Store store, bool TransposeB, class A, class B, class Out>
void expectInOrderSums(const A& a, const B& b, const Out& before) {
  Out out = before;
  multiply<store, TransposeB>(a, b, out);
  for (Index i = 0; i < a.rows(); ++i) {
    for (Index j = 0; j < out.cols(); ++j) {
      double sum = 0.0;
      for (Index k = 0; k < a.cols(); ++k) sum += a(i, k) * (TransposeB ? b(j, k) : b(k, j));
      double expected = sum;
      if (store == Store::Add) expected = before(i, j) + sum;
      if (store == Store::Subtract) expected = before(i, j) - sum;
      EXPECT_EQ(out(i, j), expected) << "entry (" << i << ", " << j << ")";
    }
  }
}

TEST(SmallProducts, SumsInOrderAtEveryShapeOfTheSteps) {
  std::srand(7);
  // P H^T (N x N times M x N transposed), H (P H^T), K H, K R, (I - K H) P (I - K H)^T.
  const Matrix<7, 7> P = Matrix<7, 7>::Random();
  const Matrix<3, 7> H = Matrix<3, 7>::Random();
  const Matrix<7, 3> K = Matrix<7, 3>::Random();
  const Matrix<3, 3> R = Matrix<3, 3>::Random();
  expectInOrderSums<Store::Assign, true>(P, H, Matrix<7, 3>::Zero().eval());
  expectInOrderSums<Store::Add, false>(H, K, Matrix<3, 3>::Random().eval());
  expectInOrderSums<Store::Subtract, false>(K, H, Matrix<7, 7>::Identity().eval());
  expectInOrderSums<Store::Assign, false>(K, R, Matrix<7, 3>::Zero().eval());
  expectInOrderSums<Store::Add, true>(P, P, Matrix<7, 7>::Random().eval());
  // A single measurement row: Eigen stores a 1 x N matrix row-major.
  const Matrix<1, 7> h = Matrix<1, 7>::Random();
  expectInOrderSums<Store::Assign, false>(h, P, Matrix<1, 7>::Zero().eval());
  expectInOrderSums<Store::Assign, true>(h, h, Matrix<1, 1>::Zero().eval());
  // Matrix times vector (K y, the sigma points' weighted mean).
  const Matrix<5, 11> points = Matrix<5, 11>::Random();
  const Matrix<11, 1> weights = Matrix<11, 1>::Random();
  expectInOrderSums<Store::Assign, false>(points, weights, Matrix<5, 1>::Zero().eval());
  // Dynamic sizes, as the factory's filters have them.
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(5, 4);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(4, 3);
  expectInOrderSums<Store::Add, false>(A, B, Eigen::MatrixXd::Random(5, 3).eval());
  expectInOrderSums<Store::Subtract, true>(A, A, Eigen::MatrixXd::Random(5, 5).eval());
}

TEST(SmallProducts, AgreesWithEigensProducts) {
  std::srand(11);
  const Matrix<8, 8> P = Matrix<8, 8>::Random();
  const Matrix<6, 8> H = Matrix<6, 8>::Random();
  Matrix<8, 6> PHt;
  multiply<Store::Assign, true>(P, H, PHt);
  EXPECT_TRUE(PHt.isApprox(P * H.transpose(), 1e-14));
  Matrix<8, 8> APAt = Matrix<8, 8>::Identity();
  multiply<Store::Add, true>(P, P, APAt);
  EXPECT_TRUE(APAt.isApprox(Matrix<8, 8>::Identity() + P * P.transpose(), 1e-14));
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(3, 9);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(9, 2);
  Eigen::MatrixXd AB(3, 2);
  multiply<Store::Assign>(A, B, AB);
  EXPECT_TRUE(AB.isApprox(A * B, 1e-14));
}

TEST(SmallProducts, EmptyInnerDimensionIsAZeroProduct) {
  const Eigen::MatrixXd a(3, 0), b(0, 2);
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(3, 2, 4.0);
  multiply<Store::Add>(a, b, out);
  EXPECT_TRUE(out.isApproxToConstant(4.0));
  multiply<Store::Assign>(a, b, out);
  EXPECT_TRUE(out.isZero(0.0));
}

}  // namespace
