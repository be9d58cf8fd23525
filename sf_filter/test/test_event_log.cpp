// The noise identification's record of a bag replay (sf_filter/tuning/event_log.hpp): a
// message's covariance block (INPUT_COVARIANCE_BLOCK, a GPS fix) is replayed as a block, so
// that its covariances reach the filter as in the bag replay. Checked against the Kalman
// update of a position held still computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <sf_estimation/kalman_filter.hpp>

#include "sf_filter/core/fusion_engine_of.hpp"
#include "sf_filter/tuning/event_log.hpp"

namespace {

using estimation::Matrix;
using estimation::Vector;

/// A position (x, y) held still (Q = 0, P0 = I), measured by x and y (header R = 4 I).
using Position = estimation::KalmanFilter<2, 2, 0>;

struct Collector {
  std::vector<Eigen::VectorXd> states;
  std::vector<Eigen::MatrixXd> covariances;
  void operator()(const sf_filter::EstimateRef& e) {
    states.emplace_back(e.state);
    covariances.emplace_back(e.covariance);
  }
};

TEST(EventLog, ReplaysACovarianceBlockAsABlock) {
  const Matrix<2, 2> I = Matrix<2, 2>::Identity();
  sf_filter::FusionCoreOptions options;
  options.period = 0.1;
  sf_filter::FusionEngineOf<Position> engine(
      Position(I, Matrix<2, 0>(), I, Matrix<2, 2>::Zero(), 4.0 * I, Vector<2>::Zero(), I), options);

  sf_filter::EventLog log;
  const estimation::Index inputs[] = {0, 1};
  const double values[] = {1.0, 2.0};
  const double block[] = {1.0, 0.5, 0.5, 1.0};
  log.clock(0.0);
  log.measurementBlock(inputs, values, block, 2, 0.02, std::numeric_limits<double>::quiet_NaN());
  log.clock(0.15);
  Collector out;
  log.replay(engine, out);

  // P- = I, S = I + R = ((2, .5), (.5, 2)), det 3.75: x = S^-1 z = (2 - 1, -.5 + 4) / 3.75,
  // P = I - S^-1. With the variances alone y would be 2 / 2 = 1.
  ASSERT_FALSE(out.states.empty());
  const Eigen::VectorXd& x = out.states.front();
  EXPECT_NEAR(x[0], 1.0 / 3.75, 1e-14);
  EXPECT_NEAR(x[1], 3.5 / 3.75, 1e-14);
  const Eigen::MatrixXd& P = out.covariances.front();
  EXPECT_NEAR(P(0, 0), 1.0 - 2.0 / 3.75, 1e-14);
  EXPECT_NEAR(P(0, 1), 0.5 / 3.75, 1e-14);
  EXPECT_NEAR(P(1, 1), 1.0 - 2.0 / 3.75, 1e-14);
}

}  // namespace
