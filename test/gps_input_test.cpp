// GPS inputs (DERIVED_INPUTS EAST, NORTH of a sensor_msgs/NavSatFix) through the code the
// shipped header config/husky_skid_steer_gps.h generates: its NodeDefinition's reader of /fix
// on serialized messages. A fix without a valid status is dropped and counted, the first valid
// fix is the datum, a fix 100 m north (WGS84 meridian radius of curvature at its height) is
// 100 m along the odom axis the yaw offset says, with the fix's own variances turned alike
// and scaled by the header's GPS_COVARIANCE_SCALE, and a fix whose covariance type is unknown falls
// back to the header's R, counted; a fix of known covariance type gives east and north together
// with their covariance in the odom frame.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "husky_skid_steer_gps.h"

#include <sf_filter/config/configuration.hpp>

#include "sf_filter/generated/node_definition_of.hpp"

#include "recording_sink.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr long kEastInput = 3, kNorthInput = 4;
constexpr double kLat = 43.5, kLon = 7.25, kAlt = 272.4;
// The header's GPS_COVARIANCE_SCALE: the filter gets this part of each fix's covariance (the
// white part; the header has the receiver's slow error as a state).
constexpr double kScale = 0.003;

using sf_test::feed;
using sf_test::readerOf;
using sf_test::RecordingSink;

sensor_msgs::NavSatFix navSatFix(double lat, double stamp, int status = 1, int type = 2) {
  sensor_msgs::NavSatFix m;
  m.header.stamp = ros::Time(stamp);
  m.status.status = static_cast<std::int8_t>(status);
  m.latitude = lat;
  m.longitude = kLon;
  m.altitude = kAlt;
  m.position_covariance[0] = 0.81;  // east
  m.position_covariance[4] = 1.21;  // north
  m.position_covariance[8] = 3.24;  // up
  m.position_covariance_type = static_cast<std::uint8_t>(type);
  return m;
}

/// Latitude [deg] 100 m north of kLat at height kAlt (meridian radius M + h, WGS84).
double hundredMetresNorth() {
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double s = std::sin(kLat * kPi / 180);
  const double m = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
  return kLat + 100.0 / (m + kAlt) * 180 / kPi;
}

TEST(GpsInput, NamesSayWhatIsDerived) {
  const auto d = sf_filter::generated::nodeDefinition();
  EXPECT_EQ(d.description.inputs[kEastInput], "/fix longitude east");
  EXPECT_EQ(d.description.inputs[kNorthInput], "/fix latitude north");
}

TEST(GpsInput, StatusDatumYawOffsetAndCovariance) {
  const auto d = sf_filter::generated::nodeDefinition();
  const sf_filter::TopicReader& fix = readerOf(d, "/fix");
  RecordingSink sink;
  sink.state.gps().setOptions({std::nullopt, kPi / 2});  // odom x points north

  feed(fix, navSatFix(10.0, 1.0, -1), sink, 0.0);  // STATUS_NO_FIX: dropped, not the datum
  EXPECT_TRUE(sink.values.empty());
  EXPECT_EQ(sink.state.gps().noFix(kEastInput), 1u);
  EXPECT_EQ(sink.state.gps().noFix(kNorthInput), 1u);

  feed(fix, navSatFix(kLat, 2.0), sink, 0.0);  // the datum
  ASSERT_EQ(sink.values.size(), 2u);
  EXPECT_NEAR(sink.values[0].value, 0.0, 1e-9);
  EXPECT_NEAR(sink.values[1].value, 0.0, 1e-9);
  EXPECT_EQ(sink.values[0].stamp, 2.0);

  sink.values.clear();
  feed(fix, navSatFix(hundredMetresNorth(), 3.0), sink, 0.0);
  ASSERT_EQ(sink.values.size(), 2u);
  EXPECT_EQ(sink.values[0].input, kEastInput);
  EXPECT_NEAR(sink.values[0].value, 100.0, 1e-3);  // odom x: north
  EXPECT_NEAR(sink.values[1].value, 0.0, 1e-3);
  EXPECT_NEAR(*sink.values[0].variance, kScale * 1.21, 1e-14);  // the north variance
  EXPECT_NEAR(*sink.values[1].variance, kScale * 0.81, 1e-14);

  sink.values.clear();
  feed(fix, navSatFix(kLat, 4.0, 0, 0), sink, 0.0);  // COVARIANCE_TYPE_UNKNOWN: the header's R
  ASSERT_EQ(sink.values.size(), 2u);
  EXPECT_FALSE(sink.values[0].variance);
  EXPECT_FALSE(sink.values[1].variance);
  EXPECT_EQ(sink.state.covarianceFallbacks(kEastInput), 1u);
  EXPECT_EQ(sink.state.covarianceFallbacks(kNorthInput), 1u);
  EXPECT_EQ(sink.blocks.size(), 2u);  // the two fixes of known covariance, not this one
}

TEST(GpsInput, CovarianceOfEastAndNorthReachesTheSinkTurned) {
  const auto d = sf_filter::generated::nodeDefinition();
  const sf_filter::TopicReader& fix = readerOf(d, "/fix");
  RecordingSink sink;
  sink.state.gps().setOptions({std::nullopt, kPi / 6});  // c = sqrt 3 / 2, s = 1 / 2
  const double c = std::sqrt(3.0) / 2, s = 0.5;
  feed(fix, navSatFix(kLat, 1.0), sink, 0.0);  // the datum
  sink.values.clear();
  sink.blocks.clear();

  // KNOWN: east 1, north 2, their covariance 0.5; R = Rot S Rot^T by hand (local_frame.hpp):
  // xx = c^2 + 2 c s 0.5 + 2 s^2, yy = s^2 - 2 c s 0.5 + 2 c^2, xy = -c s + (c^2 - s^2) 0.5 + 2 c
  // s.
  sensor_msgs::NavSatFix known = navSatFix(hundredMetresNorth(), 2.0, 0, 3);
  known.position_covariance = {1.0, 0.5, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 3.24};
  feed(fix, known, sink, 0.0);
  ASSERT_EQ(sink.blocks.size(), 1u);
  const sf_test::Block& b = sink.blocks[0];
  ASSERT_EQ(b.inputs, (std::vector<long>{kEastInput, kNorthInput}));
  EXPECT_NEAR(b.covariance[0], kScale * (c * c + c * s + 2 * s * s), 1e-14);
  EXPECT_NEAR(b.covariance[3], kScale * (s * s - c * s + 2 * c * c), 1e-14);
  EXPECT_NEAR(b.covariance[1], kScale * (c * s + 0.5 * (c * c - s * s)), 1e-14);
  EXPECT_EQ(b.covariance[1], b.covariance[2]);
  // The values: 100 m north is x = 100 s, y = 100 c.
  ASSERT_EQ(sink.values.size(), 2u);
  EXPECT_NEAR(sink.values[0].value, 100.0 * s, 1e-3);
  EXPECT_NEAR(sink.values[1].value, 100.0 * c, 1e-3);
  EXPECT_EQ(sink.values[0].stamp, 2.0);

  // DIAGONAL_KNOWN: the off-diagonal entries are ignored; the unequal variances turned still
  // correlate x and y: xy = c s (2 - 1).
  known.position_covariance_type = 2;
  known.header.stamp = ros::Time(3.0);
  feed(fix, known, sink, 0.0);
  ASSERT_EQ(sink.blocks.size(), 2u);
  EXPECT_NEAR(sink.blocks[1].covariance[0], kScale * (c * c + 2 * s * s), 1e-14);
  EXPECT_NEAR(sink.blocks[1].covariance[3], kScale * (s * s + 2 * c * c), 1e-14);
  EXPECT_NEAR(sink.blocks[1].covariance[1], kScale * c * s, 1e-14);
  EXPECT_EQ(sink.state.covarianceFallbacks(kEastInput), 0u);
}

TEST(GpsInput, AFirstFixNotOnTheEarthIsNotTheDatum) {
  // Issue 38 D2 through the header's reader: latitude 91 first (was the datum, every later
  // fix then "not finite"); dropped and counted, the next fix is the datum.
  const auto d = sf_filter::generated::nodeDefinition();
  const sf_filter::TopicReader& fix = readerOf(d, "/fix");
  RecordingSink sink;
  feed(fix, navSatFix(91.0, 1.0), sink, 0.0);
  EXPECT_TRUE(sink.values.empty());
  EXPECT_TRUE(sink.blocks.empty());
  EXPECT_EQ(sink.state.gps().implausibleFixes(kEastInput), 1u);
  EXPECT_EQ(sink.state.gps().implausibleReason(kNorthInput),
            "latitude 91 outside [-90, 90] degrees");
  feed(fix, navSatFix(kLat, 2.0), sink, 0.0);
  ASSERT_TRUE(sink.state.gps().datum());
  EXPECT_EQ(sink.state.gps().datum()->latitude, kLat);
  sink.values.clear();
  sink.blocks.clear();
  feed(fix, navSatFix(hundredMetresNorth(), 3.0), sink, 0.0);
  ASSERT_EQ(sink.values.size(), 2u);
  EXPECT_NEAR(sink.values[1].value, 100.0, 1e-3);  // north, no yaw offset
}

TEST(GpsInput, TheHeaderGatesTheFixesAtTenSigma) {
  // Issue 38 D3: the shipped GPS header had no gate, and a 1000 km jump was fused. East and
  // north are gated at a squared Mahalanobis distance of 100 (10 sigma); the other inputs
  // are not (infinity: no gate).
  EXPECT_EQ(sf_config::kGateThresholds[kEastInput], 100.0);
  EXPECT_EQ(sf_config::kGateThresholds[kNorthInput], 100.0);
  for (long i = 0; i < kEastInput; ++i) EXPECT_TRUE(std::isinf(sf_config::kGateThresholds[i])) << i;
}

}  // namespace
