// Reference for measure_node_overhead.sh --node sf_ros_floor_node: the ROS side of the nav3ctrl
// fusion node without FusionCore and without an estimator. Same subscriptions (queue 100),
// same callback pattern (ros::Time::now() and reading the used fields), same 100 ms
// ros::Timer and the same publications per period (5 x sf_msgs/OutputEntityStamped on
// pose/x, pose/y, pose/theta, velocity/linear, velocity/angular; ~state
// sf_msgs/StateEstimateStamped with 7 states and a 7x7 covariance; odometry/filtered; one tf),
// with constant values. Its CPU use is what roscpp costs for this traffic, so
// (fusion node CPU) - (this node's CPU) is what the fusion node's own code adds.
#include <array>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/Float32.h>
#include <tf2_ros/transform_broadcaster.h>

#include <sf_msgs/OutputEntityStamped.h>
#include <sf_msgs/StateEstimateStamped.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "sf_ros_floor_node");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");

  std::array<double, 4> sum{};  // stands in for the core's period averages
  std::array<double, 2> control{};
  double lastNow = 0.0;
  auto vectorCallback = [&](int input) {
    return [&, input](const geometry_msgs::Vector3Stamped::ConstPtr& m) {
      lastNow = ros::Time::now().toSec();
      sum[static_cast<std::size_t>(input)] +=
          (input == 0 ? m->vector.z : m->vector.y) + 0.0 * m->header.stamp.toSec();
    };
  };
  auto floatCallback = [&](int input) {
    return [&, input](const std_msgs::Float32::ConstPtr& m) {
      lastNow = ros::Time::now().toSec();
      sum[static_cast<std::size_t>(input)] += m->data;
    };
  };
  std::vector<ros::Subscriber> subscribers;
  subscribers.push_back(
      nh.subscribe<geometry_msgs::Vector3Stamped>("angular_velocity", 100, vectorCallback(0)));
  subscribers.push_back(
      nh.subscribe<geometry_msgs::Vector3Stamped>("acceleration", 100, vectorCallback(1)));
  subscribers.push_back(
      nh.subscribe<std_msgs::Float32>("velocity_wheel_left", 100, floatCallback(2)));
  subscribers.push_back(
      nh.subscribe<std_msgs::Float32>("velocity_wheel_right", 100, floatCallback(3)));
  subscribers.push_back(nh.subscribe<geometry_msgs::Twist>(
      "cmd_vel", 100, [&](const geometry_msgs::Twist::ConstPtr& m) {
        lastNow = ros::Time::now().toSec();
        control = {m->linear.x, m->angular.z};
      }));

  std::vector<ros::Publisher> outputs;
  for (const char* topic :
       {"pose/x", "pose/y", "pose/theta", "velocity/linear", "velocity/angular"}) {
    outputs.push_back(nh.advertise<sf_msgs::OutputEntityStamped>(topic, 10));
  }
  ros::Publisher state = pnh.advertise<sf_msgs::StateEstimateStamped>("state", 10);
  ros::Publisher odometry = nh.advertise<nav_msgs::Odometry>("odometry/filtered", 10);
  tf2_ros::TransformBroadcaster broadcaster;

  // Period ends on a fixed grid, like FusionCore's schedule; the stamp is the period end.
  const double period = 0.1;
  ros::Time::waitForValid();
  const double start = ros::Time::now().toSec();
  std::uint64_t index = 1;
  auto tick = [&](const ros::TimerEvent&) {
    const double now = ros::Time::now().toSec();
    while (now + 1e-6 >= start + static_cast<double>(index) * period) {
      const ros::Time stamp(start + static_cast<double>(index) * period);
      ++index;
      for (auto& p : outputs) {
        sf_msgs::OutputEntityStamped msg;
        msg.header.stamp = stamp;
        msg.header.frame_id = "odom";
        msg.value = sum[0];
        msg.variance = 1.0;
        p.publish(msg);
      }
      sf_msgs::StateEstimateStamped s;
      s.header.stamp = stamp;
      s.header.frame_id = "odom";
      s.method = "UnscentedKalmanFilter";
      s.state.assign(7, control[0]);
      s.covariance.assign(49, 0.0);
      s.present_inputs = 4;
      state.publish(s);
      nav_msgs::Odometry odom;
      odom.header.stamp = stamp;
      odom.header.frame_id = "odom";
      odom.child_frame_id = "base_link";
      odom.pose.pose.orientation.w = 1.0;
      odometry.publish(odom);
      geometry_msgs::TransformStamped t;
      t.header = odom.header;
      t.child_frame_id = "base_link";
      t.transform.rotation.w = 1.0;
      broadcaster.sendTransform(t);
      sum = {};
    }
  };
  ros::Timer timer = nh.createTimer(ros::Duration(period), tick);
  ros::spin();
  static_cast<void>(lastNow);
  return 0;
}
