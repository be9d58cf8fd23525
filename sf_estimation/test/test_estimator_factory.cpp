// Tests of EstimatorFactory (thesis section 4.3.3) and of the IEstimator adapter: every method
// is built from a ParameterMap and runs through IEstimator; the factory's KF/EKF/UKF/PF give
// the fixed-size filters' results; configuration errors name the method, the parameter and
// the expected size; a rejected input leaves the estimator unchanged.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "filter_test_utils.hpp"
#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_adapter.hpp"
#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"

namespace {

using estimation::EstimatorFactory;
using estimation::FunctionModel;
using estimation::IEstimator;
using estimation::Index;
using estimation::Input;
using estimation::InputValue;
using estimation::InvalidInputError;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Output;
using estimation::ParameterError;
using estimation::ParameterMap;
using estimation::Vector;
using estimation::models::Nav3Ctrl;
using estimation::models::Nav3Reduced;

/// nav3ctrl as generic lambdas, exactly the arithmetic of models::Nav3Ctrl.
FunctionModel nav3CtrlFunctionModel() {
  const double T = 0.1, radius = 0.3;
  return estimation::makeFunctionModel(
      7, 4, 2,
      [T](const auto& x, const auto& u, auto& next) {
        using std::cos;
        using std::sin;
        next(0) = x(0) + x(4) * cos(x(2));
        next(1) = x(1) + x(4) * sin(x(2));
        next(2) = x(2) + x(3) * T;
        next(3) = u(1);
        next(4) = x(5) * T;
        next(5) = x(5) + x(6) * T;
        next(6) = (u(0) - x(5)) / T;
      },
      [radius](const auto& x, auto& z) {
        z(0) = x(3);
        z(1) = x(6);
        z(2) = (x(5) - x(3) * radius) * 1000.0;
        z(3) = (x(5) + x(3) * radius) * 1000.0;
      });
}

/// The moving train (n = 2) as generic lambdas.
FunctionModel trainFunctionModel() {
  return estimation::makeFunctionModel(
      2, 2, 0,
      [](const auto& x, const auto&, auto& next) {
        next(0) = x(0) + x(1) * 0.1;
        next(1) = x(1);
      },
      [](const auto& x, auto& z) {
        z(0) = x(0);
        z(1) = x(1);
      });
}

Input toInput(const Measurement<4>& z) {
  Input in;
  for (Index i = 0; i < z.size(); ++i) {
    if (!z.available(i)) {
      in.add(InputValue::missing());
    } else if (z.varianceGiven(i)) {
      in.add(InputValue(z.value(i), z.variance(i), 0.0));
    } else {
      in.add(InputValue(z.value(i)));
    }
  }
  return in;
}

Input toInput(const Eigen::VectorXd& v) {
  Input in;
  for (Index i = 0; i < v.size(); ++i) in.add(InputValue(v(i)));
  return in;
}

Eigen::VectorXd values(const Output& out) {
  Eigen::VectorXd v(static_cast<Index>(out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) v(static_cast<Index>(i)) = out[i].getValue();
  return v;
}

Vector<7> nav3x0() {
  Vector<7> x;
  x << 0.0, 0.0, 0.1, 0.0, 0.0, 0.2, 0.0;
  return x;
}

/// Common Gaussian parameters of the nav3ctrl filters.
ParameterMap nav3Parameters() {
  ParameterMap p;
  p["model"] = nav3CtrlFunctionModel();
  p["Q"] = Eigen::MatrixXd(estimation::models::nav3ProcessNoise());
  p["R"] = Eigen::MatrixXd(estimation::models::nav3MeasurementNoise());
  p["x0"] = Eigen::VectorXd(nav3x0());
  p["P0"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(7, 7) * 0.1);
  return p;
}

/// Runs the factory estimator and the fixed-size filter over the same inputs (with a few
/// per-entry variances) and returns the largest relative differences of state and covariance.
template <class Filter>
std::pair<double, double> compare(IEstimator& dynamic, Filter& fixed,
                                  const std::vector<sftest::Step<4, 2>>& run) {
  double stateDiff = 0.0, covDiff = 0.0;
  for (std::size_t k = 0; k < run.size(); ++k) {
    Measurement<4> z = run[k].z;
    if (k % 5 == 2) {
      z.varianceGiven(1) = true;
      z.variance(1) = 0.9;
    }
    dynamic.setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    fixed.setControl(run[k].u);
    const Output out = dynamic.estimate(toInput(z));
    fixed.estimate(z);
    // The returned output, the last estimate and the filter agree.
    EXPECT_EQ(values(out), values(dynamic.getLastEstimate()));
    EXPECT_EQ(out.covariance, dynamic.getLastEstimate().covariance);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Index j = static_cast<Index>(i);
      EXPECT_EQ(out[i].getVariance(), out.covariance(j, j));
    }
    stateDiff = std::max(stateDiff, sftest::relDiff(values(out), fixed.state()));
    covDiff = std::max(covDiff, sftest::relDiff(out.covariance, fixed.covariance()));
  }
  return {stateDiff, covDiff};
}

// ---------------------------------------------------------------------------------------------
// Every method through IEstimator.
// ---------------------------------------------------------------------------------------------

TEST(EstimatorFactory, ListsEveryMethod) {
  const auto& m = EstimatorFactory::methods();
  for (const char* name :
       {"KalmanFilter", "ExtendedKalmanFilter", "UnscentedKalmanFilter", "ParticleFilterSIR",
        "MovingAverage", "MovingMedian", "ConfidenceWeightedAveraging"}) {
    EXPECT_NE(std::find(m.begin(), m.end(), name), m.end()) << name;
  }
}

TEST(EstimatorFactory, KalmanFilterEqualsFixedSizeFilter) {
  const Nav3Reduced model;
  ParameterMap p;
  p["A"] = Eigen::MatrixXd(model.transitionMatrix());
  p["B"] = Eigen::MatrixXd(model.controlMatrix());
  p["H"] = Eigen::MatrixXd(model.observationMatrix());
  p["Q"] = Eigen::MatrixXd(estimation::models::nav3ReducedProcessNoise());
  p["R"] = Eigen::MatrixXd(estimation::models::nav3MeasurementNoise());
  p["x0"] = Eigen::VectorXd(Eigen::Vector3d(0.0, 0.2, 0.0));
  p["P0"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(3, 3) * 0.5);
  const auto estimator = EstimatorFactory::create("KalmanFilter", p);
  estimation::KalmanFilter<3, 4, 2> fixed(
      model.transitionMatrix(), model.controlMatrix(), model.observationMatrix(),
      estimation::models::nav3ReducedProcessNoise(), estimation::models::nav3MeasurementNoise(),
      Vector<3>(0.0, 0.2, 0.0), Matrix<3, 3>::Identity() * 0.5);
  EXPECT_NE(estimator->description().find("KalmanFilter"), std::string::npos);
  const auto diff = compare(*estimator, fixed, sftest::simulateNav3Drive(200, 61, 0.3, 7));
  std::cout << "[ measured ] factory KF vs fixed: " << diff.first << ", " << diff.second << "\n";
  EXPECT_LE(diff.first, 1e-12);
  EXPECT_LE(diff.second, 1e-12);
}

TEST(EstimatorFactory, ExtendedKalmanFilterEqualsFixedSizeFilter) {
  const auto estimator = EstimatorFactory::create("ExtendedKalmanFilter", nav3Parameters());
  estimation::ExtendedKalmanFilter<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1);
  EXPECT_NE(estimator->description().find("ExtendedKalmanFilter"), std::string::npos);
  const auto diff = compare(*estimator, fixed, sftest::simulateNav3Drive(200, 62, 0.3, 7));
  std::cout << "[ measured ] factory EKF vs fixed: " << diff.first << ", " << diff.second << "\n";
  EXPECT_LE(diff.first, 1e-12);
  EXPECT_LE(diff.second, 1e-12);
}

TEST(EstimatorFactory, UnscentedKalmanFilterEqualsFixedSizeFilter) {
  ParameterMap p = nav3Parameters();
  p["alpha"] = 0.5;
  p["beta"] = 1;  // an int is accepted for a number
  p["kappa"] = 0.5;
  estimation::UnscentedParameters ut;
  ut.alpha = 0.5;
  ut.beta = 1.0;
  ut.kappa = 0.5;
  const auto estimator = EstimatorFactory::create("UnscentedKalmanFilter", p);
  estimation::UnscentedKalmanFilter<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1, ut);
  EXPECT_NE(estimator->description().find("UnscentedKalmanFilter"), std::string::npos);
  const auto diff = compare(*estimator, fixed, sftest::simulateNav3Drive(200, 63, 0.3, 7));
  std::cout << "[ measured ] factory UKF (alpha 0.5) vs fixed: " << diff.first << ", "
            << diff.second << "\n";
  EXPECT_LE(diff.first, 1e-12);
  EXPECT_LE(diff.second, 1e-12);
}

TEST(EstimatorFactory, UnscentedKalmanFilterPropagatedMeanEqualsFixedSizeFilter) {
  ParameterMap p = nav3Parameters();
  p["predicted-mean"] = std::string("propagated");
  p["alpha"] = 0.5;  // alpha 1e-3 rounds run-time and fixed sizes apart by ~1e-9 (weights ~1e6)
  estimation::UnscentedParameters ut;
  ut.alpha = 0.5;
  ut.predictedMean = estimation::PredictedMean::Propagated;
  const auto estimator = EstimatorFactory::create("UnscentedKalmanFilter", p);
  estimation::UnscentedKalmanFilter<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1, ut);
  estimation::UnscentedKalmanFilter<Nav3Ctrl> average(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1,
      estimation::UnscentedParameters{0.5});
  const auto run = sftest::simulateNav3Drive(200, 63, 0.3, 7);
  const auto diff = compare(*estimator, fixed, run);
  EXPECT_LE(diff.first, 1e-12);
  EXPECT_LE(diff.second, 1e-12);
  // ... and it is not the sigma-point average (nav3ctrl's position step is nonlinear in theta).
  const auto again = EstimatorFactory::create("UnscentedKalmanFilter", p);
  EXPECT_GT(compare(*again, average, run).first, 1e-9);
  p["predicted-mean"] = std::string("weighted");
  EXPECT_THROW(
      {
        try {
          EstimatorFactory::create("UnscentedKalmanFilter", p);
        } catch (const estimation::ParameterError& e) {
          EXPECT_NE(std::string(e.what()).find("'predicted-mean' is 'weighted', expected "
                                               "'sigma-point-average', 'propagated'"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      estimation::ParameterError);
}

TEST(EstimatorFactory, UnscentedKalmanFilterDefaultsAreTheDocumentedOnes) {
  // Without alpha/beta/kappa the factory must use alpha = 1e-3, beta = 2, kappa = 0: the
  // same computation (same run-time sizes) as with them given, so bit-identical.
  ParameterMap explicitDefaults = nav3Parameters();
  explicitDefaults["alpha"] = 1e-3;
  explicitDefaults["beta"] = 2.0;
  explicitDefaults["kappa"] = 0.0;
  const auto implicit = EstimatorFactory::create("UnscentedKalmanFilter", nav3Parameters());
  const auto given = EstimatorFactory::create("UnscentedKalmanFilter", explicitDefaults);
  estimation::UnscentedKalmanFilter<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1);
  const auto run = sftest::simulateNav3Drive(200, 63, 0.3, 7);
  for (const auto& step : run) {
    implicit->setControlInput(toInput(Eigen::VectorXd(step.u)));
    given->setControlInput(toInput(Eigen::VectorXd(step.u)));
    const Output a = implicit->estimate(toInput(step.z));
    const Output b = given->estimate(toInput(step.z));
    ASSERT_EQ(values(a), values(b));
    ASSERT_EQ(a.covariance, b.covariance);
  }
  // Against the fixed-size filter with its default parameters. With alpha = 1e-3 the weights
  // are W0 = -999999 and W_i = 5e5 (sum |W| = 2e6): the fixed-size and run-time-size products
  // sum in different orders and each weighted mean carries up to 2n u 2e6 |z| of rounding
  // (n = 7, u = 1.1e-16, |z| <= ~525 mm/s for the wheels), mapped to the state by a gain of at
  // most ~5e-3 (acceleration per wheel): 14 * 1.1e-16 * 2e6 * 525 * 5e-3 = 8e-9 per filter,
  // 1.6e-8 for the difference of the two, relative to a state of scale ~1. The 1e-12 of the
  // alpha = 0.5 test above is out of reach for this alpha (measured ~4e-9, printed).
  const auto fresh = EstimatorFactory::create("UnscentedKalmanFilter", nav3Parameters());
  const auto diff = compare(*fresh, fixed, run);
  std::cout << "[ measured ] factory UKF (default alpha 1e-3) vs fixed: " << diff.first << ", "
            << diff.second << "\n";
  EXPECT_LE(diff.first, 1.6e-8);
  EXPECT_LE(diff.second, 1.6e-8);
}

/// The factory's particle filter against the fixed-size one, with the pose carried per particle
/// or shared (nav3ctrl's dead-reckoned states: x, y, theta and the step length).
void checkParticleFactoryEqualsFixedSize(bool shared) {
  ParameterMap p = nav3Parameters();
  p["Q"] = Eigen::MatrixXd(estimation::models::nav3ParticleProcessNoise());
  p["particles"] = 300;
  p["seed"] = 17;
  p["resampling-threshold"] = 0.6;
  if (shared) p["dead-reckoned-states"] = std::string("shared");
  const auto estimator = EstimatorFactory::create("ParticleFilterSIR", p);
  estimation::ParticleFilterParameters pf;
  pf.particles = 300;
  pf.seed = 17;
  pf.resamplingThreshold = 0.6;
  pf.sharedDeadReckoning = shared;
  estimation::ParticleFilterSIR<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ParticleProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1, pf);
  EXPECT_NE(estimator->description().find("particles=300"), std::string::npos)
      << estimator->description();
  using Adapter = estimation::EstimatorAdapter<estimation::ParticleFilterSIR<FunctionModel>>;
  const auto* adapter = dynamic_cast<const Adapter*>(estimator.get());
  ASSERT_NE(adapter, nullptr);
  const auto& dynamicFilter = adapter->filter();
  estimation::Mask<7> deadReckoned = estimation::Mask<7>::Constant(false);
  if (shared) deadReckoned << true, true, true, false, true, false, false;
  ASSERT_EQ(fixed.deadReckonedStates(), deadReckoned);
  ASSERT_EQ(estimation::Mask<Eigen::Dynamic>(dynamicFilter.deadReckonedStates()), deadReckoned);
  // Same seed: the particles and weights are bit-identical in every step.
  const auto run = sftest::simulateNav3Drive(50, 64, 0.3, 7);
  double stateDiff = 0.0, covDiff = 0.0;
  for (std::size_t k = 0; k < run.size(); ++k) {
    estimator->setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    fixed.setControl(run[k].u);
    const Output out = estimator->estimate(toInput(run[k].z));
    fixed.estimate(run[k].z);
    ASSERT_EQ(dynamicFilter.particles(), fixed.particles()) << "step " << k;
    ASSERT_EQ(dynamicFilter.logWeights(), fixed.logWeights()) << "step " << k;
    ASSERT_EQ(dynamicFilter.resampledLastStep(), fixed.resampledLastStep()) << "step " << k;
    // The moments are sums over the same numbers, but the fixed-size (7 x N) and run-time-size
    // products add them in different orders: equal to rounding only.
    // The covariance often collapses to rounding noise (~1e-30) when one particle takes all
    // the weight, so it is compared in absolute terms: its rounding is ~u |x|^2.
    const double scale = std::max(1.0, sftest::scaleOf(fixed.state()));
    stateDiff = std::max(stateDiff, sftest::relDiff(values(out), fixed.state()));
    covDiff = std::max(covDiff, sftest::maxAbsDiff(out.covariance, fixed.covariance()));
    ASSERT_LE(sftest::relDiff(values(out), fixed.state()), 1e-12) << "step " << k;
    ASSERT_LE(sftest::maxAbsDiff(out.covariance, fixed.covariance()), 1e-12 * scale * scale);
  }
  std::cout << "[ measured ] factory PF (" << (shared ? "shared" : "per-particle")
            << " dead reckoning) vs fixed: particles and weights identical; state " << stateDiff
            << " (relative), covariance " << covDiff << " (absolute)\n";
}

TEST(EstimatorFactory, ParticleFilterEqualsFixedSizeFilter) {
  checkParticleFactoryEqualsFixedSize(false);
}

TEST(EstimatorFactory, ParticleFilterWithSharedDeadReckoningEqualsFixedSizeFilter) {
  checkParticleFactoryEqualsFixedSize(true);
}

TEST(EstimatorFactory, AveragingMethodsRunThroughTheInterface) {
  ParameterMap avg;
  avg["input-count"] = 2;
  avg["window-size"] = 3;
  const auto average = EstimatorFactory::create("MovingAverage", avg);
  for (int k = 1; k <= 4; ++k) average->estimate(toInput(Eigen::Vector2d(k, 10.0 * k)));
  // Last three values: (2, 3, 4) and (20, 30, 40).
  EXPECT_NEAR(average->getLastEstimate()[0].getValue(), 3.0, 1e-12);
  EXPECT_NEAR(average->getLastEstimate()[1].getValue(), 30.0, 1e-12);
  EXPECT_NE(average->description().find("MovingAverage"), std::string::npos);

  ParameterMap med;
  med["input-count"] = 1;
  med["window-size"] = 3;
  const auto median = EstimatorFactory::create("MovingMedian", med);
  for (double v : {5.0, 100.0, 7.0}) median->estimate(toInput(Eigen::VectorXd::Constant(1, v)));
  EXPECT_EQ(median->getLastEstimate()[0].getValue(), 7.0);

  ParameterMap cwa;
  cwa["variances"] = Eigen::VectorXd(Eigen::Vector2d(1.0, 4.0));
  const auto fused = EstimatorFactory::create("ConfidenceWeightedAveraging", cwa);
  // x = (2/1 + 7/4) / (1/1 + 1/4) = 3, var = 1 / 1.25 = 0.8
  const Output out = fused->estimate(toInput(Eigen::Vector2d(2.0, 7.0)));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].getValue(), 3.0, 1e-12);
  EXPECT_NEAR(out[0].getVariance(), 0.8, 1e-12);

  // None of them takes controls: an empty control input is accepted, a non-empty refused.
  for (IEstimator* e : {average.get(), median.get(), fused.get()}) {
    EXPECT_FALSE(e->description().empty());
    EXPECT_NO_THROW(e->setControlInput(Input()));
    EXPECT_THROW(e->setControlInput(toInput(Eigen::VectorXd::Constant(1, 1.0))), InvalidInputError);
  }
  EXPECT_NE(median->description().find("MovingMedian"), std::string::npos);
  EXPECT_NE(fused->description().find("ConfidenceWeightedAveraging"), std::string::npos)
      << fused->description();
}

TEST(EstimatorFactory, ControlInputKeepsMissingEntries) {
  const auto estimator = EstimatorFactory::create("ExtendedKalmanFilter", nav3Parameters());
  estimation::ExtendedKalmanFilter<Nav3Ctrl> fixed(
      Nav3Ctrl{}, estimation::models::nav3ProcessNoise(),
      estimation::models::nav3MeasurementNoise(), nav3x0(), Matrix<7, 7>::Identity() * 0.1);
  estimator->setControlInput(toInput(Eigen::Vector2d(0.4, 0.2)));
  Input partial;
  partial.add(InputValue::missing());
  partial.add(InputValue(-0.3));
  estimator->setControlInput(partial);  // u = (0.4, -0.3)
  fixed.setControl(Vector<2>(0.4, -0.3));
  const Output out = estimator->estimate(toInput(Measurement<4>::missing()));
  fixed.estimate(Measurement<4>::missing());
  EXPECT_LE(sftest::relDiff(values(out), fixed.state()), 1e-12);
  EXPECT_EQ(values(out)(3), -0.3);  // omega' = u1
  // Wrong size and non-finite controls are refused.
  EXPECT_THROW(estimator->setControlInput(toInput(Eigen::Vector3d(1, 2, 3))), InvalidInputError);
  EXPECT_THROW(estimator->setControlInput(
                   toInput(Eigen::Vector2d(0.1, std::numeric_limits<double>::infinity()))),
               InvalidInputError);
}

// ---------------------------------------------------------------------------------------------
// Configuration errors.
// ---------------------------------------------------------------------------------------------

/// The message of the ParameterError thrown by create(), or "" when none is thrown.
std::string parameterError(const std::string& method, const ParameterMap& p) {
  try {
    EstimatorFactory::create(method, p);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(EstimatorFactoryErrors, UnknownMethod) {
  const std::string message = parameterError("KalmanFilterX", ParameterMap{});
  EXPECT_TRUE(contains(message, "KalmanFilterX")) << message;
  EXPECT_TRUE(contains(message, "UnscentedKalmanFilter")) << message;  // lists the known ones
}

TEST(EstimatorFactoryErrors, MissingParameterNamesMethodParameterAndSize) {
  ParameterMap p = nav3Parameters();
  p.erase("Q");
  const std::string message = parameterError("ExtendedKalmanFilter", p);
  EXPECT_TRUE(contains(message, "ExtendedKalmanFilter")) << message;
  EXPECT_TRUE(contains(message, "'Q'")) << message;
  EXPECT_TRUE(contains(message, "7x7")) << message;

  ParameterMap noModel = nav3Parameters();
  noModel.erase("model");
  const std::string m2 = parameterError("UnscentedKalmanFilter", noModel);
  EXPECT_TRUE(contains(m2, "UnscentedKalmanFilter")) << m2;
  EXPECT_TRUE(contains(m2, "'model'")) << m2;

  ParameterMap avg;
  avg["input-count"] = 2;
  const std::string m3 = parameterError("MovingAverage", avg);
  EXPECT_TRUE(contains(m3, "MovingAverage")) << m3;
  EXPECT_TRUE(contains(m3, "'window-size'")) << m3;
}

TEST(EstimatorFactoryErrors, WrongTypeNamesMethodParameterAndExpectation) {
  ParameterMap p = nav3Parameters();
  p["R"] = std::string("diag(1,2,3,4)");
  const std::string message = parameterError("ExtendedKalmanFilter", p);
  EXPECT_TRUE(contains(message, "ExtendedKalmanFilter")) << message;
  EXPECT_TRUE(contains(message, "'R'")) << message;
  EXPECT_TRUE(contains(message, "4x4")) << message;
  EXPECT_TRUE(contains(message, "string")) << message;

  ParameterMap pf = nav3Parameters();
  pf["particles"] = 100.0;  // must be an int
  const std::string m2 = parameterError("ParticleFilterSIR", pf);
  EXPECT_TRUE(contains(m2, "ParticleFilterSIR")) << m2;
  EXPECT_TRUE(contains(m2, "'particles'")) << m2;
  EXPECT_TRUE(contains(m2, "integer")) << m2;

  ParameterMap ukf = nav3Parameters();
  ukf["alpha"] = std::string("small");
  const std::string m3 = parameterError("UnscentedKalmanFilter", ukf);
  EXPECT_TRUE(contains(m3, "'alpha'")) << m3;
  EXPECT_TRUE(contains(m3, "number")) << m3;

  ParameterMap model = nav3Parameters();
  model["model"] = 3;
  const std::string m4 = parameterError("ExtendedKalmanFilter", model);
  EXPECT_TRUE(contains(m4, "'model'")) << m4;
  EXPECT_TRUE(contains(m4, "FunctionModel")) << m4;
}

/// Parameter maps with one parameter of the wrong size: {method, map, parameter, expected}.
struct WrongSizeCase {
  std::string method;
  ParameterMap parameters;
  std::string parameter, expectedSize;
};

std::vector<WrongSizeCase> wrongSizeCases() {
  std::vector<WrongSizeCase> cases;
  // EKF/UKF/PF on the moving train (n = 2, m = 2) with a 3x3 Q.
  ParameterMap train;
  train["model"] = trainFunctionModel();
  train["Q"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(3, 3));
  train["R"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  for (const char* method :
       {"ExtendedKalmanFilter", "UnscentedKalmanFilter", "ParticleFilterSIR"}) {
    cases.push_back({method, train, "'Q'", "2x2"});
  }
  // R 3x3 for the 4 measurements of nav3ctrl.
  ParameterMap r = nav3Parameters();
  r["R"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(3, 3));
  cases.push_back({"ExtendedKalmanFilter", r, "'R'", "4x4"});
  // x0 with 6 entries for n = 7.
  ParameterMap x = nav3Parameters();
  x["x0"] = Eigen::VectorXd(Eigen::VectorXd::Zero(6));
  cases.push_back({"UnscentedKalmanFilter", x, "'x0'", "7"});
  // KalmanFilter: n = 2 from A, Q 3x3.
  ParameterMap kf;
  kf["A"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  kf["H"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  kf["Q"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(3, 3));
  kf["R"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(2, 2));
  cases.push_back({"KalmanFilter", kf, "'Q'", "2x2"});
  return cases;
}

TEST(EstimatorFactoryErrors, WrongSizeIsRefusedWithParameterError) {
  for (const auto& c : wrongSizeCases()) {
    const std::string message = parameterError(c.method, c.parameters);
    EXPECT_TRUE(contains(message, c.method)) << c.method << " " << c.parameter << ": " << message;
  }
}

TEST(EstimatorFactoryErrors, WrongSizeNamesMethodParameterAndExpectedSize) {
  for (const auto& c : wrongSizeCases()) {
    const std::string message = parameterError(c.method, c.parameters);
    EXPECT_TRUE(contains(message, c.method)) << message;
    EXPECT_TRUE(contains(message, c.parameter)) << message;
    EXPECT_TRUE(contains(message, c.expectedSize)) << message;
  }
}

TEST(EstimatorFactoryErrors, UnknownParameterName) {
  ParameterMap p = nav3Parameters();
  p["q"] = Eigen::MatrixXd(Eigen::MatrixXd::Identity(7, 7));
  const std::string message = parameterError("ExtendedKalmanFilter", p);
  EXPECT_TRUE(contains(message, "ExtendedKalmanFilter")) << message;
  EXPECT_TRUE(contains(message, "'q'")) << message;
  EXPECT_TRUE(contains(message, "Q")) << message;  // the accepted names are listed

  ParameterMap avg;
  avg["input-count"] = 2;
  avg["window-size"] = 3;
  avg["window"] = 3;
  const std::string m2 = parameterError("MovingAverage", avg);
  EXPECT_TRUE(contains(m2, "MovingAverage")) << m2;
  EXPECT_TRUE(contains(m2, "'window'")) << m2;
}

// ---------------------------------------------------------------------------------------------
// Rejected input leaves the estimator unchanged.
// ---------------------------------------------------------------------------------------------

void checkNonFiniteMeasurementIsRejected(const std::string& method, const ParameterMap& p) {
  SCOPED_TRACE(method);
  const auto estimator = EstimatorFactory::create(method, p);
  const auto fresh = EstimatorFactory::create(method, p);
  const auto run = sftest::simulateNav3Drive(6, 65, 0.0, 0);
  for (int k = 0; k < 3; ++k) {
    estimator->setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    fresh->setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    estimator->estimate(toInput(run[k].z));
    fresh->estimate(toInput(run[k].z));
  }
  const Output before = estimator->getLastEstimate();
  Input bad = toInput(run[3].z);
  bad[2] = InputValue(std::numeric_limits<double>::quiet_NaN());
  try {
    estimator->estimate(bad);
    ADD_FAILURE() << "NaN measurement accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_TRUE(contains(e.what(), "measurement 2")) << e.what();
  }
  bad[2] = InputValue(std::numeric_limits<double>::infinity());
  EXPECT_THROW(estimator->estimate(bad), InvalidInputError);
  Input badVariance = toInput(run[3].z);
  badVariance[1] = InputValue(0.1, -1.0, 0.0);  // negative variance
  EXPECT_THROW(estimator->estimate(badVariance), InvalidInputError);
  Input wrongSize;
  wrongSize.add(InputValue(1.0));
  EXPECT_THROW(estimator->estimate(wrongSize), InvalidInputError);

  EXPECT_EQ(values(estimator->getLastEstimate()), values(before));
  EXPECT_EQ(estimator->getLastEstimate().covariance, before.covariance);
  for (std::size_t k = 3; k < run.size(); ++k) {
    estimator->setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    fresh->setControlInput(toInput(Eigen::VectorXd(run[k].u)));
    const Output a = estimator->estimate(toInput(run[k].z));
    const Output b = fresh->estimate(toInput(run[k].z));
    EXPECT_EQ(values(a), values(b)) << "step " << k;
    EXPECT_EQ(a.covariance, b.covariance) << "step " << k;
  }
}

TEST(EstimatorFactoryRejection, NonFiniteMeasurementLeavesEveryFilterUnchanged) {
  const Nav3Reduced model;
  ParameterMap kf;
  kf["A"] = Eigen::MatrixXd(model.transitionMatrix());
  kf["B"] = Eigen::MatrixXd(model.controlMatrix());
  kf["H"] = Eigen::MatrixXd(model.observationMatrix());
  kf["Q"] = Eigen::MatrixXd(estimation::models::nav3ReducedProcessNoise());
  kf["R"] = Eigen::MatrixXd(estimation::models::nav3MeasurementNoise());
  checkNonFiniteMeasurementIsRejected("KalmanFilter", kf);
  checkNonFiniteMeasurementIsRejected("ExtendedKalmanFilter", nav3Parameters());
  checkNonFiniteMeasurementIsRejected("UnscentedKalmanFilter", nav3Parameters());
  ParameterMap pf = nav3Parameters();
  pf["Q"] = Eigen::MatrixXd(estimation::models::nav3ParticleProcessNoise());
  pf["particles"] = 200;
  pf["seed"] = 3;
  checkNonFiniteMeasurementIsRejected("ParticleFilterSIR", pf);
}

TEST(EstimatorFactoryRejection, ResetRestoresTheInitialEstimate) {
  const auto estimator = EstimatorFactory::create("ExtendedKalmanFilter", nav3Parameters());
  const auto fresh = EstimatorFactory::create("ExtendedKalmanFilter", nav3Parameters());
  const auto run = sftest::simulateNav3Drive(5, 66, 0.0, 0);
  for (const auto& step : run) estimator->estimate(toInput(step.z));
  estimator->reset();
  EXPECT_EQ(values(estimator->getLastEstimate()), Eigen::VectorXd(nav3x0()));
  const Output a = estimator->estimate(toInput(run[0].z));
  const Output b = fresh->estimate(toInput(run[0].z));
  EXPECT_EQ(values(a), values(b));
}

}  // namespace
