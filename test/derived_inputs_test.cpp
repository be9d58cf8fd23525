// DERIVED_INPUTS and INPUT_COVARIANCE through the code a configuration header generates
// (test/configs/derived_inputs_ekf.h): the NodeDefinition's topic readers on serialized
// sensor_msgs/Imu and nav_msgs/Odometry messages, checked against hand-computed values, and
// its filter fed a simulated robot driving circles across the +-pi seam.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "configs/derived_inputs_ekf.h"

#include <sf_filter/config/configuration.hpp>

#include "sf_filter/generated/node_definition_of.hpp"

#include "recording_sink.hpp"

namespace {

using sf_filter::TopicReader;

using sf_test::feed;
using sf_test::readerOf;
using sf_test::RecordingSink;

geometry_msgs::Quaternion aboutZ(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2);
  q.w = std::cos(yaw / 2);
  return q;
}

sensor_msgs::Imu imu(double yaw, double stamp, double variance) {
  sensor_msgs::Imu m;
  m.header.stamp = ros::Time(stamp);
  m.orientation = aboutZ(yaw);
  m.orientation_covariance[0] = m.orientation_covariance[4] = variance;
  m.orientation_covariance[8] = variance;
  return m;
}

nav_msgs::Odometry odom(double x, double y, double yaw, double stamp, double variance) {
  nav_msgs::Odometry m;
  m.header.stamp = ros::Time(stamp);
  m.pose.pose.position.x = x;
  m.pose.pose.position.y = y;
  m.pose.pose.orientation = aboutZ(yaw);
  m.pose.covariance[0] = variance;       // x
  m.pose.covariance[7] = 2 * variance;   // y
  m.pose.covariance[35] = 3 * variance;  // yaw
  return m;
}

TEST(DerivedInputs, Description) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  ASSERT_EQ(d.description.inputs.size(), 4u);
  EXPECT_EQ(d.description.inputs[0], "imu/data orientation yaw");
  EXPECT_EQ(d.description.inputs[1], "odom pose.pose x differential");
  EXPECT_EQ(d.description.inputs[3], "odom pose.pose.orientation yaw differential");
  EXPECT_EQ(d.topics.size(), 2u);                          // one reader per topic
  ASSERT_TRUE(d.description.pose && d.description.twist);  // POSE_OUT, TWIST_OUT
  EXPECT_EQ((*d.description.twist)[0], 3);
  EXPECT_EQ((*d.description.twist)[1], 4);
  EXPECT_TRUE(sf_config::kAngleInputs[0] && sf_config::kAngleInputs[3]);
  EXPECT_FALSE(sf_config::kAngleInputs[1] || sf_config::kAngleInputs[2]);
}

TEST(DerivedInputs, ImuYawAndItsCovariance) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  RecordingSink sink;
  const TopicReader& reader = readerOf(d, "imu/data");
  feed(reader, imu(3.0, 1.0, 0.02), sink, 1.0);
  feed(reader, imu(-3.0, 1.1, 0.0), sink, 1.1);  // all-zero covariance: the header's R
  sensor_msgs::Imu unknown = imu(M_PI, 1.2, 0.5);
  unknown.orientation_covariance[0] = -1;  // ROS's "unknown"
  feed(reader, unknown, sink, 1.2);
  ASSERT_EQ(sink.values.size(), 3u);
  EXPECT_NEAR(sink.values[0].value, 3.0, 1e-12);
  EXPECT_EQ(sink.values[0].variance, 0.02);
  EXPECT_DOUBLE_EQ(sink.values[0].stamp, 1.0);
  EXPECT_NEAR(sink.values[1].value, -3.0, 1e-12);
  EXPECT_FALSE(sink.values[1].variance);
  EXPECT_NEAR(sink.values[2].value, M_PI, 1e-12);
  EXPECT_FALSE(sink.values[2].variance);
  EXPECT_EQ(sink.state.covarianceFallbacks(0), 2u);
}

TEST(DerivedInputs, OdometryDifferentialAgainstHandComputedSteps) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  RecordingSink sink;
  const TopicReader& reader = readerOf(d, "odom");
  // (1, 2) facing yaw 3.0, then (1 + 0.4 cos 3.0 - 0.1 sin 3.0, 2 + 0.4 sin 3.0 + 0.1 cos 3.0)
  // facing -3.0: 0.4 forward, 0.1 to the left, a turn of 2 pi - 6 = 0.2832 across the seam.
  feed(reader, odom(1, 2, 3.0, 5.0, 0.01), sink, 5.0);
  EXPECT_TRUE(sink.values.empty());  // the first message only starts the differences
  const double x1 = 1 + 0.4 * std::cos(3.0) - 0.1 * std::sin(3.0);
  const double y1 = 2 + 0.4 * std::sin(3.0) + 0.1 * std::cos(3.0);
  feed(reader, odom(x1, y1, -3.0, 5.1, 0.02), sink, 5.1);
  ASSERT_EQ(sink.values.size(), 3u);
  EXPECT_EQ(sink.values[0].input, 1);
  EXPECT_NEAR(sink.values[0].value, 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(*sink.values[0].variance, 0.01 + 0.02);
  EXPECT_EQ(sink.values[1].input, 2);
  EXPECT_NEAR(sink.values[1].value, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(*sink.values[1].variance, 2 * (0.01 + 0.02));
  EXPECT_EQ(sink.values[2].input, 3);
  EXPECT_NEAR(sink.values[2].value, 2 * M_PI - 6.0, 1e-12);
  EXPECT_DOUBLE_EQ(*sink.values[2].variance, 3 * (0.01 + 0.02));
  EXPECT_DOUBLE_EQ(sink.values[2].stamp, 5.1);
  // A second sink (another run) starts anew.
  RecordingSink other;
  feed(reader, odom(x1, y1, -3.0, 5.1, 0.02), other, 5.1);
  EXPECT_TRUE(other.values.empty());
}

/// Forwards the readers' values to a fusion engine.
class EngineSink final : public sf_filter::MessageSink {
 public:
  explicit EngineSink(sf_filter::FusionEngine& engine) : engine_(engine) {}
  void measurement(estimation::Index input, double now, double value,
                   std::optional<double> variance, double stamp) override {
    engine_.addMeasurement(input, now, value, variance, stamp);
  }
  void control(estimation::Index, double) override {}
  std::optional<double> rotated(estimation::Index, const std::string&, std::uint32_t, std::uint32_t,
                                const std::array<double, 3>&, int) override {
    return std::nullopt;
  }

  sf_filter::InputState state;  ///< what the readers keep between messages

 private:
  sf_filter::FusionEngine& engine_;
};

TEST(DerivedInputs, FilterTracksACircleAcrossTheSeam) {
  // The robot drives at v = 0.5 m/s and omega = 0.8 rad/s from yaw 2.5 (crossing +-pi after
  // 0.8 s and every 7.85 s); the IMU reports the yaw with noise-free values, the odometry its
  // integrated pose in its own frame (started elsewhere, rotated: only differences count).
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  sf_filter::FusionCoreOptions options;
  options.period = d.estimationPeriodMs / 1000.0;
  options.inputs = d.inputOptions;
  auto engine = d.makeEngine(d.defaultParameters(d.estimationPeriodMs), options);
  EngineSink sink(*engine);
  const TopicReader& imuReader = readerOf(d, "imu/data");
  const TopicReader& odomReader = readerOf(d, "odom");
  const double v = 0.5, omega = 0.8, yaw0 = 2.5;
  double lastYaw = 0.0, lastV = 0.0, lastOmega = 0.0, trueYaw = yaw0;
  auto onEstimate = [&](const sf_filter::EstimateRef& e) {
    lastYaw = e.state[2];
    lastV = e.state[3];
    lastOmega = e.state[4];
  };
  for (int k = 1; k <= 300; ++k) {
    const double t = 100.0 + 0.1 * k - 0.05;  // mid-period
    trueYaw = yaw0 + omega * (t - 100.0);
    const double wrapped = std::atan2(std::sin(trueYaw), std::cos(trueYaw));
    feed(imuReader, imu(wrapped, t, 0.01), sink, t);
    // The odometry's frame: its own origin and heading offset 1.0 rad.
    const double oyaw = trueYaw + 1.0;
    const double radius = v / omega;
    const double ox = 7.0 + radius * std::sin(oyaw), oy = -3.0 - radius * std::cos(oyaw);
    feed(odomReader, odom(ox, oy, oyaw, t, 1e-6), sink, t);
    engine->advanceTo(100.0 + 0.1 * k, onEstimate);
  }
  const double wrappedTrue = std::atan2(std::sin(trueYaw), std::cos(trueYaw));
  EXPECT_LT(std::abs(std::remainder(lastYaw - wrappedTrue, 2 * M_PI)), 0.02);
  EXPECT_LE(std::abs(lastYaw), M_PI);  // the angle state stays wrapped
  // A circle step's chord: v T sinc(omega T / 2) forward (0.04997 of 0.05 m per period).
  EXPECT_NEAR(lastV, v * std::sin(omega * 0.05) / (omega * 0.05), 0.002);
  EXPECT_NEAR(lastOmega, omega, 0.01);
}

}  // namespace
