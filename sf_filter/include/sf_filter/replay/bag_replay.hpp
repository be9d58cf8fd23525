// Offline replay: reads a bag directly (no ROS master), or several as one recording, feeds its
// messages in recorded-time order through the same fusion core as the online node, and writes the
// estimates as CSV and/or as a bag with the node's own output topics, as fast as the machine
// allows. The recorded time plays the role of the node's clock, so the result is deterministic. A
// node with FRAME_ALIGNED_INPUTS gets the bag's /tf_static and /tf through readTransforms() (see
// replay_frame_aligner.hpp).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2_msgs/TFMessage.h>

#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/replay_clock.hpp"
#include "sf_filter/definition/input_state.hpp"
#include "sf_filter/definition/message_sink.hpp"
#include "sf_filter/definition/node_description.hpp"
#include "sf_filter/io/estimate_writer.hpp"
#include "sf_filter/replay/atomic_output.hpp"
#include "sf_filter/tuning/event_log.hpp"

namespace sf_filter {

struct ReplayOptions {
  /// The bags to replay, read as one recording: their messages merged in recorded-time order
  /// (the parts of a `rosbag record --split`, or topics recorded into separate bags).
  std::vector<std::string> inputBags;
  std::string csvPath;                 ///< empty: no CSV
  std::string outputBag;               ///< empty: no bag
  std::string nodeName = "sf_filter";  ///< namespace of the ~state topic in the output bag
  std::string frameId = "odom";
  std::string childFrameId = "base_link";
  /// A configured topic missing from the bag: an error (false), or a warning, the input then
  /// missing in every period (true; at least one configured topic must be there).
  bool allowMissingTopics = false;
  /// The --params file the caller read ("" for none): no output may replace it either.
  std::string parametersFile;
  /// --smooth: after the forward run, the RTS backward pass of the filter (KF, EKF; the
  /// unscented one for the UKF) over every period; the CSV gets the smoothed columns after the
  /// filtered ones, the output bag the smoothed estimates on odometry/smoothed and
  /// ~state/smoothed beside the filtered ones (doc/smoothing.md).
  bool smooth = false;
  /// --smooth batch (with smooth): the batch MAP track instead of the RTS pass
  /// (batch_period_smoother_of.hpp; KF, EKF, UKF), in the same smoothed columns.
  bool smoothBatch = false;
  /// --smooth-lag SECONDS (0: off): the fixed-lag smoother of that lag, rounded to whole
  /// periods; each CSV row gets the lagged_* columns of its own period, smoothed with the
  /// readings up to the lag later (NaN for the last lag's periods), and the output bag the
  /// smoothed estimates on odometry/smoothed and ~state/smoothed (doc/smoothing.md).
  double smoothLag = 0.0;
};

/// The files a replay reads, which none of its outputs may be (atomic_output.hpp).
inline NamedFiles inputFiles(const ReplayOptions& options) {
  NamedFiles files;
  for (const std::string& bag : options.inputBags) files.emplace_back("bag", bag);
  if (!options.parametersFile.empty()) files.emplace_back("--params file", options.parametersFile);
  return files;
}

/// "a, b, c": the bags or topics of a message.
inline std::string commaSeparated(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& item : items) list += (list.empty() ? "" : ", ") + item;
  return list;
}

struct ReplaySummary {
  std::uint64_t messages = 0;
  std::uint64_t estimates = 0;
  std::uint64_t dropped = 0;
  /// --smooth: the periods smoothed, in how many segments (period_smoother.hpp), the backward
  /// pass's time and the memory per period of the record and its result.
  std::uint64_t smoothedPeriods = 0;
  std::uint64_t smoothedSegments = 0;
  double smoothingSeconds = 0.0;
  std::size_t smoothingBytesPerPeriod = 0;
  /// --smooth batch: its iterations, costs and convergence.
  std::optional<BatchOutcome> batch;
  /// --smooth-lag: the lag in periods, the periods the smoother holds at the end and its
  /// fixed memory.
  std::size_t lagPeriods = 0;
  std::size_t lagPeriodsHeld = 0;
  std::size_t lagBytes = 0;
  /// --smooth, --smooth-lag: how far the smoother moved the filtered means (SmoothingCorrection)
  /// over every smoothed period, and the newest (--smooth-lag: the last period it smoothed).
  SmoothingCorrectionTotal corrections;
  SmoothingCorrection lastCorrection;
};

/// Rotates the vectors of FRAME_ALIGNED_INPUTS offline (replay_frame_aligner.hpp).
class ReplayRotation {
 public:
  virtual ~ReplayRotation() = default;
  virtual std::optional<double> rotated(Index input, const std::string& frame, std::uint32_t sec,
                                        std::uint32_t nsec, const std::array<double, 3>& vector,
                                        int axis) = 0;
};

class BagReplay final : public MessageSink {
 public:
  /// Receives the transforms of one /tf_static (isStatic) or /tf message.
  using TransformSink = std::function<void(const tf2_msgs::TFMessage&, bool isStatic)>;

  /// `engine`: the header's filter in its fusion core (alignment policies, gates, lag).
  BagReplay(std::unique_ptr<FusionEngine> engine, NodeDescription description,
            ReplayOptions options)
      : engine_(std::move(engine)),
        core_(*engine_),
        description_(std::move(description)),
        options_(std::move(options)),
        writer_(description_, OutputFrames{options_.frameId, options_.childFrameId}) {}

  /// Records what the bag's messages give the core into `events` (tuning/event_log.hpp), so
  /// that it can be replayed from memory without the bag.
  void recordEvents(EventLog* events) { events_ = events; }

  /// Registers the reader of one topic, as the online node subscribes it. Throws ReplayError
  /// when another reader's topic is the same (a remap) with another message type.
  void subscribe(const TopicReader& reader) {
    const std::string name = absolute(reader.topic);
    const auto known = expectedTypes_.find(name);
    if (known != expectedTypes_.end()) {
      const std::string clash = topicTypeClash(name, known->second.datatype, reader.datatype);
      if (!clash.empty()) throw ReplayError(clash);
    }
    expectedTypes_[name] = {reader.datatype, reader.md5sum};
    readers_[name].push_back(reader);
  }

  void measurement(Index input, double now, double value, std::optional<double> variance,
                   double stamp) override {
    if (events_) events_->measurement(input, now, value, variance, stamp);
    if (core_.addMeasurement(input, now, value, variance, stamp) != Rejection::None) {
      ++summary_.dropped;
    }
  }
  void measurementBlock(const Index* inputs, const double* values, const double* covariance,
                        int count, double now, double stamp) override {
    if (events_) events_->measurementBlock(inputs, values, covariance, count, now, stamp);
    if (core_.addMeasurementBlock(inputs, values, covariance, count, now, stamp) !=
        Rejection::None) {
      ++summary_.dropped;
    }
  }
  void control(Index index, double value) override {
    if (events_) events_->control(index, value);
    if (core_.addControl(index, value) != Rejection::None) ++summary_.dropped;
  }
  std::optional<double> rotated(Index input, const std::string& frame, std::uint32_t sec,
                                std::uint32_t nsec, const std::array<double, 3>& vector,
                                int axis) override {
    if (!rotation_) return std::nullopt;
    return rotation_->rotated(input, frame, sec, nsec, vector, axis);
  }
  /// The rotation of FRAME_ALIGNED_INPUTS (none without them).
  void setRotation(ReplayRotation* rotation) { rotation_ = rotation; }

  /// Hands the bag's transforms to `sink`: every /tf_static message before the first message
  /// is replayed (rosbag play latches them, so a listener has them from the start), the /tf
  /// messages in recorded order among the inputs (they do not advance the schedule: online
  /// the tf listener's thread does not either). A bag without these topics is not an error;
  /// the values that then cannot be rotated are the sink's to report.
  void readTransforms(TransformSink sink) { transformSink_ = std::move(sink); }

  /// Replays the whole recording. Throws ReplayError with a one-line reason on failure; outputs
  /// are then not created. The bags' topics and types are checked before any output is opened.
  ReplaySummary run() {
    checkOutputs(inputFiles(options_),
                 {{"--csv", options_.csvPath}, {"--bag", options_.outputBag}});
    const std::unique_ptr<PeriodSmoother> smoother = makeSmoother();
    const std::unique_ptr<LaggedSmoother> lagged = makeLaggedSmoother();
    const std::vector<std::unique_ptr<rosbag::Bag>> inputs = openInputs();
    bool readTf = false;
    const std::vector<std::string> topics = topicsToRead(inputs, readTf);

    AtomicOutput csvFile("--csv", options_.csvPath, inputFiles(options_));
    AtomicOutput bagFile("--bag", options_.outputBag, inputFiles(options_));
    std::ofstream csv;
    if (csvFile.enabled()) {
      csv.open(csvFile.temporary());
      if (!csv) throw writeError(csvFile);
      writeCsvHeader(csv);
    }
    OutputBag output;
    if (bagFile.enabled()) {
      writeOutput(bagFile, [&] { output.open(bagFile.temporary()); });
    }
    auto write = [&](const EstimateRef& e) {
      ++summary_.estimates;
      if (smoother) {
        smoother->record();
        rows_.push_back(CsvRow{e.time, e.presentInputs});
      } else if (lagged) {
        holdLagged(*lagged, e, csv, output, bagFile);
        if (csv.is_open() && !csv) throw writeError(csvFile);
      } else if (csv.is_open()) {
        writeCsvRow(csv, e.time, e.state, e.covariance, e.presentInputs);
        if (!csv) throw writeError(csvFile);
      }
      if (output) writeOutput(bagFile, [&] { writeBag(*output, e); });
    };
    readInput([&] { readMessages(inputs, topics, readTf, write); });
    if (smoother) {
      smoothRun(*smoother, csv, csvFile);
      if (output) writeOutput(bagFile, [&] { writeSmoothedBag(*smoother, *output); });
    }
    if (lagged) {
      while (!pending_.empty()) writePending(csv, nullptr);
      if (csv.is_open() && !csv) throw writeError(csvFile);
      summary_.lagPeriodsHeld = lagged->periodsHeld();
      summary_.corrections = lagged->corrections();
      summary_.lastCorrection = lagged->lastCorrection();
    }
    if (csv.is_open()) {
      csv.close();
      if (!csv) throw writeError(csvFile);
    }
    if (output) writeOutput(bagFile, [&] { output.close(); });
    csvFile.commit();
    bagFile.commit();
    return summary_;
  }
  /// What reading the inputs keeps between messages (extractors, GPS datum and counters,
  /// covariance fallbacks), this run's.
  InputState& inputState() { return inputState_; }
  const InputState& inputState() const { return inputState_; }

  const FusionEngine& core() const { return core_; }

 private:
  /// The topics the replay reads, the bags' types checked: the configured ones and, with a
  /// transform sink, /tf (`readTf`); /tf_static is read into the sink here, before the rest.
  std::vector<std::string> topicsToRead(const std::vector<std::unique_ptr<rosbag::Bag>>& inputs,
                                        bool& readTf) {
    const std::map<std::string, Recorded> recorded = readInput([&] { return connections(inputs); });
    checkTypes(recorded);
    std::vector<std::string> topics = recordedTopics(recorded);
    readTf = transformSink_ && recorded.count(kTf);
    if (transformSink_) {
      if (recorded.count(kTfStatic)) {
        readInput([&] { readStaticTransforms(inputs, recorded.at(kTfStatic).names); });
      }
      if (readTf) {
        topics.insert(topics.end(), recorded.at(kTf).names.begin(), recorded.at(kTf).names.end());
      }
    }
    return topics;
  }

  /// The bags' messages on `topics` in recorded order: the clock advanced to each (estimates
  /// to `write`), then the message read; /tf to the transform sink.
  template <class Write>
  void readMessages(const std::vector<std::unique_ptr<rosbag::Bag>>& inputs,
                    const std::vector<std::string>& topics, bool readTf, Write& write) {
    rosbag::View view;
    for (const auto& input : inputs) view.addQuery(*input, rosbag::TopicQuery(topics));
    for (const rosbag::MessageInstance& m : view) {
      if (readTf && absolute(m.getTopic()) == kTf) {
        transformSink_(*instantiate<tf2_msgs::TFMessage>(m, kTf), false);
        continue;
      }
      const double now = m.getTime().toSec();
      if (events_) events_->clock(now);
      clock_.advance(core_, now, write);
      for (const TopicReader& reader : readers_.at(absolute(m.getTopic()))) read(reader, m, now);
      ++summary_.messages;
    }
  }

  /// Hands the serialized message to the topic's reader.
  void read(const TopicReader& reader, const rosbag::MessageInstance& m, double now) {
    buffer_.resize(m.size());
    ros::serialization::OStream stream(buffer_.data(), m.size());
    m.write(stream);
    reader.read(buffer_.data(), m.size(), *this, inputState_, now);
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

  /// A connection's message type, and the bag that holds it.
  struct RecordedType {
    std::string datatype, md5sum, bag;
  };
  /// A topic of the bags: its recorded names (a recorder may have stored names without the
  /// leading slash) and the message types of its connections.
  struct Recorded {
    std::vector<std::string> names;
    std::vector<RecordedType> types;
  };

  /// The output bag. When the replay fails it is abandoned, not closed: closing writes the
  /// bag's index, and if that fails too (the disk is full) rosbag::Bag's destructor would throw
  /// and terminate the program. Its temporary file is removed by its AtomicOutput.
  class OutputBag {
   public:
    OutputBag() = default;
    OutputBag(const OutputBag&) = delete;
    OutputBag& operator=(const OutputBag&) = delete;
    ~OutputBag() {
      if (bag_ && std::uncaught_exceptions() > 0) bag_.release();  // NOLINT: abandoned on purpose
    }
    void open(const std::string& path) {
      bag_ = std::make_unique<rosbag::Bag>();
      bag_->open(path, rosbag::bagmode::Write);
    }
    void close() { bag_->close(); }
    explicit operator bool() const { return bag_ != nullptr; }
    rosbag::Bag& operator*() { return *bag_; }

   private:
    std::unique_ptr<rosbag::Bag> bag_;
  };

  struct ExpectedType {
    std::string datatype, md5sum;
  };

  /// Opens every input bag; refuses one given twice (its messages would be read twice).
  std::vector<std::unique_ptr<rosbag::Bag>> openInputs() const {
    if (options_.inputBags.empty()) throw ReplayError("no input bag");
    std::vector<std::unique_ptr<rosbag::Bag>> bags;
    for (std::size_t k = 0; k < options_.inputBags.size(); ++k) {
      const std::string& path = options_.inputBags[k];
      for (std::size_t j = 0; j < k; ++j) {
        if (sameFile(options_.inputBags[j], path)) {
          throw ReplayError("bag " + path + " is given twice (as " + options_.inputBags[j] + ")");
        }
      }
      bags.push_back(std::make_unique<rosbag::Bag>());
      openInput(*bags.back(), path);
    }
    return bags;
  }

  static void openInput(rosbag::Bag& bag, const std::string& path) {
    if (::access(path.c_str(), R_OK) != 0) {
      throw ReplayError("cannot read bag " + path + ": " + std::strerror(errno));
    }
    try {
      bag.open(path, rosbag::bagmode::Read);
    } catch (const rosbag::BagException& e) {
      throw ReplayError("cannot read bag " + path +
                        " (not a bag, or truncated or corrupt): " + e.what());
    } catch (const std::bad_alloc&) {
      throw ReplayError("cannot read bag " + path + ": corrupt (a record claims more memory " +
                        "than there is)");
    }
  }

  /// "bag A", or "one of the bags A, B" for several: where a read failed (rosbag's merged
  /// view does not say which bag a record came from).
  std::string inputsName() const {
    if (options_.inputBags.size() == 1) return "bag " + options_.inputBags.front();
    return "one of the bags " + commaSeparated(options_.inputBags);
  }

  /// Runs `read` on the input bags; their library's exceptions become a ReplayError naming them.
  template <class Read>
  auto readInput(Read read) const -> decltype(read()) {
    try {
      return read();
    } catch (const rosbag::BagException& e) {
      throw ReplayError(inputsName() + " is corrupt or truncated: " + e.what());
    } catch (const ros::Exception& e) {  // a message that does not deserialise
      throw ReplayError(inputsName() + " is corrupt, a message could not be decoded: " + e.what());
    } catch (const std::bad_alloc&) {
      throw ReplayError(inputsName() + " is corrupt: a record claims more memory than there is");
    }
  }

  /// Runs `write` on an output bag; a failure becomes a ReplayError naming the output.
  template <class Write>
  static void writeOutput(const AtomicOutput& file, Write write) {
    try {
      write();
    } catch (const rosbag::BagException& e) {
      throw ReplayError("cannot write " + file.path() + " (as " + file.temporary() +
                        "): " + e.what());
    }
  }

  static ReplayError writeError(const AtomicOutput& file) {
    return ReplayError("cannot write " + file.path() + " (as " + file.temporary() +
                       "): " + std::strerror(errno));
  }

  /// Absolute topic name -> what the bags hold under it.
  std::map<std::string, Recorded> connections(
      const std::vector<std::unique_ptr<rosbag::Bag>>& bags) const {
    std::map<std::string, Recorded> recorded;
    for (std::size_t k = 0; k < bags.size(); ++k) {
      rosbag::View all(*bags[k]);
      for (const rosbag::ConnectionInfo* c : all.getConnections()) {
        Recorded& r = recorded[absolute(c->topic)];
        if (std::find(r.names.begin(), r.names.end(), c->topic) == r.names.end()) {
          r.names.push_back(c->topic);
        }
        r.types.push_back({c->datatype, c->md5sum, options_.inputBags[k]});
      }
    }
    return recorded;
  }

  /// Every connection of a topic read must hold the message type the configuration expects
  /// (the same name and definition), checked before anything is written.
  void checkTypes(const std::map<std::string, Recorded>& recorded) const {
    std::map<std::string, ExpectedType> expected = expectedTypes_;
    if (transformSink_) {
      const ExpectedType tf{ros::message_traits::DataType<tf2_msgs::TFMessage>::value(),
                            ros::message_traits::MD5Sum<tf2_msgs::TFMessage>::value()};
      expected[kTf] = tf;
      expected[kTfStatic] = tf;
    }
    for (const auto& [topic, type] : expected) {
      const auto it = recorded.find(topic);
      if (it == recorded.end()) continue;
      for (const auto& [datatype, md5sum, bag] : it->second.types) {
        // Another name with the same definition (md5sum) is the same message: tf/tfMessage of
        // a tf1-era recording is tf2_msgs/TFMessage.
        if (datatype != type.datatype && md5sum != type.md5sum) {
          throw ReplayError("bag " + bag + ": topic " + topic + " holds " + datatype +
                            ", the configuration reads " + type.datatype);
        }
        if (md5sum != type.md5sum && md5sum != "*") {
          throw ReplayError("bag " + bag + ": topic " + topic + " holds " + datatype +
                            " of another definition (md5sum " + md5sum + ", this build has " +
                            type.md5sum + ")");
        }
      }
    }
  }

  void readStaticTransforms(const std::vector<std::unique_ptr<rosbag::Bag>>& bags,
                            const std::vector<std::string>& names) {
    rosbag::View view;
    for (const auto& bag : bags) view.addQuery(*bag, rosbag::TopicQuery(names));
    for (const rosbag::MessageInstance& m : view) {
      transformSink_(*instantiate<tf2_msgs::TFMessage>(m, kTfStatic), true);
    }
  }

  /// The bag's names of the topics the configuration reads. A missing one is an error, or
  /// with allowMissingTopics a warning (an error still when none is there).
  std::vector<std::string> recordedTopics(const std::map<std::string, Recorded>& recorded) const {
    std::vector<std::string> topics, missing;
    for (const auto& handler : readers_) {
      const auto it = recorded.find(handler.first);
      if (it == recorded.end()) {
        missing.push_back(handler.first);
      } else {
        topics.insert(topics.end(), it->second.names.begin(), it->second.names.end());
      }
    }
    if (missing.empty()) return topics;
    const std::string bags = commaSeparated(options_.inputBags);
    const std::string what =
        (options_.inputBags.size() == 1 ? "bag " + bags + " has" : "bags " + bags + " have") +
        " no topic " + commaSeparated(missing) + " that the configuration reads";
    if (!options_.allowMissingTopics) {
      throw ReplayError(what + " (--allow-missing-topics replays without it)");
    }
    if (topics.empty()) throw ReplayError(what + ": none of its topics is there");
    std::cerr << "warning: " << what << ": its inputs are missing in every period" << std::endl;
    return topics;
  }

  /// The columns: time, the filtered belief, present_inputs, and with --smooth the smoothed
  /// belief (its names prefixed "smoothed_").
  void writeCsvHeader(std::ofstream& csv) const {
    csv << "time";
    writeCsvNames(csv, "");
    csv << ",present_inputs";
    if (options_.smooth) writeCsvNames(csv, "smoothed_");
    if (options_.smoothLag > 0.0) writeCsvNames(csv, "lagged_");
    csv << '\n';
  }

  void writeCsvNames(std::ofstream& csv, const char* prefix) const {
    const Index n = core_.lastEstimate().state.size();
    for (Index i = 0; i < n; ++i) csv << ',' << prefix << 'x' << i;
    for (Index i = 0; i < n; ++i) csv << ',' << prefix << "var" << i;
    if (description_.pose) {
      csv << ',' << prefix << "pose_x," << prefix << "pose_y," << prefix << "pose_heading";
    }
  }

  void writeCsvRow(std::ofstream& csv, double time, const Eigen::Map<const Eigen::VectorXd>& x,
                   const Eigen::Map<const Eigen::MatrixXd>& P, Index presentInputs,
                   const PeriodBelief* smoothed = nullptr) const {
    csv << std::setprecision(17) << time;
    writeCsvBelief(csv, x, P);
    csv << ',' << presentInputs;
    if (smoothed) writeCsvBelief(csv, smoothed->state, smoothed->covariance);
    csv << '\n';
  }

  void writeCsvBelief(std::ofstream& csv, const Eigen::Map<const Eigen::VectorXd>& x,
                      const Eigen::Map<const Eigen::MatrixXd>& P) const {
    const Index n = x.size();
    for (Index i = 0; i < n; ++i) csv << ',' << x(i);
    for (Index i = 0; i < n; ++i) csv << ',' << P(i, i);
    if (description_.pose) {
      const auto& p = *description_.pose;
      csv << ',' << x(p[0]) << ',' << x(p[1]) << ',' << x(p[2]);
    }
  }

  /// --smooth: the filter's smoother, refused for a filter without one.
  std::unique_ptr<PeriodSmoother> makeSmoother() const {
    if (!options_.smooth) return nullptr;
    std::unique_ptr<PeriodSmoother> smoother =
        options_.smoothBatch ? core_.makeBatchSmoother() : core_.makeSmoother();
    if (!smoother && options_.smoothBatch) {
      throw ReplayError("--smooth batch: the " + core_.filterDescription() +
                        " has no batch smoother (the Kalman, extended and unscented Kalman "
                        "filters have)");
    }
    if (!smoother) {
      throw ReplayError(
          "--smooth: the " + core_.filterDescription() +
          " has no smoother (the Kalman, extended and unscented Kalman filters have)");
    }
    return smoother;
  }

  /// --smooth-lag: the fixed-lag smoother of the lag in whole periods, refused for a filter
  /// without a smoother and beside --smooth (the CSV has room for one smoothed track).
  std::unique_ptr<LaggedSmoother> makeLaggedSmoother() {
    if (!(options_.smoothLag > 0.0)) return nullptr;
    if (options_.smooth) {
      throw ReplayError(
          "--smooth and --smooth-lag: give one (the CSV has room for one "
          "smoothed track; --smooth is the best a recording allows)");
    }
    const auto periods =
        static_cast<std::size_t>(std::llround(options_.smoothLag / core_.period()));
    std::unique_ptr<LaggedSmoother> lagged =
        core_.makeLaggedSmoother(std::max<std::size_t>(1, periods));
    if (!lagged) {
      throw ReplayError(
          "--smooth-lag: the " + core_.filterDescription() +
          " has no smoother (the Kalman, extended and unscented Kalman filters have)");
    }
    summary_.lagPeriods = lagged->lag();
    summary_.lagBytes = lagged->bytes();
    return lagged;
  }

  /// --smooth-lag: holds the period's filtered row until its smoothed belief comes, lag
  /// periods later, and writes the row whose belief the smoother gives now.
  void holdLagged(LaggedSmoother& lagged, const EstimateRef& e, std::ofstream& csv,
                  OutputBag& output, const AtomicOutput& bagFile) {
    pending_.push_back(PendingRow{e.time, e.state, e.covariance, e.presentInputs});
    const std::optional<LaggedBelief> smoothed = lagged.add();
    if (!smoothed) return;
    // The smoother starts anew after a refused period: rows it will not smooth go out bare.
    while (!pending_.empty() && pending_.front().time < smoothed->time) writePending(csv, nullptr);
    if (pending_.empty()) return;
    writePending(csv, &smoothed->belief);
    if (output) {
      const EstimateRef s{smoothed->time,
                          smoothed->belief.state,
                          smoothed->belief.covariance,
                          smoothed->presentInputs,
                          0,
                          false,
                          false};
      BagSink sink{*output, options_.nodeName, ros::Time(s.time)};
      writeOutput(bagFile, [&] { writer_.writeSmoothed(s, true, sink); });
    }
  }

  /// Writes the oldest held row with the smoothed belief of its period (NaN without).
  void writePending(std::ofstream& csv, const PeriodBelief* smoothed) {
    const PendingRow& row = pending_.front();
    if (csv.is_open()) {
      const Eigen::Map<const Eigen::VectorXd> x(row.x.data(), row.x.size());
      const Eigen::Map<const Eigen::MatrixXd> P(row.P.data(), row.P.rows(), row.P.cols());
      if (smoothed) {
        writeCsvRow(csv, row.time, x, P, row.presentInputs, smoothed);
      } else {
        const Eigen::VectorXd nan =
            Eigen::VectorXd::Constant(row.x.size(), std::numeric_limits<double>::quiet_NaN());
        const Eigen::MatrixXd nanP = Eigen::MatrixXd::Constant(
            row.P.rows(), row.P.cols(), std::numeric_limits<double>::quiet_NaN());
        const PeriodBelief none{
            Eigen::Map<const Eigen::VectorXd>(nan.data(), nan.size()),
            Eigen::Map<const Eigen::MatrixXd>(nanP.data(), nanP.rows(), nanP.cols())};
        writeCsvRow(csv, row.time, x, P, row.presentInputs, &none);
      }
    }
    pending_.pop_front();
  }

  /// After the forward run: the backward pass (timed), then the CSV's rows, filtered and
  /// smoothed side by side.
  void smoothRun(PeriodSmoother& smoother, std::ofstream& csv, const AtomicOutput& csvFile) {
    const auto begin = std::chrono::steady_clock::now();
    smoother.smooth();
    summary_.smoothingSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    summary_.smoothedPeriods = smoother.periods();
    summary_.smoothedSegments = smoother.segments();
    summary_.smoothingBytesPerPeriod = smoother.bytesPerPeriod() + sizeof(CsvRow);
    for (std::size_t k = 0; k < smoother.periods(); ++k) {
      summary_.lastCorrection = smoother.correction(k);
      summary_.corrections.add(summary_.lastCorrection);
    }
    summary_.batch = smoother.batchOutcome();
    if (!csv.is_open()) return;
    for (std::size_t k = 0; k < smoother.periods(); ++k) {
      const PeriodBelief filtered = smoother.filtered(k), smoothed = smoother.smoothed(k);
      writeCsvRow(csv, rows_[k].time, filtered.state, filtered.covariance, rows_[k].presentInputs,
                  &smoothed);
      if (!csv) throw writeError(csvFile);
    }
  }

  /// --smooth --bag: each period's smoothed estimate, at its period's time, on the topics of the
  /// fixed-lag one (written after the forward run; a bag's reader orders by time).
  void writeSmoothedBag(const PeriodSmoother& smoother, rosbag::Bag& bag) const {
    for (std::size_t k = 0; k < smoother.periods(); ++k) {
      const PeriodBelief s = smoother.smoothed(k);
      const EstimateRef e{rows_[k].time, s.state, s.covariance, rows_[k].presentInputs, 0,
                          false,         false};
      BagSink sink{bag, options_.nodeName, ros::Time(e.time)};
      writer_.writeSmoothed(e, true, sink);
    }
  }

  /// EstimateWriter's sink offline: each message into the output bag at the estimate's time,
  /// the private ~state under the node's name (--name).
  struct BagSink {
    rosbag::Bag& bag;
    const std::string& nodeName;
    ros::Time stamp;
    template <class Message>
    void operator()(std::size_t, const std::string& topic, OutputScope scope,
                    const Message& m) const {
      bag.write(scope == OutputScope::Private ? "/" + nodeName + "/" + topic : absolute(topic),
                stamp, m);
    }
  };

  /// The estimate's messages as the node publishes them; the robot's motion from the first
  /// period on (the bag is read afterwards, not driven).
  void writeBag(rosbag::Bag& bag, const EstimateRef& e) const {
    BagSink sink{bag, options_.nodeName, ros::Time(e.time)};
    writer_.write(e, true, sink);
  }

  std::unique_ptr<FusionEngine> engine_;
  FusionEngine& core_;
  NodeDescription description_;
  ReplayOptions options_;
  EstimateWriter writer_;
  /// By absolute topic name: one per configured topic that resolves onto it (remaps).
  std::map<std::string, std::vector<TopicReader>> readers_;
  ReplayRotation* rotation_ = nullptr;
  std::vector<std::uint8_t> buffer_;  ///< the message being read, serialized
  InputState inputState_;
  std::map<std::string, ExpectedType> expectedTypes_;
  TransformSink transformSink_;
  ReplaySummary summary_;
  ReplayClock clock_;
  EventLog* events_ = nullptr;
  /// --smooth: what the CSV rows hold besides the beliefs, per period.
  struct CsvRow {
    double time;
    Index presentInputs;
  };
  /// --smooth-lag: a filtered row waiting for its period's smoothed belief.
  struct PendingRow {
    double time;
    Eigen::VectorXd x;
    Eigen::MatrixXd P;
    Index presentInputs;
  };
  std::deque<PendingRow> pending_;
  std::vector<CsvRow> rows_;
};

}  // namespace sf_filter
