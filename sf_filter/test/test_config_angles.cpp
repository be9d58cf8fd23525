// ANGLE_STATES and ANGLE_INPUTS from a configuration header to the filter: the generated
// flags (sf_filter/config/detail/angles.hpp) and the filter makeFilter() builds from them,
// for test/config_errors/valid_angles.h (a UKF, heading x[2], compass as input 0).
// The configuration header first: configuration.hpp reads its macros.
#include "valid_angles.h"

#include <sf_filter/config/configuration.hpp>
#include <sf_filter/config/filter_binding.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace {

static_assert(sf_config::kHasAngleStates && sf_config::kHasAngleInputs, "both are defined");
static_assert(!sf_config::kAngleStates[0] && !sf_config::kAngleStates[1] &&
                  sf_config::kAngleStates[2],
              "ANGLE_STATES (2)");
static_assert(sf_config::kAngleInputs[0] && !sf_config::kAngleInputs[1], "ANGLE_INPUTS (0)");

TEST(ConfigAngles, DeclarationsReachTheFilter) {
  sf_filter::generated::Filter filter =
      sf_filter::generated::makeFilter(sf_config::defaultParameters());
  EXPECT_FALSE(filter.angleStates()(0));
  EXPECT_FALSE(filter.angleStates()(1));
  EXPECT_TRUE(filter.angleStates()(2));
  EXPECT_TRUE(filter.angleMeasurements()(0));
  EXPECT_FALSE(filter.angleMeasurements()(1));
}

TEST(ConfigAngles, AngleInputsAreAnglesForTheirAlignmentToo) {
  const auto inputs = sf_config::defaultInputOptions();
  ASSERT_EQ(inputs.size(), 2u);
  EXPECT_TRUE(inputs[0].angle);  // the compass: circular mean, unwrapped holds
  EXPECT_FALSE(inputs[1].angle);
}

TEST(ConfigAngles, CompassInnovationIsWrapped) {
  // Heading 3.1 with P = I (the default P0), compass -3.1 with R = 0.05, the range missing,
  // no motion (u = 0): the heading's prior variance is 1 + 0.001 and the compass update is
  // exact in the UKF (h is linear in the heading), K = 1.001 / 1.051. The wrapped innovation
  // 2 pi - 6.2 moves the heading across pi; a linear one (-6.2) would swing it to -2.80.
  constexpr double kPi = 3.14159265358979323846;
  sf_filter::generated::Filter filter =
      sf_filter::generated::makeFilter(sf_config::defaultParameters());
  filter.setBelief(Eigen::Vector3d(0.0, 0.0, 3.1), Eigen::Matrix3d::Identity());
  estimation::Measurement<2> z = estimation::Measurement<2>::complete(Eigen::Vector2d(-3.1, 0.0));
  z.available(1) = false;
  filter.estimate(z);
  const double gain = 1.001 / 1.051;
  const double expected = estimation::wrapAngle(3.1 + gain * (2.0 * kPi - 6.2));
  EXPECT_NEAR(filter.state()(2), expected, 1e-9);
  EXPECT_LT(filter.state()(2), -3.0);  // wrapped into (-pi, pi]
}

}  // namespace
