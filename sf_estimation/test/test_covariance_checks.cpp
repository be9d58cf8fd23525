// Q, R and P0 are checked once at construction (parameter_checks.hpp): finite, entries of
// magnitude at most kMaxCovarianceEntry (1e100), symmetric to a relative tolerance, positive
// semi-definite, and R positive definite for the Kalman-type filters and the particle filter.
// Each refusal is a ParameterError naming the method and the matrix. Before, a covariance of
// 1e308 was accepted and every step then overflowed.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "factory_test_utils.hpp"

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/parameter_checks.hpp"

namespace {

using estimation::EstimatorFactory;
using estimation::ParameterError;
using estimation::ParameterMap;

const char* const kMethods[] = {"KalmanFilter", "ExtendedKalmanFilter", "UnscentedKalmanFilter",
                                "ParticleFilterSIR"};

/// A valid 2-state, 2-measurement configuration of `method` (x' = x, z = x).
ParameterMap valid(const std::string& method) {
  ParameterMap p;
  if (method == "KalmanFilter") {
    p["A"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
    p["H"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  } else {
    p["model"] = estimation::makeFunctionModel(
        2, 2, 0, [](const auto& x, const auto&, auto& next) { next = x; },
        [](const auto& x, auto& z) { z = x; });
  }
  if (method == "ParticleFilterSIR") p["particles"] = 16;
  p["Q"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2) * 0.1);
  p["R"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2) * 0.2);
  p["P0"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  return p;
}

using sftest::refusal;

/// `method` with matrix `name` replaced by [[a, b], [c, d]].
std::string refusalWith(const std::string& method, const std::string& name, double a, double b,
                        double c, double d) {
  ParameterMap p = valid(method);
  Eigen::MatrixXd m(2, 2);
  m << a, b, c, d;
  p[name] = m;
  return refusal(method, p);
}

::testing::AssertionResult refusedNaming(const std::string& error, const std::string& method,
                                         const std::string& name, const std::string& reason) {
  if (error.find(method) != std::string::npos &&
      error.find("'" + name + "'") != std::string::npos &&
      error.find(reason) != std::string::npos) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "expected '" << method << "', '" << name << "' and '" << reason << "' in: " << error;
}

TEST(CovarianceChecks, TheValidConfigurationsAreAccepted) {
  for (const std::string method : kMethods) EXPECT_EQ(refusal(method, valid(method)), "accepted");
}

TEST(CovarianceChecks, EntriesOf1e308AreRefusedNamingTheMatrix) {
  for (const std::string method : kMethods) {
    for (const std::string name : {"Q", "R", "P0"}) {
      EXPECT_TRUE(refusedNaming(refusalWith(method, name, 1e308, 0, 0, 1e308), method, name,
                                "magnitude 1e+308, more than the maximum 1e100"));
      // An off-diagonal entry counts as well (the matrix is then indefinite anyway).
      EXPECT_TRUE(refusedNaming(refusalWith(method, name, 1, -1e200, -1e200, 1), method, name,
                                "more than the maximum 1e100"));
    }
  }
}

TEST(CovarianceChecks, TheMaximumItselfIsAccepted) {
  for (const std::string method : kMethods) {
    // R = 1e100 on the diagonal: a sensor that says nothing, but the products stay finite.
    EXPECT_EQ(refusalWith(method, "R", 1e100, 0, 0, 1e100), "accepted") << method;
    EXPECT_EQ(refusalWith(method, "P0", 1e100, 0, 0, 1e100), "accepted") << method;
  }
}

TEST(CovarianceChecks, NonFiniteAsymmetricAndIndefiniteMatricesAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::string method : kMethods) {
    for (const std::string name : {"Q", "R", "P0"}) {
      EXPECT_TRUE(
          refusedNaming(refusalWith(method, name, nan, 0, 0, 1), method, name, "non-finite"));
      EXPECT_TRUE(
          refusedNaming(refusalWith(method, name, 1, 0, 0, INFINITY), method, name, "non-finite"));
      EXPECT_TRUE(
          refusedNaming(refusalWith(method, name, 1, 0.5, 0.4, 1), method, name, "symmetric"));
      // Eigenvalues -1 and 3.
      EXPECT_TRUE(refusedNaming(refusalWith(method, name, 1, 2, 2, 1), method, name,
                                "positive semi-definite"));
      EXPECT_TRUE(refusedNaming(refusalWith(method, name, -1, 0, 0, 1), method, name,
                                "positive semi-definite"));
    }
    // R must be positive definite: singular (eigenvalues 0 and 2) is refused; Q and P0 may be.
    EXPECT_TRUE(
        refusedNaming(refusalWith(method, "R", 1, 1, 1, 1), method, "R", "positive definite"));
    EXPECT_EQ(refusalWith(method, "Q", 1, 1, 1, 1), "accepted") << method;
    EXPECT_EQ(refusalWith(method, "P0", 1, 1, 1, 1), "accepted") << method;
  }
}

TEST(CovarianceChecks, SymmetryIsCheckedToARelativeTolerance) {
  for (const std::string method : kMethods) {
    // Rounding of a computed matrix (a relative difference of 1e-15) is accepted at any scale;
    // a relative difference of 1e-6 is not.
    EXPECT_EQ(refusalWith(method, "P0", 1e50, 1e49, 1e49 * (1 + 1e-15), 1e50), "accepted");
    EXPECT_EQ(refusalWith(method, "P0", 1e-50, 1e-51, 1e-51 * (1 + 1e-15), 1e-50), "accepted");
    EXPECT_TRUE(refusedNaming(refusalWith(method, "P0", 1e50, 1e49, 1e49 * (1 + 1e-6), 1e50),
                              method, "P0", "symmetric"));
  }
}

}  // namespace
