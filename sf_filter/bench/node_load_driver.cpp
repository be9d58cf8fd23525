// Load driver for the end-to-end overhead measurement of a fusion node (see
// measure_node_overhead.sh and doc/node_benchmarks.md, "Fusion node"). Publishes the inputs
// of the nav3ctrl nodes in wall time
//   angular_velocity, acceleration  geometry_msgs/Vector3Stamped  100 Hz
//   velocity_wheel_left/right       std_msgs/Float32               10 Hz
//   cmd_vel                         geometry_msgs/Twist            10 Hz
// from one thread sleeping to absolute 10 ms ticks, and subscribes to the node's output. For
// every output received inside the measurement window it records the publication delay
//   receive wall time - header.stamp     (header.stamp = the end of the estimated period)
// which includes the node's wake-up, estimate, serialisation, the loopback TCP transport and
// this process's own wake-up. With ~node_pid it also reads the node's CPU time at the window
// start and end: utime + stime of /proc/<pid>/stat (all threads, clock ticks) and the sum of
// /proc/<pid>/task/*/schedstat (ns on CPU of the live threads).
//
// Private parameters:
//   ~duration      measurement window [s] (60)
//   ~warmup        publishing before the window starts [s] (5)
//   ~output_topic  sf_msgs/OutputEntityStamped output (/pose/x)
//   ~state_topic   sf_msgs/StateEstimateStamped output, "" for none (/sf_nav3ctrl_ukf/state)
//   ~node_pid      pid of the fusion node, 0 for no CPU reading (0)
//   ~period        estimation period of the node [s] (0.1), for the per-period figures
//   ~tcp_nodelay   subscribe to the outputs with TCP_NODELAY (false, as most subscribers do)
//   ~report        file to write the results to as key=value lines ("" for none)
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <ros/ros.h>
#include <std_msgs/Float32.h>

#include <sf_msgs/OutputEntityStamped.h>
#include <sf_msgs/StateEstimateStamped.h>

#include "process_stats.hpp"
#include "tick_clock.hpp"

namespace {

using sf_bench::CpuSample;
using sf_bench::readCpu;

double monotonicNow() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Delays of one output topic inside the window [start, end) of header stamps (wall time).
class DelayRecorder {
 public:
  explicit DelayRecorder(std::string name) : name_(std::move(name)) { delays_.reserve(100000); }

  void setWindow(double start, double end) {
    std::lock_guard<std::mutex> lock(mutex_);
    start_ = start;
    end_ = end;
  }

  void record(const ros::Time& stamp) {
    const double received = ros::WallTime::now().toSec();
    const double s = stamp.toSec();
    std::lock_guard<std::mutex> lock(mutex_);
    if (s < start_ || s >= end_) return;
    delays_.push_back(received - s);
    if (last_ > 0.0 && s - last_ > 1.5 * period_)
      gaps_ += static_cast<std::uint64_t>(std::lround((s - last_) / period_)) - 1;
    last_ = s;
  }

  void setPeriod(double p) { period_ = p; }

  void report(std::ostream& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<double> d = delays_;
    std::sort(d.begin(), d.end());
    out << name_ << ".count=" << d.size() << "\n";
    out << name_ << ".missed_periods=" << gaps_ << "\n";
    if (d.empty()) return;
    double sum = 0.0;
    for (double x : d) sum += x;
    auto at = [&](double q) {
      const std::size_t i =
          std::min(d.size() - 1, static_cast<std::size_t>(q * static_cast<double>(d.size())));
      return d[i] * 1e6;
    };
    out << name_ << ".delay_mean_us=" << sum / static_cast<double>(d.size()) * 1e6 << "\n";
    out << name_ << ".delay_min_us=" << d.front() * 1e6 << "\n";
    out << name_ << ".delay_median_us=" << at(0.5) << "\n";
    out << name_ << ".delay_p90_us=" << at(0.9) << "\n";
    out << name_ << ".delay_p99_us=" << at(0.99) << "\n";
    out << name_ << ".delay_max_us=" << d.back() * 1e6 << "\n";
  }

 private:
  std::string name_;
  std::mutex mutex_;
  std::vector<double> delays_;
  double start_ = 0.0, end_ = 0.0, last_ = 0.0, period_ = 0.1;
  std::uint64_t gaps_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sf_node_load_driver");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double duration = 60.0, warmup = 5.0, period = 0.1;
  int nodePid = 0;
  bool tcpNoDelay = false;
  std::string outputTopic, stateTopic, reportPath;
  pnh.param("duration", duration, 60.0);
  pnh.param("warmup", warmup, 5.0);
  pnh.param("period", period, 0.1);
  pnh.param("node_pid", nodePid, 0);
  pnh.param("tcp_nodelay", tcpNoDelay, false);
  pnh.param<std::string>("output_topic", outputTopic, "/pose/x");
  pnh.param<std::string>("state_topic", stateTopic, "/sf_nav3ctrl_ukf/state");
  pnh.param<std::string>("report", reportPath, "");

  auto gyro = nh.advertise<geometry_msgs::Vector3Stamped>("angular_velocity", 100);
  auto accel = nh.advertise<geometry_msgs::Vector3Stamped>("acceleration", 100);
  auto left = nh.advertise<std_msgs::Float32>("velocity_wheel_left", 10);
  auto right = nh.advertise<std_msgs::Float32>("velocity_wheel_right", 10);
  auto cmdVel = nh.advertise<geometry_msgs::Twist>("cmd_vel", 10);

  ros::TransportHints hints;
  if (tcpNoDelay) hints = hints.tcpNoDelay();
  DelayRecorder outputDelays("output"), stateDelays("state");
  outputDelays.setPeriod(period);
  stateDelays.setPeriod(period);
  auto outputSub = nh.subscribe<sf_msgs::OutputEntityStamped>(
      outputTopic, 100,
      [&](const sf_msgs::OutputEntityStamped::ConstPtr& m) {
        outputDelays.record(m->header.stamp);
      },
      ros::VoidConstPtr(), hints);
  ros::Subscriber stateSub;
  if (!stateTopic.empty()) {
    stateSub = nh.subscribe<sf_msgs::StateEstimateStamped>(
        stateTopic, 100,
        [&](const sf_msgs::StateEstimateStamped::ConstPtr& m) {
          stateDelays.record(m->header.stamp);
        },
        ros::VoidConstPtr(), hints);
  }
  ros::AsyncSpinner spinner(1);  // receive callbacks while the main thread publishes
  spinner.start();

  // Wait until the node is connected both ways.
  const double connectDeadline = monotonicNow() + 30.0;
  while (ros::ok() && (gyro.getNumSubscribers() == 0 || accel.getNumSubscribers() == 0 ||
                       left.getNumSubscribers() == 0 || right.getNumSubscribers() == 0 ||
                       cmdVel.getNumSubscribers() == 0 || outputSub.getNumPublishers() == 0 ||
                       (!stateTopic.empty() && stateSub.getNumPublishers() == 0))) {
    if (monotonicNow() > connectDeadline) {
      ROS_FATAL("the fusion node did not connect within 30 s");
      return 1;
    }
    ros::WallDuration(0.05).sleep();
  }

  const double wallStart = ros::WallTime::now().toSec();
  outputDelays.setWindow(wallStart + warmup, wallStart + warmup + duration);
  stateDelays.setWindow(wallStart + warmup, wallStart + warmup + duration);
  ROS_INFO("connected; publishing for %.0f s warm-up + %.0f s measurement", warmup, duration);

  // Publishing loop: 10 ms ticks on CLOCK_MONOTONIC (absolute, so no drift).
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  const double tick = 0.01;
  const std::uint64_t warmupTicks = static_cast<std::uint64_t>(std::llround(warmup / tick));
  const std::uint64_t totalTicks =
      warmupTicks + static_cast<std::uint64_t>(std::llround(duration / tick));
  CpuSample cpuStart, cpuEnd;
  double windowStartMono = 0.0, windowEndMono = 0.0;
  double lateSum = 0.0, lateMax = 0.0;
  std::uint64_t published = 0;
  for (std::uint64_t k = 0; k <= totalTicks && ros::ok(); ++k) {
    sf_bench::sleepToNextTick(next, 10000000);
    const double late = monotonicNow() - (static_cast<double>(next.tv_sec) +
                                          1e-9 * static_cast<double>(next.tv_nsec));
    if (k == warmupTicks) {
      windowStartMono = monotonicNow();
      if (nodePid > 0) cpuStart = readCpu(nodePid);
    }
    if (k == totalTicks) {
      windowEndMono = monotonicNow();
      if (nodePid > 0) cpuEnd = readCpu(nodePid);
      break;
    }
    if (k >= warmupTicks) {
      lateSum += late;
      lateMax = std::max(lateMax, late);
    }

    // A robot driving a smooth curve (nav3ctrl quantities), values are not what is measured.
    const ros::Time stamp = ros::Time::now();
    const double t = static_cast<double>(k) * tick;
    const double v = 0.6 + 0.4 * std::sin(0.15 * t), dv = 0.06 * std::cos(0.15 * t);
    const double omega = 0.5 * std::sin(0.4 * t);
    geometry_msgs::Vector3Stamped g;
    g.header.stamp = stamp;
    g.header.frame_id = "base_link";
    g.vector.z = omega;
    gyro.publish(g);
    geometry_msgs::Vector3Stamped a;
    a.header = g.header;
    a.vector.y = dv;
    accel.publish(a);
    published += 2;
    if (k % 10 == 2) {
      geometry_msgs::Twist u;
      u.linear.x = v;
      u.angular.z = omega;
      cmdVel.publish(u);
      ++published;
    }
    if (k % 10 == 5) {
      std_msgs::Float32 l, r;
      l.data = static_cast<float>((v - omega * 0.3) * 1000.0);
      r.data = static_cast<float>((v + omega * 0.3) * 1000.0);
      left.publish(l);
      right.publish(r);
      published += 2;
    }
  }
  ros::WallDuration(0.5).sleep();  // the last period's outputs
  spinner.stop();

  std::ostringstream out;
  const double window = windowEndMono - windowStartMono;
  out << "window_s=" << window << "\n";
  out << "published_msgs=" << published << "\n";
  out << "driver_tick_late_mean_us=" << lateSum / std::max(1.0, window / tick) * 1e6 << "\n";
  out << "driver_tick_late_max_us=" << lateMax * 1e6 << "\n";
  outputDelays.report(out);
  if (!stateTopic.empty()) stateDelays.report(out);
  if (nodePid > 0 && cpuStart.ok && cpuEnd.ok && window > 0.0) {
    const double periods = window / period;
    const double stat = cpuEnd.statSeconds - cpuStart.statSeconds;
    const double sched = (cpuEnd.schedNs - cpuStart.schedNs) * 1e-9;
    out << "node_threads=" << cpuEnd.threads << "\n";
    out << "node_cpu_stat_s=" << stat << "\n";
    out << "node_cpu_stat_percent=" << 100.0 * stat / window << "\n";
    out << "node_cpu_stat_us_per_period=" << stat / periods * 1e6 << "\n";
    out << "node_cpu_sched_s=" << sched << "\n";
    out << "node_cpu_sched_percent=" << 100.0 * sched / window << "\n";
    out << "node_cpu_sched_us_per_period=" << sched / periods * 1e6 << "\n";
  } else if (nodePid > 0) {
    out << "node_cpu_error=could not read /proc/" << nodePid << "\n";
  }
  std::fputs(out.str().c_str(), stdout);
  if (!reportPath.empty()) std::ofstream(reportPath) << out.str();
  return 0;
}
