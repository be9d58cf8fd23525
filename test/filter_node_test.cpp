// Integration test of a generated fusion node (config/train_kf.h) under a ROS master. The
// test owns /clock: per period it publishes a speedometer at twice the estimation rate, an
// accelerometer at a third of it and a command, then moves the clock to the period's end and
// compares the published estimate with the library's Kalman filter stepped offline on the
// same aligned data (the mean of the period's values, missing when none arrived). A second
// node has R overridden, a third the alignment policies (~input_alignment): the newest speed
// of the period, and the accelerometer held (zero-order hold, variance 0.5) while it is silent.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include <geometry_msgs/Vector3Stamped.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>

#include <sf_estimation/kalman_filter.hpp>
#include <sf_msgs/OutputEntityStamped.h>
#include <sf_msgs/StateEstimateStamped.h>

namespace {

using estimation::Matrix;
using estimation::Measurement;
using estimation::Vector;
using Train = estimation::KalmanFilter<2, 2, 1>;

constexpr double kPeriod = 0.1;
constexpr double kStart = 1.0;

// The model and noise of config/train_kf.h, written out independently.
Train referenceFilter(double speedVariance) {
  Matrix<2, 2> A;
  A << 1, kPeriod, 0, 0;
  const Matrix<2, 1> B(0, 1);
  Matrix<2, 2> Q, R;
  Q << 0.001, 0, 0, 0.01;
  R << speedVariance, 0, 0, 0.04;
  return Train(A, B, Matrix<2, 2>::Identity(), Q, R, Vector<2>::Zero(),
               Matrix<2, 2>::Identity());
}

template <class Message>
struct Latest {
  std::optional<Message> message;
  void callback(const typename Message::ConstPtr& m) { message = *m; }
};

class FilterNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    clock_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10, true);
    velocity_ = nh_.advertise<std_msgs::Float64>("/train/velocity", 10);
    acceleration_ = nh_.advertise<geometry_msgs::Vector3Stamped>("/train/acceleration", 10);
    command_ = nh_.advertise<std_msgs::Float64>("/train/command", 10);
    setClock(kStart);
    estimate_ = nh_.subscribe("/train/estimate/velocity", 100,
                              &Latest<sf_msgs::OutputEntityStamped>::callback, &speed_);
    override_ = nh_.subscribe("/override/train/estimate/velocity", 100,
                              &Latest<sf_msgs::OutputEntityStamped>::callback, &overrideSpeed_);
    policies_ = nh_.subscribe("/policies/train/estimate/velocity", 100,
                              &Latest<sf_msgs::OutputEntityStamped>::callback, &policiesSpeed_);
    state_ = nh_.subscribe("/train_kf/state", 100,
                           &Latest<sf_msgs::StateEstimateStamped>::callback, &state_msg_);
    // Wait until both nodes are connected to every topic of the test.
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30.0);
    while (ros::ok() && ros::WallTime::now() < deadline &&
           (velocity_.getNumSubscribers() < 3 || acceleration_.getNumSubscribers() < 3 ||
            command_.getNumSubscribers() < 3 || estimate_.getNumPublishers() < 1 ||
            override_.getNumPublishers() < 1 || policies_.getNumPublishers() < 1 ||
            state_.getNumPublishers() < 1)) {
      ros::WallDuration(0.05).sleep();
      ros::spinOnce();
    }
    ros::WallDuration(1.0).sleep();  // the nodes start their schedule at kStart
  }

  void setClock(double t) {
    rosgraph_msgs::Clock c;
    c.clock = ros::Time(t);
    clock_.publish(c);
    ros::WallDuration(0.03).sleep();
  }

  /// Spins until a message stamped `t` arrived on every output, or times out.
  bool waitForEstimates(double t) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(5.0);
    auto stampedAt = [t](const auto& latest) {
      return latest.message && std::abs(latest.message->header.stamp.toSec() - t) < 1e-6;
    };
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      if (stampedAt(speed_) && stampedAt(overrideSpeed_) && stampedAt(policiesSpeed_) &&
          stampedAt(state_msg_)) {
        return true;
      }
      ros::WallDuration(0.005).sleep();
    }
    return false;
  }

  ros::NodeHandle nh_;
  ros::Publisher clock_, velocity_, acceleration_, command_;
  ros::Subscriber estimate_, override_, policies_, state_;
  Latest<sf_msgs::OutputEntityStamped> speed_, overrideSpeed_, policiesSpeed_;
  Latest<sf_msgs::StateEstimateStamped> state_msg_;
};

TEST_F(FilterNodeTest, EstimatesMatchTheLibraryOnTheAlignedInputs) {
  Train reference = referenceFilter(0.25);
  Train overridden = referenceFilter(1.0);  // ~measurement_noise_covariance set at launch
  Train policies = referenceFilter(0.25);   // ~input_alignment set at launch
  std::optional<double> heldAcceleration;
  constexpr int kPeriods = 30;
  for (int k = 1; k <= kPeriods; ++k) {
    const double begin = kStart + (k - 1) * kPeriod;
    const double trueAcceleration = 0.5 * std::sin(0.3 * k);
    const double command = trueAcceleration;
    Measurement<2> z, newest;
    z.available.setConstant(false);

    setClock(begin + 0.02);
    // Speedometer at 20 Hz: two values per period, averaged by the node.
    const double v1 = 0.1 * k + 0.05 * std::cos(1.7 * k), v2 = 0.1 * k - 0.03 * std::sin(k);
    for (double v : {v1, v2}) {
      std_msgs::Float64 m;
      m.data = v;
      velocity_.publish(m);
    }
    z.value(0) = 0.5 * (v1 + v2);
    z.available(0) = true;
    newest = z;
    newest.value(0) = v2;
    // Accelerometer at 3.3 Hz: missing in two periods out of three.
    if (k % 3 == 0) {
      geometry_msgs::Vector3Stamped a;
      a.header.stamp = ros::Time(begin + 0.02);
      a.vector.x = trueAcceleration + 0.01;
      acceleration_.publish(a);
      z.value(1) = a.vector.x;
      z.available(1) = true;
      newest.value(1) = a.vector.x;
      newest.available(1) = true;
      heldAcceleration = a.vector.x;
    } else if (heldAcceleration) {
      newest.value(1) = *heldAcceleration;
      newest.available(1) = true;
      newest.varianceGiven(1) = true;
      newest.variance(1) = 0.5;
    }
    std_msgs::Float64 u;
    u.data = command;
    command_.publish(u);
    ros::WallDuration(0.1).sleep();  // let the nodes receive before the period ends

    setClock(begin + kPeriod);
    ASSERT_TRUE(waitForEstimates(begin + kPeriod)) << "no estimate for period " << k;

    reference.setControl(Vector<1>(command));
    reference.estimate(z);
    overridden.setControl(Vector<1>(command));
    overridden.estimate(z);
    policies.setControl(Vector<1>(command));
    policies.estimate(newest);
    EXPECT_NEAR(speed_.message->value, reference.state()(0), 1e-9) << "period " << k;
    EXPECT_NEAR(speed_.message->variance, reference.covariance()(0, 0), 1e-9);
    EXPECT_NEAR(overrideSpeed_.message->value, overridden.state()(0), 1e-9) << "period " << k;
    EXPECT_NEAR(overrideSpeed_.message->variance, overridden.covariance()(0, 0), 1e-9);
    EXPECT_NEAR(policiesSpeed_.message->value, policies.state()(0), 1e-9) << "period " << k;
    EXPECT_NEAR(policiesSpeed_.message->variance, policies.covariance()(0, 0), 1e-9);
    ASSERT_EQ(state_msg_.message->state.size(), 2u);
    ASSERT_EQ(state_msg_.message->covariance.size(), 4u);
    EXPECT_NEAR(state_msg_.message->state[1], reference.state()(1), 1e-9);
    EXPECT_NEAR(state_msg_.message->covariance[1], reference.covariance()(0, 1), 1e-9);
    EXPECT_EQ(state_msg_.message->present_inputs, k % 3 == 0 ? 2u : 1u);
    EXPECT_EQ(state_msg_.message->method, "KALMAN_FILTER");
  }
  // The override changed the estimate: a larger R(0,0) trusts the speedometer less.
  EXPECT_GT(overridden.covariance()(0, 0), reference.covariance()(0, 0));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sf_filter_node_test");
  return RUN_ALL_TESTS();
}
