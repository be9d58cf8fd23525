// Offline replay: reads a bag directly (no ROS master), feeds its messages in recorded-time
// order through the same fusion core as the online node, and writes the estimates as CSV
// and/or as a bag with the node's own output topics, as fast as the machine allows. The
// recorded time plays the role of the node's clock, so the result is deterministic.
// A node with FRAME_ALIGNED_INPUTS gets the bag's /tf_static and /tf through
// readTransforms() (see replay_frame_aligner.hpp).
#pragma once

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_msgs/TFMessage.h>

#include "sf_filter/core/fusion_core.hpp"
#include "sf_filter/node/estimate_messages.hpp"
#include "sf_filter/node/node_description.hpp"

namespace sf_filter {

/// A replay that cannot run (unreadable bag, missing topic, wrong type, unwritable output).
class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ReplayOptions {
  std::string inputBag;
  std::string csvPath;     ///< empty: no CSV
  std::string outputBag;   ///< empty: no bag
  std::string nodeName = "sf_filter";  ///< namespace of the ~state topic in the output bag
  std::string frameId = "odom";
  std::string childFrameId = "base_link";
};

struct ReplaySummary {
  std::uint64_t messages = 0;
  std::uint64_t estimates = 0;
  std::uint64_t dropped = 0;
  double estimatorSeconds = 0.0;
};

/// An output file written under a temporary name and renamed into place only when the whole
/// replay succeeded, so a failed run never leaves a partial result behind.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::string path)
      : path_(std::move(path)), temporary_(path_.empty() ? "" : path_ + ".partial") {}
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput() {
    if (!committed_ && !temporary_.empty()) std::remove(temporary_.c_str());
  }
  bool enabled() const { return !path_.empty(); }
  const std::string& temporary() const { return temporary_; }
  void commit() {
    if (!enabled()) return;
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
      throw ReplayError("cannot move " + temporary_ + " to " + path_);
    }
    committed_ = true;
  }

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

template <class Filter>
class BagReplay {
  using Core = FusionCore<Filter>;
  using Handler = std::function<void(const rosbag::MessageInstance&, double)>;

 public:
  /// Receives the transforms of one /tf_static (isStatic) or /tf message.
  using TransformSink = std::function<void(const tf2_msgs::TFMessage&, bool isStatic)>;

  BagReplay(Filter filter, double period, NodeDescription description, ReplayOptions options)
      : BagReplay(std::move(filter), makeOptions(period), std::move(description),
                  std::move(options)) {}

  /// With the fusion core's options (alignment policies, gates, measurement lag).
  BagReplay(Filter filter, const typename Core::Options& coreOptions, NodeDescription description,
            ReplayOptions options)
      : core_(std::move(filter), coreOptions),
        description_(std::move(description)),
        options_(std::move(options)) {}

  /// Registers the reader of one topic; `dispatch(msg, replay, now)` as for the online node.
  template <class Message, class Dispatch>
  void subscribe(const std::string& topic, Dispatch dispatch) {
    const std::string name = absolute(topic);
    handlers_[name] = [this, name, dispatch](const rosbag::MessageInstance& m, double now) {
      dispatch(*instantiate<Message>(m, name), *this, now);
    };
  }

  void measurement(Index input, double now, double value, std::optional<double> variance,
                   double stamp) {
    if (core_.addMeasurement(input, now, value, variance, stamp) != Rejection::None) {
      ++summary_.dropped;
    }
  }
  void control(Index index, double value) {
    if (core_.addControl(index, value) != Rejection::None) ++summary_.dropped;
  }

  /// Hands the bag's transforms to `sink`: every /tf_static message before the first message
  /// is replayed (rosbag play latches them, so a listener has them from the start), the /tf
  /// messages in recorded order among the inputs (they do not advance the schedule: online
  /// the tf listener's thread does not either). A bag without these topics is not an error;
  /// the values that then cannot be rotated are the sink's to report.
  void readTransforms(TransformSink sink) { transformSink_ = std::move(sink); }

  /// Replays the whole bag. Throws ReplayError with a one-line reason on failure; outputs are
  /// then not created.
  ReplaySummary run() {
    rosbag::Bag input;
    try {
      input.open(options_.inputBag, rosbag::bagmode::Read);
    } catch (const rosbag::BagException& e) {
      throw ReplayError("cannot read bag " + options_.inputBag + ": " + e.what());
    }
    const std::map<std::string, std::string> recorded = recordedNames(input);
    std::vector<std::string> topics = recordedTopics(recorded);
    std::string tfTopic;  // the bag's name of /tf, if read
    if (transformSink_) {
      if (recorded.count(kTfStatic)) readStaticTransforms(input, recorded.at(kTfStatic));
      if (recorded.count(kTf)) topics.push_back(tfTopic = recorded.at(kTf));
    }

    AtomicOutput csvFile(options_.csvPath), bagFile(options_.outputBag);
    std::ofstream csv;
    if (csvFile.enabled()) {
      csv.open(csvFile.temporary());
      if (!csv) throw ReplayError("cannot write " + csvFile.temporary());
      writeCsvHeader(csv);
    }
    std::optional<rosbag::Bag> output;
    if (bagFile.enabled()) {
      output.emplace();
      try {
        output->open(bagFile.temporary(), rosbag::bagmode::Write);
      } catch (const rosbag::BagException& e) {
        throw ReplayError("cannot write bag " + bagFile.temporary() + ": " + e.what());
      }
    }
    auto write = [&](const typename Core::Estimate& e) {
      ++summary_.estimates;
      if (csv.is_open()) writeCsvRow(csv, e);
      if (output) writeBag(*output, e);
    };
    try {
      rosbag::View view(input, rosbag::TopicQuery(topics));
      for (const rosbag::MessageInstance& m : view) {
        if (!tfTopic.empty() && m.getTopic() == tfTopic) {
          transformSink_(*instantiate<tf2_msgs::TFMessage>(m, kTf), false);
          continue;
        }
        const double now = m.getTime().toSec();
        advanceClock(now, write);
        handlers_.at(absolute(m.getTopic()))(m, now);
        ++summary_.messages;
      }
    } catch (const rosbag::BagException& e) {
      throw ReplayError("bag " + options_.inputBag + " is corrupt or truncated: " + e.what());
    } catch (const ros::Exception& e) {
      throw ReplayError("bag " + options_.inputBag + " could not be decoded: " + e.what());
    }
    if (csv.is_open()) {
      csv.close();
      if (!csv) throw ReplayError("writing " + csvFile.temporary() + " failed");
    }
    if (output) output->close();
    csvFile.commit();
    bagFile.commit();
    summary_.estimatorSeconds = core_.estimatorSeconds();
    return summary_;
  }

  const Core& core() const { return core_; }

 private:
  /// Advances the core's clock to the message time `now` as the online node's ros::Timer
  /// would: the timer estimates every period while rosbag play's clock runs through a gap
  /// between messages, so a gap longer than Options::maxCatchUpPeriods periods (which the
  /// core would skip with one estimate) is crossed in steps of one period less than that,
  /// each estimating every period it ends. Shorter gaps take one step, as before.
  template <class Write>
  void advanceClock(double now, Write& write) {
    if (clockStarted_) {
      const std::uint64_t periods = core_.maxCatchUpPeriods();
      const double step = static_cast<double>(periods > 1 ? periods - 1 : 1) * core_.period();
      while (now - core_.clock() > step) core_.advanceTo(core_.clock() + step, write);
    }
    core_.advanceTo(now, write);
    clockStarted_ = true;
  }

  static typename Core::Options makeOptions(double period) {
    typename Core::Options options;
    options.period = period;
    return options;
  }

  static constexpr const char* kTf = "/tf";
  static constexpr const char* kTfStatic = "/tf_static";

  static std::string absolute(const std::string& topic) {
    return !topic.empty() && topic[0] == '/' ? topic : "/" + topic;
  }

  /// The message of `m`, which was recorded on `topic`; throws if it is of another type.
  template <class Message>
  static boost::shared_ptr<Message> instantiate(const rosbag::MessageInstance& m,
                                                const std::string& topic) {
    auto msg = m.instantiate<Message>();
    if (!msg) {
      throw ReplayError("topic " + topic + " holds " + m.getDataType() + ", expected " +
                        ros::message_traits::DataType<Message>::value());
    }
    return msg;
  }

  /// Absolute topic name -> the bag's name for it (a recorder may have stored names without
  /// the leading slash).
  static std::map<std::string, std::string> recordedNames(rosbag::Bag& bag) {
    std::map<std::string, std::string> recorded;
    rosbag::View all(bag);
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      recorded[absolute(c->topic)] = c->topic;
    }
    return recorded;
  }

  void readStaticTransforms(rosbag::Bag& bag, const std::string& topic) {
    rosbag::View view(bag, rosbag::TopicQuery(topic));
    for (const rosbag::MessageInstance& m : view) {
      transformSink_(*instantiate<tf2_msgs::TFMessage>(m, kTfStatic), true);
    }
  }

  /// The bag's names of the topics the configuration reads; throws when one is missing.
  std::vector<std::string> recordedTopics(
      const std::map<std::string, std::string>& recorded) const {
    std::vector<std::string> topics;
    for (const auto& handler : handlers_) {
      const auto it = recorded.find(handler.first);
      if (it == recorded.end()) {
        throw ReplayError("bag " + options_.inputBag + " has no topic " + handler.first +
                          " that the configuration reads");
      }
      topics.push_back(it->second);
    }
    return topics;
  }

  void writeCsvHeader(std::ofstream& csv) const {
    const Index n = core_.lastEstimate().state.size();
    csv << "time";
    for (Index i = 0; i < n; ++i) csv << ",x" << i;
    for (Index i = 0; i < n; ++i) csv << ",var" << i;
    if (description_.pose) csv << ",pose_x,pose_y,pose_heading";
    csv << ",present_inputs\n";
  }

  void writeCsvRow(std::ofstream& csv, const typename Core::Estimate& e) const {
    const Index n = e.state.size();
    csv << std::setprecision(17) << e.time;
    for (Index i = 0; i < n; ++i) csv << ',' << e.state(i);
    for (Index i = 0; i < n; ++i) csv << ',' << e.covariance(i, i);
    if (description_.pose) {
      const auto& p = *description_.pose;
      csv << ',' << e.state(p[0]) << ',' << e.state(p[1]) << ',' << e.state(p[2]);
    }
    csv << ',' << e.presentInputs << '\n';
  }

  void writeBag(rosbag::Bag& bag, const typename Core::Estimate& e) const {
    const ros::Time stamp(e.time);
    for (const auto& out : description_.outputs) {
      bag.write(absolute(out.first), stamp, makeOutputEntity(e, out.second, options_.frameId));
    }
    bag.write("/" + options_.nodeName + "/state", stamp,
              makeStateEstimate(e, description_.method, options_.frameId));
    if (description_.pose) {
      bag.write("/odometry/filtered", stamp,
                makeOdometry(e, *description_.pose, options_.frameId, options_.childFrameId));
    }
  }

  Core core_;
  NodeDescription description_;
  ReplayOptions options_;
  std::map<std::string, Handler> handlers_;
  TransformSink transformSink_;
  ReplaySummary summary_;
  bool clockStarted_ = false;  ///< the core's clock has had its first reading
};

}  // namespace sf_filter
