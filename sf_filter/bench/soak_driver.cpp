// Load / soak driver for a fusion node built from test/configs/soak_four_inputs_kf.h (see
// soak_node.sh and doc/reliability.md). It owns the simulated clock: per step of 1/input_rate
// it publishes /clock, then one message on each of the four input topics stamped with that
// time, and the command at control_rate. It runs as fast as the node keeps up: after the
// /clock that closes a period it waits until the node's estimate of the period `window`
// periods back has arrived, so that no more than about (window + 1) * period * input_rate
// messages per topic are in flight (well under the node's subscriber queue of 100) and the
// node never drops a message for being slow. Measured:
//   - messages published per topic (the node logs what it received at shutdown),
//   - the node's estimates (~state): their stamps' spacing against the period (missed,
//     repeated or irregular periods) and the wall time from the /clock that closes a period
//     to the arrival of its estimate,
//   - the node's CPU time over the run (/proc/<pid>/stat utime + stime) and its resident
//     memory (/proc/<pid>/status VmRSS) sampled every rss_interval wall seconds.
//
// Private parameters:
//   ~sim_duration  simulated time to publish [s] (600)
//   ~warmup        simulated time before the memory baseline is taken [s] (10% of sim_duration)
//   ~input_rate    rate of each input topic [Hz] (1000)
//   ~control_rate  rate of the command [Hz] (100)
//   ~period        the node's estimation period [s] (0.01)
//   ~window        periods the node may lag behind the clock (1; at 4 the node lost 0.08 %
//                  of the stamped inputs, doc/reliability.md)
//   ~start_time    first simulated time [s] (1000)
//   ~node_pid      pid of the fusion node, 0 for no CPU and memory readings (0)
//   ~rss_interval  wall seconds between memory samples (0.5)
//   ~state_topic   the node's sf_msgs/StateEstimateStamped (/sf_test_soak/state)
//   ~report        file to write the results to as key=value lines ("" for none)
//   ~rss_csv       file for the memory samples: wall_s,sim_s,vmrss_kib ("" for none)
//   ~wall_clock    publish in wall time at the input rate instead (false): no /clock, no
//                  waiting for the node; sim_duration is then wall seconds, and the spacing
//                  of the estimates' arrivals against the period is the node timer's jitter
#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>

#include <sf_msgs/StateEstimateStamped.h>

#include "process_stats.hpp"
#include "tick_clock.hpp"

namespace {

double wallNow() { return ros::WallTime::now().toSec(); }

/// Quantile q of sorted values.
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto i =
      std::min(sorted.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sorted.size())));
  return sorted[i];
}

/// The node's estimates: period indices from their stamps, spacing, and the wall delay from
/// the /clock that closed each period. In wall-clock mode the grid starts at the first
/// estimate, the delay is arrival - stamp, and the arrival spacing is the timer's jitter.
class EstimateRecorder {
 public:
  EstimateRecorder(double start, double period, std::size_t periods, bool wallClock)
      : start_(start), period_(period), wallClock_(wallClock), closedAt_(periods + 2, 0.0) {
    delays_.reserve(periods + 2);
    arrivals_.reserve(periods + 2);
  }

  void closed(std::int64_t index, double wall) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (index >= 0 && static_cast<std::size_t>(index) < closedAt_.size()) {
      closedAt_[static_cast<std::size_t>(index)] = wall;
    }
  }

  void record(const ros::Time& stamp) {
    const double wall = wallNow();
    const double s = stamp.toSec();
    if (wallClock_ && count_ == 0) start_ = s;
    const auto index = static_cast<std::int64_t>(std::llround((s - start_) / period_));
    std::lock_guard<std::mutex> lock(mutex_);
    ++count_;
    if (std::abs(s - (start_ + static_cast<double>(index) * period_)) > 1e-6) ++offGrid_;
    if (last_ >= 0) {
      const std::int64_t step = index - last_;
      if (step <= 0) {
        ++repeated_;
      } else if (step > 1) {
        missed_ += static_cast<std::uint64_t>(step - 1);
      }
      const double spacing = s - lastStamp_;
      maxSpacingError_ = std::max(maxSpacingError_, std::abs(spacing - period_));
    }
    last_ = std::max(last_, index);
    lastStamp_ = s;
    if (wallClock_) {
      delays_.push_back(wall - s);
      arrivals_.push_back(wall);
    } else if (index >= 0 && static_cast<std::size_t>(index) < closedAt_.size() &&
               closedAt_[static_cast<std::size_t>(index)] > 0.0) {
      delays_.push_back(wall - closedAt_[static_cast<std::size_t>(index)]);
    }
    changed_.notify_all();
  }

  /// Waits until the estimate of period `index` (or a later one) arrived; false on timeout.
  bool waitFor(std::int64_t index, double timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::duration<double>(timeout), [&] {
      return last_ >= index || !ros::ok();
    }) && last_ >= index;
  }

  void report(std::ostream& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<double> d = delays_;
    std::sort(d.begin(), d.end());
    out << "estimates=" << count_ << "\n";
    out << "estimates_missed_periods=" << missed_ << "\n";
    out << "estimates_repeated_or_backwards=" << repeated_ << "\n";
    out << "estimates_off_grid=" << offGrid_ << "\n";
    out << "estimate_spacing_max_error_us=" << maxSpacingError_ * 1e6 << "\n";
    out << "estimate_delay_count=" << d.size() << "\n";
    if (d.empty()) return;
    double sum = 0.0;
    for (double x : d) sum += x;
    out << "estimate_delay_mean_us=" << sum / static_cast<double>(d.size()) * 1e6 << "\n";
    out << "estimate_delay_median_us=" << quantile(d, 0.5) * 1e6 << "\n";
    out << "estimate_delay_p99_us=" << quantile(d, 0.99) * 1e6 << "\n";
    out << "estimate_delay_max_us=" << d.back() * 1e6 << "\n";
    if (arrivals_.size() < 2) return;
    std::vector<double> jitter;  // |arrival spacing - period|
    for (std::size_t i = 1; i < arrivals_.size(); ++i) {
      jitter.push_back(std::abs(arrivals_[i] - arrivals_[i - 1] - period_));
    }
    std::sort(jitter.begin(), jitter.end());
    out << "arrival_jitter_median_us=" << quantile(jitter, 0.5) * 1e6 << "\n";
    out << "arrival_jitter_p99_us=" << quantile(jitter, 0.99) * 1e6 << "\n";
    out << "arrival_jitter_max_us=" << jitter.back() * 1e6 << "\n";
  }

 private:
  double start_, period_;
  bool wallClock_;
  std::vector<double> closedAt_, delays_, arrivals_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::int64_t last_ = -1;
  double lastStamp_ = 0.0, maxSpacingError_ = 0.0;
  std::uint64_t count_ = 0, missed_ = 0, repeated_ = 0, offGrid_ = 0;
};

/// VmRSS samples of the node.
struct MemorySamples {
  struct Sample {
    double wall, sim;
    long kib;
  };
  std::vector<Sample> samples;

  void report(std::ostream& out, double warmupEnd) const {
    if (samples.empty()) return;
    long baseline = -1, peak = 0, peakAfter = 0;
    for (const Sample& s : samples) {
      peak = std::max(peak, s.kib);
      if (s.sim >= warmupEnd) {
        if (baseline < 0) baseline = s.kib;
        peakAfter = std::max(peakAfter, s.kib);
      }
    }
    out << "rss_samples=" << samples.size() << "\n";
    out << "rss_first_kib=" << samples.front().kib << "\n";
    out << "rss_after_warmup_kib=" << baseline << "\n";
    out << "rss_last_kib=" << samples.back().kib << "\n";
    out << "rss_max_kib=" << peak << "\n";
    if (baseline >= 0) {
      out << "rss_growth_after_warmup_kib=" << samples.back().kib - baseline << "\n";
      out << "rss_max_above_warmup_kib=" << peakAfter - baseline << "\n";
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sf_soak_driver");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double simDuration = 600.0, inputRate = 1000.0, controlRate = 100.0, period = 0.01;
  double startTime = 1000.0, rssInterval = 0.5;
  int window = 1, nodePid = 0;
  std::string stateTopic, reportPath, rssCsv;
  pnh.param("sim_duration", simDuration, 600.0);
  const double warmup = pnh.param("warmup", 0.1 * simDuration);
  pnh.param("input_rate", inputRate, 1000.0);
  pnh.param("control_rate", controlRate, 100.0);
  pnh.param("period", period, 0.01);
  pnh.param("window", window, 1);
  pnh.param("start_time", startTime, 1000.0);
  pnh.param("node_pid", nodePid, 0);
  pnh.param("rss_interval", rssInterval, 0.5);
  pnh.param<std::string>("state_topic", stateTopic, "/sf_test_soak/state");
  pnh.param<std::string>("report", reportPath, "");
  pnh.param<std::string>("rss_csv", rssCsv, "");
  bool wallClock = false;
  pnh.param("wall_clock", wallClock, false);
  const auto stepsPerPeriod = static_cast<std::int64_t>(std::llround(period * inputRate));
  const auto stepsPerControl = static_cast<std::int64_t>(std::llround(inputRate / controlRate));
  const auto steps = static_cast<std::int64_t>(std::llround(simDuration * inputRate));
  if (stepsPerPeriod < 1 || stepsPerControl < 1 || steps < stepsPerPeriod || window < 1) {
    ROS_FATAL("bad parameters: the period and the control period must be whole input steps");
    return 2;
  }
  const std::size_t periods = static_cast<std::size_t>(steps / stepsPerPeriod);

  auto clock = nh.advertise<rosgraph_msgs::Clock>("/clock", 1000);
  auto positionA = nh.advertise<geometry_msgs::PointStamped>("soak/position_a", 1000);
  auto positionB = nh.advertise<std_msgs::Float64>("soak/position_b", 1000);
  auto velocityA = nh.advertise<geometry_msgs::Vector3Stamped>("soak/velocity_a", 1000);
  auto velocityB = nh.advertise<std_msgs::Float64>("soak/velocity_b", 1000);
  auto command = nh.advertise<std_msgs::Float64>("soak/command", 1000);
  EstimateRecorder estimates(startTime, period, periods, wallClock);
  auto stateSub = nh.subscribe<sf_msgs::StateEstimateStamped>(
      stateTopic, 1000,
      [&](const sf_msgs::StateEstimateStamped::ConstPtr& m) { estimates.record(m->header.stamp); });
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // The node's schedule starts at the first /clock it sees: publish the start until it has
  // connected everything, then give it a moment to start.
  const double connectDeadline = wallNow() + 30.0;
  rosgraph_msgs::Clock tick;
  tick.clock = ros::Time(startTime);
  while (ros::ok() && ((!wallClock && clock.getNumSubscribers() == 0) ||
                       positionA.getNumSubscribers() == 0 || positionB.getNumSubscribers() == 0 ||
                       velocityA.getNumSubscribers() == 0 || velocityB.getNumSubscribers() == 0 ||
                       command.getNumSubscribers() == 0 || stateSub.getNumPublishers() == 0)) {
    if (wallNow() > connectDeadline) {
      ROS_FATAL("the fusion node did not connect within 30 s");
      return 1;
    }
    if (!wallClock) clock.publish(tick);
    ros::WallDuration(0.05).sleep();
  }
  if (!wallClock) clock.publish(tick);
  ros::WallDuration(1.0).sleep();

  MemorySamples memory;
  const double wallStart = wallNow();
  double nextSample = wallStart;
  auto sampleMemory = [&](double sim) {
    if (nodePid <= 0) return;
    const long kib = sf_bench::readStatusKiB(nodePid, "VmRSS");
    if (kib >= 0) memory.samples.push_back({wallNow() - wallStart, sim - startTime, kib});
  };
  const sf_bench::CpuSample cpuStart =
      nodePid > 0 ? sf_bench::readCpu(nodePid) : sf_bench::CpuSample{};
  std::uint64_t published[5] = {0, 0, 0, 0, 0}, clocks = 0;
  bool stalled = false;
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  if (wallClock) startTime = ros::Time::now().toSec();
  for (std::int64_t k = 1; k <= steps && ros::ok(); ++k) {
    if (wallClock) sf_bench::sleepToNextTick(next, std::lround(1e9 / inputRate));
    const double t =
        wallClock ? ros::Time::now().toSec() : startTime + static_cast<double>(k) / inputRate;
    const ros::Time stamp(t);
    if (!wallClock) {
      tick.clock = stamp;
      clock.publish(tick);
      ++clocks;
    }
    if (!wallClock && k % stepsPerPeriod == 0) {
      const std::int64_t closedPeriod = k / stepsPerPeriod;
      estimates.closed(closedPeriod, wallNow());
      if (!estimates.waitFor(closedPeriod - window, 10.0)) {
        ROS_FATAL("no estimate of period %lld within 10 s: the node stalled",
                  static_cast<long long>(closedPeriod - window));
        stalled = true;
        break;
      }
    }
    // A cart accelerating back and forth; the values are not what is measured.
    const double s = t - startTime;
    const double position = std::sin(0.5 * s), velocity = 0.5 * std::cos(0.5 * s);
    geometry_msgs::PointStamped pa;
    pa.header.stamp = stamp;
    pa.header.frame_id = "odom";
    pa.point.x = position;
    positionA.publish(pa);
    std_msgs::Float64 pb;
    pb.data = position + 0.01;
    positionB.publish(pb);
    geometry_msgs::Vector3Stamped va;
    va.header = pa.header;
    va.vector.x = velocity;
    velocityA.publish(va);
    std_msgs::Float64 vb;
    vb.data = velocity - 0.01;
    velocityB.publish(vb);
    for (int i = 0; i < 4; ++i) ++published[i];
    if (k % stepsPerControl == 0) {
      std_msgs::Float64 u;
      u.data = -0.25 * std::sin(0.5 * s);
      command.publish(u);
      ++published[4];
    }
    if (wallNow() >= nextSample) {
      sampleMemory(t);
      nextSample += rssInterval;
    }
  }
  // Close the last period and wait for its estimate.
  const std::int64_t lastPeriod = steps / stepsPerPeriod;
  tick.clock = ros::Time(startTime + static_cast<double>(steps + 1) / inputRate);
  if (!wallClock) clock.publish(tick);
  const bool last = wallClock || (!stalled && estimates.waitFor(lastPeriod, 10.0));
  const double wallEnd = wallNow();
  sampleMemory(startTime + simDuration);
  const sf_bench::CpuSample cpuEnd =
      nodePid > 0 ? sf_bench::readCpu(nodePid) : sf_bench::CpuSample{};
  ros::WallDuration(0.5).sleep();
  spinner.stop();

  std::ostringstream out;
  const double wall = wallEnd - wallStart;
  out << "sim_s=" << simDuration << "\n";
  out << "wall_s=" << wall << "\n";
  out << "speed_vs_real_time=" << simDuration / wall << "\n";
  out << "periods=" << periods << "\n";
  out << "stalled=" << (stalled || !last ? 1 : 0) << "\n";
  out << "published_clock=" << clocks << "\n";
  const char* names[5] = {"position_a", "position_b", "velocity_a", "velocity_b", "command"};
  std::uint64_t inputs = 0;
  for (int i = 0; i < 5; ++i) {
    out << "published_" << names[i] << "=" << published[i] << "\n";
    if (i < 4) inputs += published[i];
  }
  out << "published_inputs=" << inputs << "\n";
  estimates.report(out);
  if (nodePid > 0 && cpuStart.ok && cpuEnd.ok && wall > 0.0) {
    const double cpu = cpuEnd.statSeconds - cpuStart.statSeconds;
    out << "node_threads=" << cpuEnd.threads << "\n";
    out << "node_cpu_s=" << cpu << "\n";
    out << "node_cpu_percent_of_a_core=" << 100.0 * cpu / wall << "\n";
    out << "node_cpu_us_per_sim_s=" << cpu / simDuration * 1e6 << "\n";
    out << "node_cpu_us_per_message="
        << cpu / static_cast<double>(inputs + published[4] + clocks) * 1e6 << "\n";
  }
  memory.report(out, warmup);
  std::fputs(out.str().c_str(), stdout);
  if (!reportPath.empty()) std::ofstream(reportPath) << out.str();
  if (!rssCsv.empty()) {
    std::ofstream csv(rssCsv);
    csv << "wall_s,sim_s,vmrss_kib\n";
    for (const auto& s : memory.samples) csv << s.wall << ',' << s.sim << ',' << s.kib << '\n';
  }
  return stalled || !last ? 1 : 0;
}
