// The non-template helpers of filter_test_utils.hpp, compiled once for the test program:
// defined inline in the header, each test file including it compiled an eigen-solver and
// the simulation again (doc/build_cost.md, "The unit tests' helpers").
#include "filter_test_utils.hpp"

#include <Eigen/Eigenvalues>

namespace sftest {

Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& P) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P, Eigen::EigenvaluesOnly).eigenvalues();
}

Eigen::MatrixXd psdRoot(const Eigen::MatrixXd& P) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(P);
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

std::vector<Step<4, 2>> simulateNav3Drive(int steps, std::uint64_t seed, double missingProbability,
                                          int allMissingEvery, double T, double radius) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::bernoulli_distribution missing(missingProbability);
  const double f1 = 0.05 + 0.2 * uniform(rng), f2 = 0.05 + 0.2 * uniform(rng);
  const double p1 = 6.3 * uniform(rng), p2 = 6.3 * uniform(rng);
  const Vector<4> sigma = estimation::models::nav3MeasurementNoise().diagonal().cwiseSqrt();
  auto speed = [&](double t) { return 0.4 + 0.5 * std::sin(f1 * t + p1); };
  auto turn = [&](double t) { return 0.6 * std::sin(f2 * t + p2); };
  std::vector<Step<4, 2>> run;
  for (int k = 0; k < steps; ++k) {
    const double t = k * T;
    Step<4, 2> step{Vector<2>(speed(t + T), turn(t + T)), Measurement<4>(4)};
    const double v = speed(t), omega = turn(t);
    const double a = 0.5 * f1 * std::cos(f1 * t + p1);
    step.z.value << omega + sigma(0) * normal(rng), a + sigma(1) * normal(rng),
        1000.0 * (v - radius * omega) + sigma(2) * normal(rng),
        1000.0 * (v + radius * omega) + sigma(3) * normal(rng);
    for (Index i = 0; i < 4; ++i) step.z.available(i) = !missing(rng);
    if (allMissingEvery > 0 && k % allMissingEvery == allMissingEvery - 1) {
      step.z.available.setConstant(false);
    }
    run.push_back(step);
  }
  return run;
}

Matrix<7, 7> nav3CtrlTransitionJacobian(const estimation::models::Nav3Ctrl& model,
                                        const Vector<7>& x) {
  const double T = model.T, th = x(2), ds = x(4);
  Matrix<7, 7> A = Matrix<7, 7>::Zero();
  A(0, 0) = 1.0;
  A(0, 2) = -ds * std::sin(th);
  A(0, 4) = std::cos(th);
  A(1, 1) = 1.0;
  A(1, 2) = ds * std::cos(th);
  A(1, 4) = std::sin(th);
  A(2, 2) = 1.0;
  A(2, 3) = T;
  A(4, 5) = T;
  A(5, 5) = 1.0;
  A(5, 6) = T;
  A(6, 5) = -1.0 / T;
  return A;
}

Matrix<4, 7> nav3CtrlObservationJacobian(const estimation::models::Nav3Ctrl& model) {
  const double R = model.radius;
  Matrix<4, 7> H = Matrix<4, 7>::Zero();
  H(0, 3) = 1.0;
  H(1, 6) = 1.0;
  H(2, 3) = -1000.0 * R;
  H(2, 5) = 1000.0;
  H(3, 3) = 1000.0 * R;
  H(3, 5) = 1000.0;
  return H;
}

Matrix<4, 4> correlatedNav3MeasurementNoise() {
  Matrix<4, 4> L = Matrix<4, 4>::Zero();
  L(0, 0) = 0.013;
  L(1, 0) = 0.01;
  L(1, 1) = 0.5;
  L(2, 0) = 0.2;
  L(2, 1) = 0.1;
  L(2, 2) = 1.4;
  L(3, 0) = -0.2;
  L(3, 1) = 0.1;
  L(3, 2) = 0.3;
  L(3, 3) = 1.3;
  return L * L.transpose();
}

}  // namespace sftest
