// The ROS side of a fusion node: a thin adapter that feeds the fusion core with the messages
// it receives and the passing of ros::Time, and publishes each estimate. Time is ros::Time,
// so the node behaves the same live and under `rosbag play --clock` with use_sim_time. Its
// diagnostics (fusion_diagnostics.hpp) go to /diagnostics. Compiled once for every
// configuration header: it sees the header's filter through FusionEngine and its topics
// through TopicReader, subscribing to each topic as serialized messages (ShapeShifter) and
// checking their type itself, so that a publisher of the wrong type is reported, not ignored.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <topic_tools/shape_shifter.h>

#include <sf_msgs/SetPose.h>

#include "sf_filter/config/extractors/quaternion_angles.hpp"
#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/message_arrival.hpp"
#include "sf_filter/definition/input_state.hpp"
#include "sf_filter/definition/message_sink.hpp"
#include "sf_filter/definition/node_description.hpp"
#include "sf_filter/io/estimate_writer.hpp"
#include "sf_filter/io/ros_parameters.hpp"
#include "sf_filter/node/frame_aligner.hpp"
#include "sf_filter/node/fusion_diagnostics.hpp"

namespace sf_filter {

class FusionNode final : public MessageSink {
 public:
  /// `engine`: the header's filter in its fusion core (period, per-input alignment, gates,
  /// measurement lag, timeouts, ranges, NIS window); `aligner`: the spatial alignment of
  /// FRAME_ALIGNED_INPUTS (nullptr without); a diagnostic report every `diagnosticPeriod` s;
  /// `settings`: frames, tf, queue sizes (loadOutputParameters).
  FusionNode(ros::NodeHandle nh, ros::NodeHandle pnh, std::unique_ptr<FusionEngine> engine,
             NodeDescription description, FrameAligner* aligner, double diagnosticPeriod = 1.0,
             const OutputSettings& settings = OutputSettings())
      : nh_(nh),
        pnh_(pnh),
        description_(std::move(description)),
        engine_(std::move(engine)),
        core_(*engine_),
        aligner_(aligner),
        diagnostics_(nh_, pnh_, core_, description_.inputs, diagnosticPeriod),
        diagnosticPeriod_(diagnosticPeriod),
        frameId_(settings.frameId),
        childFrameId_(settings.childFrameId),
        publishTf_(settings.publishTf),
        queueSize_(settings.queueSize),
        writer_(description_, OutputFrames{settings.frameId, settings.childFrameId}) {
    AdvertiseSink advertiser{*this};
    writer_.declare(advertiser);
    if (settings.smoothingLag > 0.0) setUpLaggedSmoother(settings.smoothingLag, advertiser);
    if (description_.pose) advertisePose();
    addLossSources();
    logConfiguration();
  }

  /// Subscribes the reader's topic as serialized messages; each message of the expected type
  /// is handed to the reader, which gives every used field to measurement() or control().
  /// Messages received before the clock is valid wait for it (the newest ~queue_size of them).
  /// Throws std::invalid_argument when another reader's topic resolves (remaps applied) onto
  /// the same topic with another message type (topicTypeClash).
  void subscribe(const TopicReader& reader) {
    const std::string resolved = nh_.resolveName(reader.topic);
    const auto known = resolvedTypes_.find(resolved);
    if (known != resolvedTypes_.end()) {
      const std::string clash = topicTypeClash(resolved, known->second, reader.datatype);
      if (!clash.empty()) throw std::invalid_argument(clash);
    }
    resolvedTypes_[resolved] = reader.datatype;
    using Event = ros::MessageEvent<topic_tools::ShapeShifter const>;
    const boost::function<void(const Event&)> callback = [this, reader](const Event& event) {
      if (!scheduled_) {
        if (!ros::Time::isValid()) {
          if (early_.size() >= static_cast<std::size_t>(queueSize_)) early_.pop_front();
          early_.emplace_back(reader, event);
          return;
        }
        startSchedule(ros::Time::now().toSec());
      }
      receive(reader, event);
    };
    subscribers_.push_back(
        nh_.subscribe<topic_tools::ShapeShifter, const Event&>(reader.topic, queueSize_, callback));
  }

  /// Starts the fixed-rate schedule once the clock is valid and returns at once (a nodelet's
  /// onInit must not block its manager). On simulated time the schedule advances with each
  /// /clock message, the first one starting it; a ros::Timer would make roscpp's timer thread
  /// poll the simulated clock every millisecond of wall time, running or stopped (2-5 % of a
  /// core, doc/node_benchmarks.md). Before the first /clock message the wait is reported:
  /// /diagnostics every ~diagnostic_period, a warning every 5 s.
  void start() {
    waitingSince_ = ros::WallTime::now();
    if (ros::Time::isSimTime()) {
      clock_ = nh_.subscribe<rosgraph_msgs::Clock>(
          "/clock", 10,
          [this](const rosgraph_msgs::Clock::ConstPtr& m) { onClock(m->clock.toSec()); });
    }
    if (ros::Time::isValid()) {
      startSchedule(ros::Time::now().toSec());
      return;
    }
    reportWaiting();
    clockWait_ = nh_.createWallTimer(ros::WallDuration(diagnosticPeriod_),
                                     [this](const ros::WallTimerEvent&) { reportWaiting(); });
  }

  void measurement(Index input, double now, double value, std::optional<double> variance,
                   double stamp) override {
    const Rejection r = core_.addMeasurement(input, now, value, variance, stamp);
    if (r != Rejection::None) reportDrop(input, r, "a value");
  }

  void measurementBlock(const Index* inputs, const double* values, const double* covariance,
                        int count, double now, double stamp) override {
    const Rejection r = core_.addMeasurementBlock(inputs, values, covariance, count, now, stamp);
    if (r != Rejection::None) reportDrop(inputs[0], r, "a value of the covariance block");
  }

  void control(Index index, double value) override {
    if (core_.addControl(index, value) != Rejection::None) {
      ROS_WARN_THROTTLE(5.0, "dropped a non-finite value of control %ld (%s)",
                        static_cast<long>(index),
                        description_.controls.at(static_cast<std::size_t>(index)).c_str());
    }
  }

  std::optional<double> rotated(Index input, const std::string& frame, std::uint32_t sec,
                                std::uint32_t nsec, const std::array<double, 3>& vector,
                                int axis) override {
    return aligner_->align(static_cast<std::size_t>(input), frame, ros::Time(sec, nsec), vector,
                           axis);
  }

  const FusionEngine& core() const { return core_; }

  /// What reading the inputs keeps between messages (extractors, GPS datum and counters,
  /// covariance fallbacks), this run's.
  InputState& inputState() { return inputState_; }
  const InputState& inputState() const { return inputState_; }

 private:
  /// POSE_OUT: robot_localization's set_pose topics and service.
  void advertisePose() {
    // robot_localization's set_pose topic and rviz's 2D Pose Estimate (/initialpose).
    for (const char* topic : {"set_pose", "initialpose"}) {
      setPoseSubscribers_.push_back(nh_.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
          topic, 10, [this, topic](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
            setPose(topic, *m);
          }));
    }
    // robot_localization's ~set_pose service: the same reset, with its outcome returned.
    setPoseService_ = pnh_.advertiseService<sf_msgs::SetPose::Request, sf_msgs::SetPose::Response>(
        "set_pose",
        [this](sf_msgs::SetPose::Request& request, sf_msgs::SetPose::Response& response) {
          response.message = setPose("~set_pose", request.pose);
          response.success = response.message.empty();
          return true;
        });
    diagnostics_.addEstimationValue("poses set", [this] { return std::to_string(setPoses_); });
    diagnostics_.addEstimationValue("poses refused",
                                    [this] { return std::to_string(refusedPoses_); });
  }

  /// The values lost before the core sees them, in the inputs' diagnostics.
  void addLossSources() {
    // What is lost before the core sees it is in the input's diagnostics too: a message of
    // another type on its topic, a value that cannot be rotated into the base frame.
    InputLossSource wrongType;
    wrongType.alwaysError = true;
    wrongType.count = [this](std::size_t i) { return wrongTypeOf(i).count; };
    wrongType.reason = [this](std::size_t i) {
      const WrongType& w = wrongTypeOf(i);
      return "topic " + w.topic + " receives " + w.received + ", the configuration reads " +
             w.expected;
    };
    diagnostics_.addLossSource(wrongType);
    // A GPS input's fixes without a valid status (gps::GpsInputs).
    InputLossSource noFix;
    noFix.count = [this](std::size_t i) { return inputState_.gps().noFix(i); };
    noFix.reason = [](std::size_t) { return std::string("GPS fix status below STATUS_FIX"); };
    diagnostics_.addLossSource(noFix);
    // A GPS input's fixes whose position is not on the Earth (gps::implausible).
    InputLossSource implausibleFix;
    implausibleFix.count = [this](std::size_t i) { return inputState_.gps().implausibleFixes(i); };
    implausibleFix.reason = [this](std::size_t i) {
      return "GPS fix not on the Earth: " + inputState_.gps().implausibleReason(i);
    };
    diagnostics_.addLossSource(implausibleFix);
    // INPUT_COVARIANCE: messages whose covariance was unknown (all zero, -1 first) used R.
    diagnostics_.addInputValue("covariance unknown, header R used", [this](std::size_t i) {
      const std::uint64_t n = inputState_.covarianceFallbacks(static_cast<Index>(i));
      return n ? std::to_string(n) : std::string();
    });
    if (aligner_) {
      InputLossSource unrotated;
      unrotated.count = [this](std::size_t i) { return aligner_->dropped(i); };
      unrotated.reason = [this](std::size_t i) { return aligner_->dropReason(i); };
      diagnostics_.addLossSource(unrotated);
    }
  }

  using MessageEvent = ros::MessageEvent<topic_tools::ShapeShifter const>;

  /// A value of input `input` dropped for `r`. Late values are explained per input, with
  /// their delays and the lag that would keep them (lateAdvice): at the first, then at most
  /// every kLateWarningPeriod s of wall time; other drops in one line every 5 s.
  void reportDrop(Index input, Rejection r, const char* what) {
    const auto i = static_cast<std::size_t>(input);
    if (r == Rejection::TooLate && i < description_.inputs.size()) {
      if (lateWarnings_.empty()) lateWarnings_.resize(description_.inputs.size());
      const ros::WallTime now = ros::WallTime::now();
      if (lateWarnings_[i].isZero() || (now - lateWarnings_[i]).toSec() >= kLateWarningPeriod) {
        lateWarnings_[i] = now;
        core_.fillStatistics(statistics_);
        ROS_WARN("%s", lateAdvice(i, description_.inputs[i], statistics_.inputs[i],
                                  core_.maxMeasurementLag())
                           .c_str());
      }
      return;
    }
    ROS_WARN_THROTTLE(5.0, "dropped %s of input %ld (%s): %s", what, static_cast<long>(input),
                      description_.inputs.at(i).c_str(), toString(r));
  }

  /// A message of `reader`'s topic: the clock advances to its arrival, then the reader reads it.
  void receive(const TopicReader& reader, const MessageEvent& event) {
    const topic_tools::ShapeShifter::ConstPtr& msg = event.getConstMessage();
    const double now = arrival(event.getReceiptTime());
    advance(now);
    if (!hasExpectedType(reader, *msg)) return;
    buffer_.resize(msg->size());
    ros::serialization::OStream stream(buffer_.data(), msg->size());
    msg->write(stream);
    try {
      reader.read(buffer_.data(), msg->size(), *this, inputState_, now);
    } catch (const ros::Exception& e) {
      ROS_ERROR_THROTTLE(5.0, "topic %s: a message could not be decoded: %s", reader.topic.c_str(),
                         e.what());
    }
  }

  /// The wait of start() for the first /clock message, reported.
  void reportWaiting() {
    const ros::WallTime now = ros::WallTime::now();
    if (!waitingReport_) {
      waitingReport_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
    }
    diagnostic_msgs::DiagnosticArray report;
    diagnostic_msgs::DiagnosticStatus status;
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.name = pnh_.getNamespace().substr(1) + ": estimation";
    status.message = "waiting for /clock (use_sim_time is true): no estimate yet";
    status.hardware_id = "none";
    report.status.push_back(status);
    waitingReport_.publish(report);
    if (lastWaitWarning_.isZero() || (now - lastWaitWarning_).toSec() >= 5.0) {
      lastWaitWarning_ = now;
      ROS_WARN(
          "waiting for /clock (use_sim_time is true and no clock message arrived in %.0f "
          "s): no estimate until a clock publisher (rosbag play --clock, a simulator) "
          "runs",
          (now - waitingSince_).toSec());
    }
  }

  /// The fixed-rate schedule from the first valid clock reading `now` on: on wall-clock time
  /// a ros::Timer ends the periods, on simulated time the /clock messages do (start()).
  void startSchedule(double now) {
    scheduled_ = true;
    clockWait_.stop();
    waitingReport_.shutdown();
    diagnostics_.start();
    advance(now);
    for (const auto& [reader, event] : early_) receive(reader, event);
    early_.clear();
    if (!ros::Time::isSimTime()) {
      timer_ = nh_.createTimer(ros::Duration(core_.period()), [this](const ros::TimerEvent&) {
        advance(ros::Time::now().toSec());
      });
    }
  }

  /// Whether `msg` is of the reader's type; a message of another type is dropped, counted and
  /// reported (a typed roscpp subscription would refuse such a publisher without a word).
  bool hasExpectedType(const TopicReader& reader, const topic_tools::ShapeShifter& msg) {
    if (msg.getDataType() == reader.datatype &&
        (msg.getMD5Sum() == reader.md5sum || msg.getMD5Sum() == "*")) {
      return true;
    }
    WrongType& w = wrongType_[nh_.resolveName(reader.topic)];
    ++w.count;
    w.topic = nh_.resolveName(reader.topic);
    w.received = msg.getDataType();
    w.expected = reader.datatype;
    ROS_ERROR_THROTTLE(5.0,
                       "topic %s: received %s (md5sum %s), the configuration reads %s (md5sum "
                       "%s): message dropped (%llu so far)",
                       reader.topic.c_str(), msg.getDataType().c_str(), msg.getMD5Sum().c_str(),
                       reader.datatype.c_str(), reader.md5sum.c_str(),
                       static_cast<unsigned long long>(w.count));
    return false;
  }

  /// A /clock message (simulated time). A message of an input topic advances the schedule to
  /// its receipt time, which roscpp reads from the clock its own thread keeps, so a /clock
  /// message still queued behind it can read older than the core's clock although the clock
  /// never went back: that reading is stale and changes nothing (it reset the filter on a
  /// loaded machine). Only /clock itself going back (a restarted bag, a reset simulator) is a
  /// jump backwards.
  void onClock(double t) {
    if (!scheduled_) startSchedule(t);
    const bool backwards = t < lastClockMessage_;
    lastClockMessage_ = t;
    advance(backwards ? t : std::max(t, core_.clock()));
  }

  /// The arrival time of a message (messageArrival): its receipt time, never before the
  /// core's last clock reading.
  double arrival(const ros::Time& receipt) const {
    return messageArrival(receipt.toSec(), ros::Time::now().toSec(), core_.clock());
  }

  void advance(double now) {
    const ClockEvent event = core_.advanceTo(now, publishEstimate_);
    core_.fillStatistics(statistics_);  // allocation-free after the first period
    const FusionStatistics& s = statistics_;
    if (event == ClockEvent::JumpedBackwards) {
      measured_ = false;
      ROS_WARN_THROTTLE(5.0,
                        "time jumped backwards to %.3f s (bag restarted?): filter reset (%llu "
                        "times so far)",
                        now, static_cast<unsigned long long>(s.clockResets));
    } else if (event == ClockEvent::SkippedGap) {
      ROS_WARN_THROTTLE(5.0,
                        "time jumped forward to %.3f s: skipped the missed periods (%llu gaps "
                        "so far)",
                        now, static_cast<unsigned long long>(s.skippedGaps));
    }
    if (s.estimationFailures != failuresReported_) {
      ROS_ERROR_THROTTLE(5.0,
                         "estimation step rejected (%llu so far, %llu filter resets): %s; the "
                         "last good estimate is kept",
                         static_cast<unsigned long long>(s.estimationFailures),
                         static_cast<unsigned long long>(s.filterResets), s.lastFailure.c_str());
      failuresReported_ = s.estimationFailures;
    }
    reportTimeouts();
    const std::uint64_t gated = s.totals.gated;
    if (gated != gatedReported_) {
      ROS_WARN_THROTTLE(10.0,
                        "%llu values failed their input's Mahalanobis gate so far (used as "
                        "missing)",
                        static_cast<unsigned long long>(gated));
      gatedReported_ = gated;
    }
    const estimation::NumericalRepairs& repairs = s.repairs;
    if (repairs.total() != repairsReported_) {
      ROS_WARN_THROTTLE(10.0,
                        "the filter repaired its numbers %llu times so far (covariance made "
                        "positive semi-definite %llu, all particle weights vanished %llu, "
                        "sigma spread widened %llu); the estimate goes on",
                        static_cast<unsigned long long>(repairs.total()),
                        static_cast<unsigned long long>(repairs.covariance),
                        static_cast<unsigned long long>(repairs.weights),
                        static_cast<unsigned long long>(repairs.sigmaSpread));
      repairsReported_ = repairs.total();
    }
  }

  /// set_pose, initialpose and ~set_pose: the pose part of the belief (POSE_OUT's x, y,
  /// heading) and its covariance block (x, y, yaw slots of the message's 6 x 6 covariance) are
  /// replaced, the pose first turned into the odom frame (inOdomFrame). Returns why the pose
  /// was refused (the belief then is as it was), empty if set. Logged at most once per
  /// kPoseLogPeriod each, set and refused (a 1 kHz publisher wrote 10 000 lines in 10 s);
  /// every pose is counted in the diagnostics and the service answers each.
  std::string setPose(const char* topic, const geometry_msgs::PoseWithCovarianceStamped& given) {
    geometry_msgs::PoseWithCovarianceStamped m;
    std::string refused =
        scheduled_ ? inOdomFrame(given, m) : "the clock does not run yet (use_sim_time, no /clock)";
    if (refused.empty()) {
      advance(arrival(ros::Time()));  // the clock now, never before the core's reading
      refused = replacePose(m);
    }
    if (!refused.empty()) {
      ++refusedPoses_;
      ROS_ERROR_THROTTLE(kPoseLogPeriod, "%s: pose refused: %s; %llu refused so far", topic,
                         refused.c_str(), static_cast<unsigned long long>(refusedPoses_));
      return refused;
    }
    ++setPoses_;
    measured_ = true;  // a pose given by the user is a real pose: odometry and tf follow
    const auto& p = m.pose.pose.position;
    const auto& c = m.pose.covariance;
    ROS_INFO_THROTTLE(kPoseLogPeriod,
                      "%s: pose set to x %.3f, y %.3f, yaw %.3f in %s (variances %.3g, %.3g, "
                      "%.3g); %llu so far",
                      topic, p.x, p.y, yawOf(m), frameId_.c_str(), c[0], c[7], c[35],
                      static_cast<unsigned long long>(setPoses_));
    return {};
  }

  static double yawOf(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const auto& q = m.pose.pose.orientation;
    return sf_config::extractors::eulerAngles({q.x, q.y, q.z, q.w}).yaw;
  }

  /// `given` in the odom frame (~frame_id) into `out`: as it is when its header.frame_id is
  /// that frame or empty; else turned through tf (rviz publishes initialpose in its fixed
  /// frame, often map), covariance included (tf2's doTransform). Returns why not, naming
  /// both frames, when tf has no transform between them; empty on success.
  std::string inOdomFrame(const geometry_msgs::PoseWithCovarianceStamped& given,
                          geometry_msgs::PoseWithCovarianceStamped& out) {
    std::string frame = given.header.frame_id;
    if (!frame.empty() && frame.front() == '/') frame.erase(0, 1);  // tf1's spelling
    out = given;
    if (frame.empty() || frame == frameId_) return {};
    if (!poseTf_) {
      poseTf_ = std::make_unique<tf2_ros::Buffer>();
      poseTfListener_ = std::make_unique<tf2_ros::TransformListener>(*poseTf_, nh_);
      // Its own thread fills the buffer; wall time, as simulated time may stand still.
      const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(kPoseTfWait);
      while (!poseTf_->canTransform(frameId_, frame, ros::Time(0)) &&
             ros::WallTime::now() < until) {
        ros::WallDuration(0.01).sleep();
      }
    }
    try {
      // The newest transform: a pose is given for now, and a map -> odom transform (a
      // localiser's) is published at a few Hz, rarely at the pose's stamp yet.
      const geometry_msgs::TransformStamped t =
          poseTf_->lookupTransform(frameId_, frame, ros::Time(0));
      tf2::doTransform(given, out, t);
    } catch (const tf2::TransformException& e) {
      return "no transform from the pose's frame '" + frame + "' into the odom frame '" + frameId_ +
             "' (tf: " + e.what() + ")";
    }
    return {};
  }

  /// The pose of `m` (in the odom frame) made the belief's; why not, empty if it was.
  std::string replacePose(const geometry_msgs::PoseWithCovarianceStamped& m) {
    const std::array<double, 3> pose = {m.pose.pose.position.x, m.pose.pose.position.y, yawOf(m)};
    const std::array<int, 3> slot = {0, 1, 5};
    Eigen::Matrix3d covariance;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) covariance(r, c) = m.pose.covariance[slot[r] * 6 + slot[c]];
    }
    if (!(std::isfinite(pose[0]) && std::isfinite(pose[1]) && std::isfinite(pose[2]))) {
      return "the pose's x, y or orientation is not finite";
    }
    if (!withinParameterMagnitude(pose[0]) || !withinParameterMagnitude(pose[1])) {
      // As ~initial_state: beyond 1e100 a period's products overflow.
      return "the pose's x or y is not a finite number of magnitude at most 1e100";
    }
    if (!covariance.allFinite()) return "the pose's covariance block (x, y, yaw) is not finite";
    try {
      if (!core_.setPose(*description_.pose, pose, covariance)) {
        return "the " + description_.method + " cannot be re-initialised";
      }
    } catch (const std::exception& e) {
      return std::string("the pose's covariance block (x, y, yaw) is not a covariance: ") +
             e.what();
    }
    return {};
  }

  /// Logs an input's timing out and its return once each.
  void reportTimeouts() {
    timedOut_.resize(static_cast<std::size_t>(core_.inputCount()), false);
    for (Index i = 0; i < core_.inputCount(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      const bool now = core_.timedOut(i);
      if (now == timedOut_[k]) continue;
      timedOut_[k] = now;
      if (now) {
        ROS_WARN("input %ld (%s) timed out: no value for %.3f s; used as missing until it returns",
                 static_cast<long>(i), description_.inputs[k].c_str(),
                 core_.inputOptions(i).timeout);
      } else {
        ROS_INFO("input %ld (%s) is back", static_cast<long>(i), description_.inputs[k].c_str());
      }
    }
  }

  /// EstimateWriter's sink online, advertising: a publisher per output, in the writer's order.
  struct AdvertiseSink {
    FusionNode& node;
    template <class Message>
    void declare(std::size_t, const std::string& topic, OutputScope scope) {
      ros::NodeHandle& h = scope == OutputScope::Private ? node.pnh_ : node.nh_;
      node.publishers_.push_back(h.advertise<Message>(topic, node.queueSize_));
    }
  };

  /// EstimateWriter's sink online, publishing; the filtered odometry's pose also goes to tf.
  struct PublishSink {
    FusionNode& node;
    bool tf;
    template <class Message>
    void operator()(std::size_t k, const std::string&, OutputScope, const Message& m) const {
      node.publishers_[k].publish(m);
      if constexpr (std::is_same_v<Message, nav_msgs::Odometry>) {
        if (tf) node.broadcast(m);
      }
    }
  };

  void publish(const EstimateRef& e) {
    // No pose before the first estimate from a real input: the filter's initial belief at
    // the origin is not a position of the robot (doc/filter_node.md).
    measured_ = measured_ || e.presentInputs > 0;
    PublishSink sink{*this, true};
    writer_.write(e, measured_, sink);
    if (lagged_) publishSmoothed();
  }

  /// ~smoothing_lag: the fixed-lag smoother of that lag in whole periods and its publishers;
  /// refused (the node does not start) for a filter without a smoother.
  void setUpLaggedSmoother(double lagSeconds, AdvertiseSink& advertiser) {
    const auto periods = static_cast<std::size_t>(std::llround(lagSeconds / core_.period()));
    lagged_ = core_.makeLaggedSmoother(std::max<std::size_t>(1, periods));
    if (!lagged_) {
      throw ParameterOverrideError("parameter ~smoothing_lag: the " + core_.filterDescription() +
                                   " has no smoother (the Kalman, extended and unscented Kalman "
                                   "filters have)");
    }
    writer_.declareSmoothed(advertiser);
    diagnostics_.addSmoother(*lagged_);
  }

  /// The smoothed belief of the period the lag back, once the smoother holds the lag.
  void publishSmoothed() {
    const std::optional<LaggedBelief> s = lagged_->add();
    if (!s) return;
    const EstimateRef e{s->time, s->belief.state, s->belief.covariance, s->presentInputs, 0, false,
                        false};
    PublishSink sink{*this, false};
    writer_.writeSmoothed(e, measured_, sink);
  }

  /// The odometry's pose as the transform frame_id -> child_frame_id (unless ~publish_tf off).
  void broadcast(const nav_msgs::Odometry& odom) {
    if (!publishTf_) return;
    geometry_msgs::TransformStamped t;
    t.header = odom.header;
    t.child_frame_id = childFrameId_;
    t.transform.translation.x = odom.pose.pose.position.x;
    t.transform.translation.y = odom.pose.pose.position.y;
    t.transform.translation.z = odom.pose.pose.position.z;  // 0 for a planar pose
    t.transform.rotation = odom.pose.pose.orientation;
    broadcaster_.sendTransform(t);
  }

  void logConfiguration() const {
    ROS_INFO("%s: n=%ld states, m=%ld measurements, l=%ld controls, period %.1f ms",
             core_.filterDescription().c_str(), static_cast<long>(core_.stateSize()),
             static_cast<long>(core_.measurementSize()), static_cast<long>(core_.controlSize()),
             core_.period() * 1000.0);
    bool byStamp = false;
    for (std::size_t i = 0; i < description_.inputs.size(); ++i) {
      const InputOptions& o = core_.inputOptions(static_cast<Index>(i));
      byStamp = byStamp || o.alignByStamp;
      std::string alignment = toString(o.alignment);
      if (o.gated()) {
        char gate[32];
        std::snprintf(gate, sizeof gate, ", gate %g", o.gateThreshold);
        alignment += gate;
      }
      if (o.alignByStamp) alignment += ", by stamp";
      if (o.hasTimeout()) {
        char timeout[48];
        std::snprintf(timeout, sizeof timeout, ", timeout %g ms", o.timeout * 1000.0);
        alignment += timeout;
      }
      if (o.hasRange()) {
        char range[64];
        std::snprintf(range, sizeof range, ", range [%g, %g]", o.minimum, o.maximum);
        alignment += range;
      }
      ROS_INFO("  input %zu: %s (%s)", i, resolvedInput(i).c_str(), alignment.c_str());
    }
    if (byStamp) {
      ROS_INFO("  periods wait %.1f ms for stamped values", core_.maxMeasurementLag() * 1000.0);
    }
    for (std::size_t i = 0; i < description_.controls.size(); ++i) {
      ROS_INFO("  control %zu: %s", i, description_.controls[i].c_str());
    }
    logOutputs();
  }

  /// logConfiguration's outputs, in the writer's order.
  void logOutputs() const {
    for (const auto& out : description_.outputs) {
      ROS_INFO("  output %s <- x[%d]", nh_.resolveName(out.first).c_str(), out.second);
    }
    const std::size_t state = description_.outputs.size();  // writer_'s order
    ROS_INFO("  state -> %s", publishers_.at(state).getTopic().c_str());
    if (core_.nis().enabled()) {
      ROS_INFO("  diagnostics -> /diagnostics, NIS over %zu periods", core_.nis().capacity());
    } else {
      ROS_INFO("  diagnostics -> /diagnostics");
    }
    if (description_.hasOdometry()) {
      ROS_INFO("  odometry -> %s, tf %s -> %s%s", publishers_.at(state + 1).getTopic().c_str(),
               frameId_.c_str(), childFrameId_.c_str(), publishTf_ ? "" : " (tf disabled)");
    }
    if (description_.pose3d) {
      ROS_INFO("  Euler angles -> %s", publishers_.at(state + 2).getTopic().c_str());
    }
    if (description_.pose) {
      ROS_INFO("  pose resets <- %s, %s, service %s", nh_.resolveName("set_pose").c_str(),
               nh_.resolveName("initialpose").c_str(), setPoseService_.getService().c_str());
    }
    if (description_.accel) {
      ROS_INFO("  acceleration x[%d] -> %s", *description_.accel,
               publishers_.at(writer_.count() - 1).getTopic().c_str());
    }
    if (lagged_) {
      ROS_INFO(
          "  smoothed with a lag of %zu periods -> %s%s%s", lagged_->lag(),
          publishers_.at(writer_.count()).getTopic().c_str(),
          description_.hasOdometry() ? ", " : "",
          description_.hasOdometry() ? publishers_.at(writer_.count() + 1).getTopic().c_str() : "");
    }
  }

  /// [s] between two log lines of set poses (and of refused ones).
  static constexpr double kPoseLogPeriod = 1.0;
  /// [s] a pose in another frame waits for tf's first transform (the listener starts with
  /// the first such pose, so /tf_static's latched transforms arrive within this).
  static constexpr double kPoseTfWait = 2.0;
  /// Input i's "topic field" name with the topic as subscribed (namespace and remaps applied),
  /// and the configured name when a remap changed it: the log shows what the node listens to.
  std::string resolvedInput(std::size_t i) const {
    const std::string& name = description_.inputs.at(i);
    const std::size_t space = name.find(' ');
    const std::string topic = name.substr(0, space);
    const std::string resolved = nh_.resolveName(topic);
    const std::string rest = space == std::string::npos ? "" : name.substr(space);
    const bool remapped = resolved != nh_.resolveName(topic, false);
    return resolved + rest + (remapped ? " [remapped from " + topic + "]" : "");
  }

  ros::NodeHandle nh_, pnh_;
  NodeDescription description_;
  std::unique_ptr<FusionEngine> engine_;
  FusionEngine& core_;
  FrameAligner* aligner_;
  FusionDiagnostics diagnostics_;
  double diagnosticPeriod_;  ///< [s] between diagnostic reports
  std::function<void(const EstimateRef&)> publishEstimate_ = [this](const EstimateRef& e) {
    publish(e);
  };
  std::vector<std::uint8_t> buffer_;  ///< the message being read, serialized
  InputState inputState_;
  /// Messages of another type received on a topic.
  struct WrongType {
    std::uint64_t count = 0;
    std::string topic, received, expected;
  };
  /// The wrong-type record of input i's topic (the first word of its "topic field" name).
  const WrongType& wrongTypeOf(std::size_t i) const {
    static const WrongType none;
    const std::string& name = description_.inputs.at(i);
    const auto it = wrongType_.find(nh_.resolveName(name.substr(0, name.find(' '))));
    return it == wrongType_.end() ? none : it->second;
  }
  std::map<std::string, WrongType> wrongType_;        ///< by resolved topic name
  std::map<std::string, std::string> resolvedTypes_;  ///< subscribed: resolved topic -> type
  std::vector<ros::Subscriber> subscribers_;
  std::vector<ros::Subscriber> setPoseSubscribers_;
  ros::ServiceServer setPoseService_;
  std::uint64_t setPoses_ = 0, refusedPoses_ = 0;
  /// tf for poses in another frame than the odom frame, started by the first of them (a node
  /// whose poses come in its own frame does not subscribe /tf).
  std::unique_ptr<tf2_ros::Buffer> poseTf_;
  std::unique_ptr<tf2_ros::TransformListener> poseTfListener_;
  std::vector<ros::Publisher> publishers_;  ///< per output of writer_, in its order
  ros::Timer timer_;                        ///< the schedule on wall-clock time
  ros::Subscriber clock_;                   ///< the schedule on simulated time
  /// The newest /clock message read (onClock); -infinity before the first.
  double lastClockMessage_ = -std::numeric_limits<double>::infinity();
  bool scheduled_ = false;  ///< the clock was valid: subscribed, timer running
  /// Messages received before the clock was valid, read when the schedule starts.
  std::deque<std::pair<TopicReader, MessageEvent>> early_;
  ros::WallTimer clockWait_;      ///< reports the wait for the first /clock message
  ros::Publisher waitingReport_;  ///< /diagnostics while the updater cannot run yet
  ros::WallTime waitingSince_, lastWaitWarning_;
  /// Seconds between two explanations of an input's late values (reportDrop).
  static constexpr double kLateWarningPeriod = 60.0;
  std::vector<ros::WallTime> lateWarnings_;  ///< per input: the last one (zero: none yet)
  tf2_ros::TransformBroadcaster broadcaster_;
  std::string frameId_, childFrameId_;
  bool publishTf_ = true;
  int queueSize_ = 1000;  ///< ~queue_size: of every subscription and publication
  EstimateWriter writer_;
  std::unique_ptr<LaggedSmoother> lagged_;  ///< ~smoothing_lag (nullptr: off)
  bool measured_ = false;        ///< an estimate used a measured value (since the last reset)
  FusionStatistics statistics_;  ///< the core's counters after the last advance()
  std::uint64_t failuresReported_ = 0;
  std::uint64_t gatedReported_ = 0;
  std::uint64_t repairsReported_ = 0;
  std::vector<bool> timedOut_;  ///< per input: its timeout was logged
};

}  // namespace sf_filter
