// Spatial alignment (FRAME_ALIGNED_INPUTS) and POSE_OUT of a generated fusion node
// (test/configs/imu_heading_ekf.h) under a ROS master, plus unit tests of the tf2 rotation
// helper (sf_filter/io/vector_rotation.hpp) on a bare tf2::BufferCore.
//
// The robot turns counter-clockwise (positive yaw rate about base_link's z axis). Its gyros:
//   imu        sensor_msgs/Imu in imu_link, mounted upside down (180 deg about x): the raw
//              angular_velocity.z is the NEGATIVE yaw rate
//   gyro       geometry_msgs/Vector3Stamped in gyro_link (-90 deg about y): the yaw rate is
//              the raw vector.x; its transform is published after the first gyro message
//   imu_unmounted  sensor_msgs/Imu in unmounted_link, which has no transform
// The test publishes the static transforms, owns /clock and compares each estimate with the
// library's EKF on an independently written model fed with the base-frame yaw rates, the
// nav_msgs/Odometry with the state, and the odom -> base_link transform with the odometry.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/Imu.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/buffer_core.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <sf_estimation/extended_kalman_filter.hpp>
#include <sf_msgs/StateEstimateStamped.h>

#include "sf_filter/io/vector_rotation.hpp"

namespace {

using estimation::Index;
using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;

constexpr double kPeriod = 0.1;
constexpr double kStart = 1.0;
constexpr double kSpeed = 1.0;

geometry_msgs::TransformStamped staticTransform(const std::string& parent, const std::string& child,
                                                double tx, double ty, double tz,
                                                const tf2::Quaternion& q) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = tx;
  t.transform.translation.y = ty;
  t.transform.translation.z = tz;
  t.transform.rotation.x = q.x();
  t.transform.rotation.y = q.y();
  t.transform.rotation.z = q.z();
  t.transform.rotation.w = q.w();
  return t;
}

tf2::Quaternion rpy(double roll, double pitch, double yaw) {
  tf2::Quaternion q;
  q.setRPY(roll, pitch, yaw);
  return q;
}

// ------------------------------------------------------------------ vector_rotation.hpp, no master
TEST(VectorRotation, StaticMountRotatesAtAnyStampAndIgnoresTranslation) {
  tf2::BufferCore buffer;
  buffer.setTransform(staticTransform("base_link", "imu_link", 0.3, -0.2, 0.5, rpy(M_PI, 0, 0)),
                      "test", true);
  geometry_msgs::Vector3 v;
  v.x = 1.0;
  v.y = 2.0;
  v.z = 3.0;
  for (double stamp : {0.0, 5.0, 1e6}) {
    std::string error;
    const auto r = sf_filter::rotateVector(buffer, v, "imu_link", "base_link", ros::Time(stamp), &error);
    ASSERT_TRUE(r) << error;
    EXPECT_NEAR(r->x, 1.0, 1e-12);
    EXPECT_NEAR(r->y, -2.0, 1e-12);
    EXPECT_NEAR(r->z, -3.0, 1e-12);
  }
  const auto same = sf_filter::rotateVector(buffer, v, "base_link", "base_link", ros::Time(1.0));
  ASSERT_TRUE(same);
  EXPECT_EQ(same->z, 3.0);
}

TEST(VectorRotation, DynamicFrameIsInterpolatedButNeverExtrapolated) {
  tf2::BufferCore buffer;
  geometry_msgs::TransformStamped t = staticTransform("odom", "base_link", 0, 0, 0, rpy(0, 0, 0));
  t.header.stamp = ros::Time(1.0);
  buffer.setTransform(t, "test");
  t = staticTransform("odom", "base_link", 1, 0, 0, rpy(0, 0, M_PI / 2));
  t.header.stamp = ros::Time(2.0);
  buffer.setTransform(t, "test");
  geometry_msgs::Vector3 v;
  v.x = 1.0;
  const auto mid = sf_filter::rotateVector(buffer, v, "base_link", "odom", ros::Time(1.5));
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->x, std::cos(M_PI / 4), 1e-9);
  EXPECT_NEAR(mid->y, std::sin(M_PI / 4), 1e-9);
  // After the last transform: no fallback to the latest one (the frame is not static).
  std::string error;
  EXPECT_FALSE(sf_filter::rotateVector(buffer, v, "base_link", "odom", ros::Time(3.0), &error));
  EXPECT_NE(error.find("extrapolation"), std::string::npos) << error;
}

TEST(VectorRotation, TransformMayStillArriveOnlyForAStampAfterTheNewestOne) {
  // The node waits for a transform on an input's first value only while it may still come
  // (frame_aligner.hpp): not for a value stamped before the oldest transform tf holds (the
  // Husky recording's first IMU values, stamped before its first /tf message), for which
  // the wait lasted the whole ~transform_timeout.
  tf2::BufferCore buffer;
  EXPECT_TRUE(sf_filter::transformMayStillArrive(buffer, "base_link", "imu_link", ros::Time(10)));
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "base_link";
  t.child_frame_id = "imu_link";
  t.transform.rotation.w = 1.0;
  for (double stamp : {10.5, 11.0}) {
    t.header.stamp = ros::Time(stamp);
    buffer.setTransform(t, "test", false);
  }
  // before the oldest (10.5): a lookup there fails and no later message will fill it in
  EXPECT_FALSE(sf_filter::rotateVector(buffer, geometry_msgs::Vector3(), "imu_link", "base_link",
                                       ros::Time(10.0)));
  EXPECT_FALSE(sf_filter::transformMayStillArrive(buffer, "base_link", "imu_link", ros::Time(10)));
  // after the newest (11.0): the next message may cover it
  EXPECT_TRUE(sf_filter::transformMayStillArrive(buffer, "base_link", "imu_link", ros::Time(12)));
  // a static chain holds at every time: never waited for
  t.child_frame_id = "gyro_link";
  buffer.setTransform(t, "test", true);
  EXPECT_FALSE(sf_filter::transformMayStillArrive(buffer, "base_link", "gyro_link", ros::Time(12)));
}

TEST(VectorRotation, UnknownOrEmptyFrameFailsWithTheTf2Error) {
  tf2::BufferCore buffer;
  buffer.setTransform(staticTransform("base_link", "imu_link", 0, 0, 0, rpy(0, 0, 0)), "test", true);
  geometry_msgs::Vector3 v;
  std::string error;
  EXPECT_FALSE(sf_filter::rotateVector(buffer, v, "nowhere", "base_link", ros::Time(1.0), &error));
  EXPECT_NE(error.find("nowhere"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(sf_filter::rotateVector(buffer, v, "", "base_link", ros::Time(1.0), &error));
  EXPECT_FALSE(error.empty());
}

// ------------------------------------------------------------------------- the node, under a master
/// The model of test/configs/imu_heading_ekf.h written out independently, with hand-derived
/// Jacobians (the node differentiates automatically).
struct HeadingModel {
  static constexpr int StateSize = 5, MeasurementSize = 3, ControlSize = 1;
  Index stateSize() const { return 5; }
  Index measurementSize() const { return 3; }
  Index controlSize() const { return 1; }
  void transition(const Vector<5>& x, const Vector<1>& u, Vector<5>& next) const {
    next << x(0) + x(4) * std::cos(x(2)) * kPeriod, x(1) + x(4) * std::sin(x(2)) * kPeriod,
        x(2) + x(3) * kPeriod, x(3), u(0);
  }
  void observation(const Vector<5>& x, Vector<3>& z) const { z.setConstant(x(3)); }
  void transitionJacobian(const Vector<5>& x, const Vector<1>&, Matrix<5, 5>& A) const {
    A.setIdentity();
    A(0, 2) = -x(4) * std::sin(x(2)) * kPeriod;
    A(0, 4) = std::cos(x(2)) * kPeriod;
    A(1, 2) = x(4) * std::cos(x(2)) * kPeriod;
    A(1, 4) = std::sin(x(2)) * kPeriod;
    A(2, 3) = kPeriod;
    A(4, 4) = 0.0;
  }
  void observationJacobian(const Vector<5>&, Matrix<3, 5>& H) const {
    H.setZero();
    H.col(3).setOnes();
  }
};
using Reference = estimation::ExtendedKalmanFilter<HeadingModel>;

Reference referenceFilter() {
  Vector<5> q;
  q << 0.001, 0.001, 0.001, 0.1, 0.001;
  Vector<3> r(0.01, 0.01, 0.02);
  return Reference(HeadingModel{}, q.asDiagonal().toDenseMatrix(), r.asDiagonal().toDenseMatrix(),
                   Vector<5>::Zero(), Matrix<5, 5>::Identity());
}

template <class Message>
struct Latest {
  std::optional<Message> message;
  void callback(const typename Message::ConstPtr& m) { message = *m; }
};

class SpatialAlignmentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    clock_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10, true);
    setClock(kStart);
    // imu_link is mounted upside down; gyro_link follows after the first gyro message.
    statics_.sendTransform(
        staticTransform("base_link", "imu_link", 0.1, 0.0, 0.2, tf2::Quaternion(1, 0, 0, 0)));
    imu_ = nh_.advertise<sensor_msgs::Imu>("/imu", 10);
    unmounted_ = nh_.advertise<sensor_msgs::Imu>("/imu_unmounted", 10);
    gyro_ = nh_.advertise<geometry_msgs::Vector3Stamped>("/gyro", 10);
    cmdVel_ = nh_.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
    state_ = nh_.subscribe("/imu_heading/state", 100,
                           &Latest<sf_msgs::StateEstimateStamped>::callback, &stateMsg_);
    odometry_ = nh_.subscribe("/odometry/filtered", 100, &Latest<nav_msgs::Odometry>::callback,
                              &odometryMsg_);
    rosout_ = nh_.subscribe("/rosout", 100, &SpatialAlignmentTest::onLog, this);
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           (imu_.getNumSubscribers() < 1 || unmounted_.getNumSubscribers() < 1 ||
            gyro_.getNumSubscribers() < 1 || cmdVel_.getNumSubscribers() < 1 ||
            state_.getNumPublishers() < 1 || odometry_.getNumPublishers() < 1)) {
      ros::WallDuration(0.05).sleep();
      ros::spinOnce();
    }
    ros::WallDuration(1.0).sleep();  // the node starts its schedule at kStart, gets /tf_static
  }

  void onLog(const rosgraph_msgs::Log::ConstPtr& log) {
    if (log->name == "/imu_heading" && log->level == rosgraph_msgs::Log::WARN) {
      warnings_.push_back(log->msg);
    }
  }

  void setClock(double t) {
    rosgraph_msgs::Clock c;
    c.clock = ros::Time(t);
    clock_.publish(c);
    ros::WallDuration(0.03).sleep();
  }

  /// Spins until the state and the odometry stamped `t` arrived, or times out.
  bool waitForEstimates(double t) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
    auto stampedAt = [t](const auto& latest) {
      return latest.message && std::abs(latest.message->header.stamp.toSec() - t) < 1e-6;
    };
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      if (stampedAt(stateMsg_) && stampedAt(odometryMsg_)) return true;
      ros::WallDuration(0.005).sleep();
    }
    return false;
  }

  /// Spins until one of the node's warnings contains every string of `parts`.
  bool waitForWarning(const std::vector<std::string>& parts) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      for (const auto& w : warnings_) {
        bool all = true;
        for (const auto& p : parts) all = all && w.find(p) != std::string::npos;
        if (all) return true;
      }
      ros::WallDuration(0.01).sleep();
    }
    return false;
  }

  void publishImu(ros::Publisher& pub, const std::string& frame, double stamp, double wx,
                  double wy, double wz) {
    sensor_msgs::Imu m;
    m.header.stamp = ros::Time(stamp);
    m.header.frame_id = frame;
    m.orientation.w = 1.0;
    m.angular_velocity.x = wx;
    m.angular_velocity.y = wy;
    m.angular_velocity.z = wz;
    m.linear_acceleration.z = 9.81;
    pub.publish(m);
  }

  ros::NodeHandle nh_;
  tf2_ros::StaticTransformBroadcaster statics_;
  tf2_ros::Buffer tfBuffer_;
  tf2_ros::TransformListener tfListener_{tfBuffer_};
  ros::Publisher clock_, imu_, unmounted_, gyro_, cmdVel_;
  ros::Subscriber state_, odometry_, rosout_;
  Latest<sf_msgs::StateEstimateStamped> stateMsg_;
  Latest<nav_msgs::Odometry> odometryMsg_;
  std::vector<std::string> warnings_;
};

TEST_F(SpatialAlignmentTest, RotatesGyrosIntoBaseFramePublishesOdometryAndDropsUnknownFrames) {
  Reference reference = referenceFilter();
  constexpr int kPeriods = 30;
  for (int k = 1; k <= kPeriods; ++k) {
    const double begin = kStart + (k - 1) * kPeriod;
    const double end = begin + kPeriod;
    const double stamp = begin + 0.02;
    // Periods 16..22: only the gyro without a transform (and, in period 19, the IMU with an
    // empty frame_id): every value is dropped, the estimate is a time update only.
    const bool unmountedOnly = k >= 16 && k <= 22;
    // True angular velocity in base_link: positive yaw rate, some roll and pitch rate.
    const double wx = 0.03 * std::sin(k), wy = -0.02, wz = 0.4 + 0.1 * std::sin(0.5 * k);
    const double imuYawRate = wz + 0.01 * std::cos(k);    // the sensors' own errors
    const double gyroYawRate = wz - 0.02 * std::sin(2 * k);
    Measurement<3> z = Measurement<3>::missing();

    setClock(stamp);
    geometry_msgs::Twist cmd;
    cmd.linear.x = kSpeed;
    cmdVel_.publish(cmd);
    if (!unmountedOnly) {
      // imu_link = base_link rotated 180 deg about x: (x, y, z) -> (x, -y, -z).
      publishImu(imu_, "imu_link", stamp, wx, -wy, -imuYawRate);
      z.value(0) = imuYawRate;
      z.available(0) = true;
      // gyro_link = base_link rotated -90 deg about y: the gyro reads (z, y, -x) of base_link.
      geometry_msgs::Vector3Stamped g;
      g.header.stamp = ros::Time(stamp);
      g.header.frame_id = "gyro_link";
      g.vector.x = gyroYawRate;
      g.vector.y = wy;
      g.vector.z = -wx;
      gyro_.publish(g);
      z.value(2) = gyroYawRate;
      z.available(2) = true;
      if (k == 1) {
        // gyro_link (x axis along base_link's z axis) arrives while the node waits for it on
        // the first gyro message (~transform_timeout, 1 s): that value is not dropped.
        ros::WallDuration(0.3).sleep();
        statics_.sendTransform(
            staticTransform("base_link", "gyro_link", -0.1, 0.05, 0.3, rpy(0, -M_PI / 2, 0)));
      }
    } else {
      publishImu(unmounted_, "unmounted_link", stamp, wx, wy, wz);
      if (k == 19) publishImu(imu_, "", stamp, wx, -wy, -imuYawRate);
    }
    ros::WallDuration(0.1).sleep();  // let the node receive before the period ends

    setClock(end);
    ASSERT_TRUE(waitForEstimates(end)) << "no estimate for period " << k;
    reference.setControl(Vector<1>(kSpeed));
    reference.estimate(z);
    const Vector<5> x = reference.state();
    const Matrix<5, 5> P = reference.covariance();
    const auto& state = *stateMsg_.message;
    ASSERT_EQ(state.state.size(), 5u);

    // (a) the yaw rates were rotated: positive heading rate and heading, as the reference.
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(state.state[i], x(i), 1e-9) << "x[" << i << "], period " << k;
    EXPECT_GT(state.state[3], 0.1) << "period " << k;
    EXPECT_GT(state.state[2], 0.0) << "period " << k;
    EXPECT_NEAR(state.covariance[3 * 5 + 3], P(3, 3), 1e-9);
    // (d) no value of an unrotatable input reached the filter.
    EXPECT_EQ(state.present_inputs, unmountedOnly ? 0u : 2u) << "period " << k;

    // (b) nav_msgs/Odometry: frames and the pose of the state (POSE_OUT (0)(1)(2)).
    const auto& odom = *odometryMsg_.message;
    EXPECT_EQ(odom.header.frame_id, "odom");
    EXPECT_EQ(odom.child_frame_id, "base_link");
    EXPECT_NEAR(odom.pose.pose.position.x, state.state[0], 1e-12);
    EXPECT_NEAR(odom.pose.pose.position.y, state.state[1], 1e-12);
    EXPECT_NEAR(tf2::getYaw(odom.pose.pose.orientation), state.state[2], 1e-9);
    EXPECT_NEAR(odom.pose.covariance[0], state.covariance[0], 1e-12);
    EXPECT_NEAR(odom.pose.covariance[35], state.covariance[2 * 5 + 2], 1e-12);

    // (c) the broadcast odom -> base_link transform is the same pose.
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           !tfBuffer_.canTransform("odom", "base_link", ros::Time(end))) {
      ros::WallDuration(0.005).sleep();
    }
    geometry_msgs::TransformStamped t;
    ASSERT_NO_THROW(t = tfBuffer_.lookupTransform("odom", "base_link", ros::Time(end)))
        << "period " << k;
    EXPECT_NEAR(t.transform.translation.x, state.state[0], 1e-12);
    EXPECT_NEAR(t.transform.translation.y, state.state[1], 1e-12);
    EXPECT_NEAR(tf2::getYaw(t.transform.rotation), state.state[2], 1e-9);

    if (k == 22) {
      // (d) reported: input, frames and the tf2 error; the node kept running (periods 23..30).
      EXPECT_TRUE(waitForWarning({"input 1", "unmounted_link", "base_link", "dropped"}));
      EXPECT_TRUE(waitForWarning({"input 0", "base_link", "dropped"}));
    }
  }
  // The imu_link mount turned a negative raw reading into a positive yaw rate.
  EXPECT_GT(stateMsg_.message->state[3], 0.3);
  // The robot drove counter-clockwise: left of its start.
  EXPECT_GT(stateMsg_.message->state[1], 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sf_spatial_alignment_test");
  return RUN_ALL_TESTS();
}
