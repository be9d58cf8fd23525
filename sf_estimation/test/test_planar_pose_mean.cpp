// Tests of the SE(2) mean of planar poses (planar_pose_mean.hpp; SE(2) itself is tested in
// test_manifold_layout.cpp): the mean of poses on one arc against the arc's middle, and the
// particle filter's reported pose against ground truth on a dead-reckoned drive whose heading
// spreads.
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/planar_pose_mean.hpp"
#include "statistical_steps.hpp"

// Named, not anonymous: compiled in a unity group (sf_estimation/CMakeLists.txt).
namespace planar_pose_mean_test {

using estimation::Index;
using estimation::Matrix;
using estimation::Measurement;
using estimation::ParticleFilterParameters;
using estimation::ParticleFilterSIR;
using estimation::PlanarPoseIndices;
using estimation::Vector;

// Poses exp(s_i xi) on one arc from a start pose: relative to exp(mean(s) xi) their logs are
// (s_i - mean(s)) xi, which sum to zero with equal weights, so the SE(2) mean is the arc's
// pose at the mean distance. The entry-wise mean lies inside the arc.
TEST(PlanarPoseMean, PosesOnOneArcAverageToTheArc) {
  // Se2Block stores (theta, x, y); the twist xi = (theta, rho_x, rho_y) turns by 1.5 rad
  // over 2 m. The poses below are (x, y, heading), the filter's order.
  const Vector<3> xi(1.5, 2.0, 0.0);
  const Vector<3> start(0.4, 1.0, -2.0);
  const std::vector<double> s = {0.2, 0.7, 1.0, 1.3, 1.8};
  auto poseAt = [&](double distance) {
    Vector<3> stored;
    estimation::manifold::Se2Block::plus(start, Vector<3>(distance * xi), stored);
    return Vector<3>(stored(1), stored(2), stored(0));
  };
  std::vector<Vector<3>> poses;
  Vector<3> mean = Vector<3>::Zero();
  double sinSum = 0.0, cosSum = 0.0;
  for (const double d : s) {
    poses.push_back(poseAt(d));
    mean += poses.back() / static_cast<double>(s.size());
    sinSum += std::sin(poses.back()(2));
    cosSum += std::cos(poses.back()(2));
  }
  mean(2) = std::atan2(sinSum, cosSum);
  const Vector<3> expected = poseAt(1.0);
  EXPECT_GT((mean.head<2>() - expected.head<2>()).norm(), 0.05);  // entry-wise: off the arc
  estimation::planarPoseMean(
      PlanarPoseIndices{0, 1, 2},
      [&](auto&& f) {
        for (const auto& p : poses) f(p, 1.0 / static_cast<double>(s.size()));
      },
      mean);
  EXPECT_NEAR(mean(0), expected(0), 1e-10);
  EXPECT_NEAR(mean(1), expected(1), 1e-10);
  EXPECT_NEAR(mean(2), expected(2), 1e-10);
}

// Dead reckoning x = (px, py, theta, v, omega) over T = 0.1 s with no measurement: the white
// turn rate spreads the particles' headings along an ever wider arc (weights stay equal,
// nothing is resampled). The filter's pose is compared with the track its own speed and
// turn-rate estimates imply (integrated as the model does): the mean of the pose must not
// contract away from it. (With measurements and resampling the cloud collapses onto one
// lineage, whose integrated velocity noise no mean can undo: path degeneracy, doc/manifolds.md.)
struct DeadReckoning {
  static constexpr int StateSize = 5, MeasurementSize = 2, ControlSize = 0;
  Index stateSize() const { return 5; }
  Index measurementSize() const { return 2; }
  Index controlSize() const { return 0; }
  template <class S>
  void transition(const Eigen::Matrix<S, 5, 1>& x, const Vector<0>&,
                  Eigen::Matrix<S, 5, 1>& next) const {
    using std::cos;
    using std::sin;
    next << x(0) + 0.1 * x(3) * cos(x(2)), x(1) + 0.1 * x(3) * sin(x(2)), x(2) + 0.1 * x(4), x(3),
        S(0);  // a white turn rate (its process noise): the heading is a random walk
  }
  template <class S>
  void observation(const Eigen::Matrix<S, 5, 1>& x, Eigen::Matrix<S, 2, 1>& z) const {
    z << x(3), x(4);
  }
};

double finalDistanceFromOwnVelocities(bool planarPose) {
  ParticleFilterParameters params;
  params.particles = 700;
  params.seed = 11;
  if (planarPose) params.planarPose = PlanarPoseIndices{0, 1, 2};
  // Heading variance after 60 s: 600 * 0.1^2 * 0.1 = 0.6 rad^2.
  const Matrix<5, 5> Q = Vector<5>(0, 0, 0, 0, 0.1).asDiagonal();
  const Matrix<2, 2> R = Vector<2>(0.01, 0.1).asDiagonal();
  const Matrix<5, 5> P0 = Vector<5>(0, 0, 0, 0, 0).asDiagonal();
  ParticleFilterSIR<DeadReckoning> pf(DeadReckoning{}, Q, R, Vector<5>(0, 0, 0, 0.5, 0), P0, params,
                                      estimation::AngularComponents{{2}, {}});
  double px = 0.0, py = 0.0, theta = 0.0;
  Measurement<2> z(2);
  z.available << false, false;
  // 60 s for the headings to spread; 3 s under the sanitizers.
  for (int k = 0; k < sftest::statisticalSteps(600, 30); ++k) {
    // The model steps the pose with the previous period's speed and turn rate.
    const double v = pf.state()(3), w = pf.state()(4);
    pf.estimate(z);
    px += 0.1 * v * std::cos(theta);
    py += 0.1 * v * std::sin(theta);
    theta += 0.1 * w;
  }
  return std::hypot(pf.state()(0) - px, pf.state()(1) - py);
}

TEST(PlanarPoseMean, ParticleFilterPoseStaysOnTheTrack) {
  const double entryWise = finalDistanceFromOwnVelocities(false);
  const double onGroup = finalDistanceFromOwnVelocities(true);
  std::cout << "[ measured ] particle filter, 60 s dead reckoning, final distance from the "
               "track of its own velocity estimates: "
            << "entry-wise mean " << entryWise << " m, SE(2) mean " << onGroup << " m\n";
  EXPECT_TRUE(std::isfinite(entryWise) && std::isfinite(onGroup));
  if (sftest::kStatisticsAsserted) {
    EXPECT_LT(onGroup, 0.5 * entryWise);
  }
}

TEST(PlanarPoseMean, ParticleFilterRefusesABadPose) {
  ParticleFilterParameters params;
  const Matrix<5, 5> I5 = Matrix<5, 5>::Identity();
  const Matrix<2, 2> I2 = Matrix<2, 2>::Identity();
  auto make = [&](PlanarPoseIndices k, std::vector<Index> angles) {
    params.planarPose = k;
    ParticleFilterSIR<DeadReckoning> pf(DeadReckoning{}, I5, I2, Vector<5>::Zero(), I5, params,
                                        estimation::AngularComponents{angles, {}});
  };
  EXPECT_NO_THROW(make({0, 1, 2}, {2}));
  EXPECT_THROW(make({0, 1, 5}, {2}), estimation::ParameterError);
  EXPECT_THROW(make({0, 0, 2}, {2}), estimation::ParameterError);
  try {
    make({0, 1, 2}, {});
    ADD_FAILURE() << "a heading that is not an angle state was accepted";
  } catch (const estimation::ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("heading x[2] is not an angle state"), std::string::npos)
        << e.what();
  }
}

}  // namespace planar_pose_mean_test
