// DERIVED_INPUTS MAGNETIC_YAW through the code a configuration header generates
// (test/configs/magnetic_heading_ekf.h, an INPUTS record): the reader of serialized
// sensor_msgs/MagneticField messages against hand-computed headings, ~magnetic_declination read
// and range-checked like the node's other parameters, and the header's filter following a
// turning robot across the +-pi seam.
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "configs/magnetic_heading_ekf.h"

#include <sf_filter/config/configuration.hpp>

#include "sf_filter/generated/node_definition_of.hpp"
#include "sf_filter/io/extractor_parameters.hpp"

#include "recording_sink.hpp"

namespace {

using sf_filter::TopicReader;
using sf_test::feed;
using sf_test::readerOf;
using sf_test::RecordingSink;

constexpr double kDeg = M_PI / 180.0;

/// What a level magnetometer measures at true yaw `yaw` (ENU) where magnetic north lies
/// `declination` east of true north: the horizontal field (20 uT) at yaw_magnetic = yaw +
/// declination from magnetic east, b = (B sin yaw_magnetic, B cos yaw_magnetic).
sensor_msgs::MagneticField magnetometer(double yaw, double declination, double stamp) {
  sensor_msgs::MagneticField m;
  m.header.stamp = ros::Time(stamp);
  m.magnetic_field.x = 2e-5 * std::sin(yaw + declination);
  m.magnetic_field.y = 2e-5 * std::cos(yaw + declination);
  m.magnetic_field.z = -4e-5;
  return m;
}

/// Private parameters from a map (the node's come from the parameter server, the replay's
/// from --params).
class MapParameters final : public sf_filter::ParameterSource {
 public:
  explicit MapParameters(std::map<std::string, XmlRpc::XmlRpcValue> values)
      : values_(std::move(values)) {}
  bool get(const std::string& name, XmlRpc::XmlRpcValue& value) const override {
    const auto it = values_.find(name);
    if (it == values_.end()) return false;
    value = it->second;
    return true;
  }
  std::vector<std::string> names() const override {
    std::vector<std::string> n;
    for (const auto& [name, value] : values_) n.push_back(name);
    return n;
  }

 private:
  std::map<std::string, XmlRpc::XmlRpcValue> values_;
};

TEST(MagneticHeading, Description) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  ASSERT_EQ(d.description.inputs.size(), 2u);
  EXPECT_EQ(d.description.inputs[0], "mag_yaw: imu/mag magnetic_field magnetic_yaw");
  EXPECT_TRUE(sf_config::kAngleInputs[0]);  // an angle input without ANGLE_INPUTS
  EXPECT_FALSE(sf_config::kAngleInputs[1]);
  ASSERT_EQ(d.extractorParameters.size(), 1u);
  EXPECT_EQ(d.extractorParameters[0].name, "magnetic_declination");
}

TEST(MagneticHeading, ReaderGivesHandComputedHeadings) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  const TopicReader& reader = readerOf(d, "imu/mag");
  RecordingSink sink;
  // Facing north-west (135 deg) without declination: b = (B sin 135, B cos 135).
  feed(reader, magnetometer(135 * kDeg, 0.0, 1.0), sink, 1.0);
  // The same field read with ~magnetic_declination 10 deg east: the robot faces 125 deg.
  sink.state.extractorParameters() = sf_filter::loadExtractorParameters(
      MapParameters({{"magnetic_declination", 10 * kDeg}}), d.extractorParameters);
  feed(reader, magnetometer(135 * kDeg, 0.0, 1.1), sink, 1.1);
  // A field with a known covariance: sigma_x = sigma_y = 1 uT over |b| = 20 uT, so the heading's
  // variance is (1 / 20)^2 rad^2 whatever the direction.
  sensor_msgs::MagneticField known = magnetometer(-170 * kDeg, 10 * kDeg, 1.2);
  known.magnetic_field_covariance[0] = known.magnetic_field_covariance[4] = 1e-12;
  known.magnetic_field_covariance[8] = 1e-12;
  feed(reader, known, sink, 1.2);
  ASSERT_EQ(sink.values.size(), 3u);
  EXPECT_NEAR(sink.values[0].value, 135 * kDeg, 1e-12);
  EXPECT_FALSE(sink.values[0].variance);  // all-zero covariance: the header's R
  EXPECT_DOUBLE_EQ(sink.values[0].stamp, 1.0);
  EXPECT_NEAR(sink.values[1].value, 125 * kDeg, 1e-12);
  EXPECT_NEAR(sink.values[2].value, -170 * kDeg, 1e-12);
  ASSERT_TRUE(sink.values[2].variance);
  EXPECT_NEAR(*sink.values[2].variance, 0.0025, 1e-15);
  EXPECT_EQ(sink.state.covarianceFallbacks(0), 2u);
}

TEST(MagneticHeading, DeclinationOutOfRangeIsRefused) {
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  try {
    sf_filter::loadExtractorParameters(MapParameters({{"magnetic_declination", 4.0}}),
                                       d.extractorParameters);
    FAIL() << "a declination of 4 rad was accepted";
  } catch (const sf_filter::ParameterOverrideError& e) {
    EXPECT_EQ(std::string(e.what()),
              "parameter ~magnetic_declination: expected radians in [-pi, pi], magnetic north "
              "east of true north positive, found 4");
  }
  EXPECT_THROW(
      sf_filter::loadExtractorParameters(
          MapParameters({{"magnetic_declination", std::string("east")}}), d.extractorParameters),
      sf_filter::ParameterOverrideError);
  // Known to the node: no "unknown parameter" warning.
  EXPECT_TRUE(
      sf_filter::unknownParameterWarnings(MapParameters({{"magnetic_declination", 0.1}}),
                                          sf_filter::extractorParameterNames(d.extractorParameters))
          .empty());
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

TEST(MagneticHeading, FilterFollowsATurnAcrossTheSeam) {
  // Turning at 0.5 rad/s from yaw 2.8 (across +pi after 0.68 s) where magnetic north lies
  // 12 deg west of true north; the magnetometer and the gyro are noise-free.
  const sf_filter::NodeDefinition d = sf_filter::generated::nodeDefinition();
  sf_filter::FusionCoreOptions options;
  options.period = d.estimationPeriodMs / 1000.0;
  options.inputs = d.inputOptions;
  auto engine = d.makeEngine(d.defaultParameters(d.estimationPeriodMs), options);
  EngineSink sink(*engine);
  sink.state.extractorParameters().set("magnetic_declination", -12 * kDeg);
  const TopicReader& mag = readerOf(d, "imu/mag");
  const TopicReader& gyro = readerOf(d, "imu/data");
  const double omega = 0.5, yaw0 = 2.8;
  double lastYaw = 0.0, lastOmega = 0.0;
  auto onEstimate = [&](const sf_filter::EstimateRef& e) {
    lastYaw = e.state[0];
    lastOmega = e.state[1];
  };
  for (int k = 1; k <= 100; ++k) {
    const double t = 50.0 + 0.1 * k - 0.05;
    const double trueYaw = yaw0 + omega * (t - 50.0);
    feed(mag, magnetometer(trueYaw, -12 * kDeg, t), sink, t);
    sensor_msgs::Imu imu;
    imu.header.stamp = ros::Time(t);
    imu.angular_velocity.z = omega;
    feed(gyro, imu, sink, t);
    engine->advanceTo(50.0 + 0.1 * k, onEstimate);
  }
  // The estimate at the end of the last period (t = 60.0) against the true yaw there.
  const double trueEnd = yaw0 + omega * 10.0;
  EXPECT_LT(std::abs(std::remainder(lastYaw - trueEnd, 2 * M_PI)), 0.03);
  EXPECT_LE(std::abs(lastYaw), M_PI);
  EXPECT_NEAR(lastOmega, omega, 0.01);
}

}  // namespace
