// The prebuilt main of every fusion node (runFusionNode, node_definition.hpp): the online
// ROS node, or with --replay the offline bag replay. Compiled once into the node library;
// the translation unit of each configuration header only builds its NodeDefinition.
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/message_traits.h>
#include <ros/ros.h>

#include "sf_filter/definition/node_definition.hpp"
#include "sf_filter/node/frame_aligner.hpp"
#include "sf_filter/node/fusion_node.hpp"
#include "sf_filter/node/gps_parameters.hpp"
#include "sf_filter/node/ros_parameters.hpp"
#include "sf_filter/replay/bag_replay.hpp"
#include "sf_filter/replay/contained_run.hpp"
#include "sf_filter/replay/library_messages.hpp"
#include "sf_filter/replay/replay_frame_aligner.hpp"
#include "sf_filter/replay/yaml_parameters.hpp"

#include <geometry_msgs/TransformStamped.h>
#include <tf2/LinearMath/Quaternion.h>

namespace {

using sf_filter::NodeDefinition;

/// A topic name without its leading '/': the configured and the remapped names compare so.
std::string relativeName(const std::string& topic) {
  return !topic.empty() && topic[0] == '/' ? topic.substr(1) : topic;
}

/// The input names with what FRAME_ALIGNED_INPUTS do to them, for the log and diagnostics.
sf_filter::NodeDescription describe(const NodeDefinition& def, const std::string& baseFrame) {
  sf_filter::NodeDescription d = def.description;
  for (std::size_t i = 0; i < d.inputs.size(); ++i) {
    if (!def.alignedAxis[i].empty()) {
      d.inputs[i] += " rotated into " + baseFrame + ", " + def.alignedAxis[i];
    }
  }
  return d;
}

/// The fusion core's options: the period and the per-input options with the lag [ms]; stamps
/// more than `maxFutureStampMs` ahead of the clock are dropped.
sf_filter::FusionCoreOptions coreOptions(
    double periodMs, std::vector<sf_filter::InputOptions> inputs, double lagMs,
    double maxFutureStampMs = sf_filter::kDefaultMaxFutureStampMs) {
  sf_filter::FusionCoreOptions options;
  options.period = periodMs / 1000.0;
  options.inputs = std::move(inputs);
  options.maxMeasurementLag = lagMs / 1000.0;
  options.maxFutureStamp = maxFutureStampMs / 1000.0;
  return options;
}

/// FRAME_ALIGNED_INPUTS in the replay: the bag's transforms through ReplayFrameAligner.
class ReplayAlignerRotation final : public sf_filter::ReplayRotation {
 public:
  explicit ReplayAlignerRotation(sf_filter::ReplayFrameAligner& aligner) : aligner_(aligner) {}
  std::optional<double> rotated(sf_filter::Index input, const std::string& frame,
                                std::uint32_t sec, std::uint32_t nsec,
                                const std::array<double, 3>& vector, int axis) override {
    return aligner_.align(static_cast<std::size_t>(input), frame, ros::Time(sec, nsec), vector,
                          axis);
  }

 private:
  sf_filter::ReplayFrameAligner& aligner_;
};

/// One line with what became of every input's values, logged by the node at shutdown (the
/// soak test compares `received` with what its driver published).
std::string inputCountersLine(const sf_filter::FusionEngine& core, const std::vector<std::string>& names) {
  std::ostringstream line;
  line << "input counters at shutdown:";
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    line << (i ? ";" : "") << " input " << i << " (" << names.at(static_cast<std::size_t>(i))
         << "): received " << c.received << ", used " << c.used << ", dropped " << c.dropped()
         << ", gated " << c.gated;
  }
  return line.str();
}

/// The input index of a replay option: an integer (its range is checked by the override).
long inputIndex(const std::string& text) {
  std::size_t used = 0;
  long index = -1;
  try {
    index = std::stol(text, &used);
  } catch (const std::logic_error&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw std::invalid_argument("input index '" + text + "' is not an integer");
  }
  return index;
}

/// The replay summary's line per input: what it received, used, dropped (by reason), gated.
void printInputCounters(const std::string& name, const sf_filter::FusionEngine& core) {
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    std::cout << name << ": input " << i << ": " << c.received << " received, " << c.used
              << " used, dropped: " << sf_filter::dropReasons(c) << ", " << c.gated << " gated, "
              << c.timedOutPeriods << " periods timed out" << std::endl;
  }
}

/// The GPS inputs' fixes without a valid status and unknown covariances (for the inputs that
/// received a fix).
void printGpsCounters(const std::string& name, const sf_filter::MessageSink& sink,
                      const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!sink.gps().receivedFix(i)) continue;
    const auto input = static_cast<sf_filter::Index>(i);
    std::cout << name << ": input " << i << " (GPS): " << sink.gps().noFix(i)
              << " fixes dropped without a fix (status < STATUS_FIX), "
              << sink.covarianceFallbacks(input) << " with an unknown covariance (header R used)"
              << std::endl;
  }
}

/// Offline replay: `<node> --replay in.bag [--csv out.csv] [--bag out.bag] [options]`.
int replayMain(int argc, char** argv, const NodeDefinition& def) {
  const std::string program = argv[0];
  const std::string usage =
      "usage: " + program +
      " --replay INPUT.bag [--csv OUT.csv] [--bag OUT.bag] [--name NODE]\n"
      "       [--estimation-period S | --estimation-period-ms MS] [--scale-q FACTOR]\n"
      "       [--scale-r FACTOR] [--seed N] [--strict]\n"
      "       [--frame-id FRAME] [--child-frame-id FRAME] [--base-frame FRAME]\n"
      "       [--align INPUT=POLICY]... [--gate INPUT=THRESHOLD]... [--align-by-stamp INPUT]...\n"
      "       [--align-by-arrival INPUT]... [--max-lag S] [--allow-missing-topics]\n"
      "       [--params FILE.yaml] [FROM:=TO]...\n"
      "       [--static-transform X Y Z YAW PITCH ROLL PARENT CHILD]...\n"
      "Replays the bag through this node's filter without a ROS master, in recorded-time\n"
      "order, and writes the estimates. Without --csv and --bag only a summary is printed.\n"
      "--frame-id, --child-frame-id: frames of the output bag's odometry (default odom,\n"
      "base_link, like the node's ~frame_id, ~child_frame_id); --base-frame: the frame\n"
      "FRAME_ALIGNED_INPUTS are rotated into (default BASE_FRAME, like ~base_frame), with\n"
      "the bag's /tf_static and /tf. --allow-missing-topics: a configured topic missing from\n"
      "the bag is a warning (its inputs are missing in every period), not an error.\n"
      "Times in seconds like the node's parameters (--estimation-period 0.01: 10 ms;\n"
      "--estimation-period-ms 10 is the same). --strict: exit status 1 if a step failed,\n"
      "the filter was reset or a value was dropped. --params: the node's private parameters from a "
      "YAML file\n"
      "(as rosparam load takes it), parsed and checked as the node does; options given\n"
      "here override it. FROM:=TO reads the configured topic FROM from the bag's topic TO.\n"
      "--static-transform: a transform as static_transform_publisher takes it (metres,\n"
      "radians), for a bag without /tf_static.\n"
      "POLICY: AVERAGE, LAST, SAMPLED, 'HOLD LAGRANGE|BEZIER|TAYLOR ORDER [VARIANCE]' or\n"
      "'FILL OMEGA N [VARIANCE]'; THRESHOLD 0 removes a gate (doc/alignment_policies.md).";
  sf_filter::ReplayOptions options;
  options.nodeName = program.substr(program.find_last_of('/') + 1);
  double periodMs = def.estimationPeriodMs, scaleQ = 1.0, scaleR = 1.0;
  double lagMs = def.maxMeasurementLagMs;
  bool strict = false;
  std::optional<long> seed;
  std::string baseFrame = def.baseFrame;
  std::vector<sf_filter::InputOptions> inputs = def.inputOptions;
  const sf_filter::InputCapabilities& can = def.capabilities;
  std::optional<sf_filter::YamlParameterSource> params;
  sf_filter::gps::GpsOptions gpsOptions;  // ~datum, ~gps_yaw_offset of --params
  std::optional<double> periodOverrideMs;
  std::optional<sf_filter::FilterParameters> fileParameters;
  double maxFutureStampMs = sf_filter::kDefaultMaxFutureStampMs;
  std::map<std::string, std::string> remaps;
  std::vector<geometry_msgs::TransformStamped> staticTransforms;
  try {
    // --params first: the options override the file whatever their order.
    for (int i = 1; i + 1 < argc; ++i) {
      if (std::string(argv[i]) != "--params") continue;
      if (params) throw std::invalid_argument("--params given twice");
      params.emplace(argv[i + 1]);
      for (const std::string& line : sf_filter::unknownParameterWarnings(*params)) {
        std::cerr << program << ": warning: --params " << argv[i + 1] << ": " << line << std::endl;
      }
      periodMs = sf_filter::loadPeriodMs(*params, periodMs);
      sf_filter::loadInputParameters(*params, inputs, lagMs, can);
      maxFutureStampMs = sf_filter::loadFaultParameters(*params, inputs, can).maxFutureStampMs;
      const sf_filter::OutputSettings out = sf_filter::loadOutputParameters(*params);
      options.frameId = out.frameId;
      options.childFrameId = out.childFrameId;
      baseFrame = sf_filter::detail::frameParameter(*params, "base_frame", baseFrame);
      gpsOptions = sf_filter::loadGpsParameters(*params);
    }
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument("option " + arg + " needs a value");
        return argv[++i];
      };
      const std::size_t remap = arg.find(":=");
      if (remap != std::string::npos && remap > 0 && arg[0] != '_') {
        remaps[relativeName(arg.substr(0, remap))] = arg.substr(remap + 2);
        continue;
      }
      if (arg == "--help") {
        std::cout << usage << std::endl;
        return EXIT_SUCCESS;
      } else if (arg == "--replay") {
        options.inputBag = value();
      } else if (arg == "--csv") {
        options.csvPath = value();
      } else if (arg == "--bag") {
        options.outputBag = value();
      } else if (arg == "--params") {
        value();  // read above
      } else if (arg == "--static-transform") {
        if (i + 8 >= argc) {
          throw std::invalid_argument("--static-transform needs X Y Z YAW PITCH ROLL PARENT CHILD");
        }
        double v[6];
        for (double& x : v) {
          x = std::stod(argv[++i]);
          if (!std::isfinite(x)) throw std::invalid_argument("--static-transform: not finite");
        }
        geometry_msgs::TransformStamped t;
        t.header.frame_id = argv[++i];
        t.child_frame_id = argv[++i];
        t.transform.translation.x = v[0];
        t.transform.translation.y = v[1];
        t.transform.translation.z = v[2];
        tf2::Quaternion q;
        q.setRPY(v[5], v[4], v[3]);
        t.transform.rotation.x = q.x();
        t.transform.rotation.y = q.y();
        t.transform.rotation.z = q.z();
        t.transform.rotation.w = q.w();
        staticTransforms.push_back(t);
      } else if (arg == "--name") {
        options.nodeName = value();
      } else if (arg == "--estimation-period") {
        periodMs = sf_filter::secondsToMs("--estimation-period", std::stod(value()),
                                          sf_filter::kMinPeriodSeconds,
                                          sf_filter::kMaxPeriodSeconds, false);
        periodOverrideMs = periodMs;
      } else if (arg == "--estimation-period-ms") {
        periodMs = sf_filter::secondsToMs("--estimation-period-ms", std::stod(value()) / 1000.0,
                                          sf_filter::kMinPeriodSeconds,
                                          sf_filter::kMaxPeriodSeconds, false);
        periodOverrideMs = periodMs;
      } else if (arg == "--strict") {
        strict = true;
      } else if (arg == "--scale-q") {
        scaleQ = std::stod(value());
      } else if (arg == "--scale-r") {
        scaleR = std::stod(value());
      } else if (arg == "--seed") {
        seed = std::stol(value());
      } else if (arg == "--frame-id") {
        options.frameId = value();
      } else if (arg == "--child-frame-id") {
        options.childFrameId = value();
      } else if (arg == "--base-frame") {
        baseFrame = value();
      } else if (arg == "--align" || arg == "--gate") {
        const std::string given = value();
        const std::size_t equals = given.find('=');
        if (equals == std::string::npos) {
          throw std::invalid_argument(arg + " " + given + ": expected INPUT=" +
                                      (arg == "--align" ? "POLICY" : "THRESHOLD"));
        }
        try {
          const long input = inputIndex(given.substr(0, equals));
          if (arg == "--align") {
            sf_filter::overrideAlignment(inputs, input, given.substr(equals + 1), can);
          } else {
            sf_filter::overrideGate(inputs, input, std::stod(given.substr(equals + 1)), can);
          }
        } catch (const std::logic_error& e) {  // invalid_argument and stod's out_of_range
          throw std::invalid_argument(arg + " " + given + ": " + e.what());
        }
      } else if (arg == "--align-by-stamp" || arg == "--align-by-arrival") {
        const std::string given = value();
        try {
          sf_filter::overrideAlignByStamp(inputs, inputIndex(given), arg == "--align-by-stamp",
                                          can);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(arg + " " + given + ": " + e.what());
        }
      } else if (arg == "--allow-missing-topics") {
        options.allowMissingTopics = true;
      } else if (arg == "--max-lag") {
        lagMs = sf_filter::checkedLagMs(sf_filter::secondsToMs("--max-lag", std::stod(value()), 0.0,
                                                               sf_filter::kMaxLagSeconds, true));
      } else {
        throw std::invalid_argument("unknown option " + arg);
      }
    }

    if (!(scaleQ > 0.0) || !(scaleR > 0.0))
      throw std::invalid_argument("scale factors must be positive");
    if (seed && *seed < 0) throw std::invalid_argument("--seed must not be negative");
    // With --params: the file's Q, R, x0, P0, ... through the node's own parsing, the
    // header's entries evaluated for the final period (an option overrides the file's).
    if (params) {
      fileParameters = sf_filter::loadParameters<sf_filter::FilterParameters>(
          *params, [&](double) { return def.defaultParameters(periodMs); },
          periodOverrideMs.value_or(periodMs));
    }
    if (!staticTransforms.empty() && !def.frameAlignment) {
      throw std::invalid_argument("--static-transform: this node has no FRAME_ALIGNED_INPUTS");
    }
    for (const auto& [from, to] : remaps) {
      bool known = false;
      for (const sf_filter::TopicReader& reader : def.topics) {
        known = known || relativeName(reader.topic) == from;
      }
      if (!known) throw std::invalid_argument(from + ":=" + to + ": no configured topic " + from);
    }
    if (def.frameAlignment && (baseFrame.empty() || baseFrame.front() == '/')) {
      throw std::invalid_argument("--base-frame '" + baseFrame +
                                  "' is not a tf2 frame name (not empty, no leading '/')");
    }
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n" << usage << std::endl;
    return 2;
  }
  // In a child process: a library crashing on a corrupt bag, or an interrupt, still ends
  // with one line and without partial outputs (contained_run.hpp).
  auto replayBag = [&]() -> int {
    static sf_filter::ReplayLibraryMessages libraryMessages(program);
    console_bridge::useOutputHandler(&libraryMessages);
    try {
      ros::Time::init();
      sf_filter::FilterParameters parameters =
          fileParameters ? *fileParameters : def.defaultParameters(periodMs);
      parameters.process_noise_covariance *= scaleQ;
      parameters.measurement_noise_covariance *= scaleR;
      if (seed) parameters.random_seed = static_cast<unsigned>(*seed);
      std::optional<sf_filter::ReplayFrameAligner> aligner;
      if (def.frameAlignment) aligner.emplace(baseFrame, def.description.inputs);
      std::optional<ReplayAlignerRotation> rotation;
      sf_filter::BagReplay replay(
          def.makeEngine(parameters, coreOptions(periodMs, inputs, lagMs, maxFutureStampMs)),
          describe(def, baseFrame), options);
      if (aligner) {
        rotation.emplace(*aligner);
        replay.setRotation(&*rotation);
        replay.readTransforms([&aligner](const tf2_msgs::TFMessage& msg, bool isStatic) {
          aligner->addTransforms(msg, isStatic);
        });
        if (!staticTransforms.empty()) {
          tf2_msgs::TFMessage given;
          given.transforms = staticTransforms;
          aligner->addTransforms(given, true);
        }
      }
      replay.gps().setOptions(gpsOptions);
      for (sf_filter::TopicReader reader : def.topics) {
        const auto remapped = remaps.find(relativeName(reader.topic));
        if (remapped != remaps.end()) reader.topic = remapped->second;
        replay.subscribe(reader);
      }
      const auto start = std::chrono::steady_clock::now();
      const sf_filter::ReplaySummary s = replay.run();
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::uint64_t gated = 0, late = 0, substituted = 0;
      for (sf_filter::Index i = 0; i < replay.core().inputCount(); ++i) {
        gated += replay.core().counters(i).gated;
        late += replay.core().counters(i).late;
        substituted += replay.core().counters(i).substituted;
      }
      const std::uint64_t failures = replay.core().estimationFailures();
      const std::uint64_t resets = replay.core().filterResets();
      const std::uint64_t unrotated = aligner ? aligner->droppedTotal() : 0;
      std::cout << options.nodeName << ": " << s.messages << " messages, " << s.estimates
                << " estimates, " << failures << " failed steps, " << resets << " filter resets, "
                << s.skippedGaps << " gaps skipped, " << s.dropped << " dropped values (" << late
                << " late), " << gated << " gated, " << substituted << " substitutes, "
                << (s.estimates ? 1e6 * s.estimatorSeconds / static_cast<double>(s.estimates) : 0.0)
                << " us per estimation step, " << wall << " s in all" << std::endl;
      printInputCounters(options.nodeName, replay.core());
      printGpsCounters(options.nodeName, replay, def.description.inputs);
      if (aligner) {
        std::cout << options.nodeName << ": " << aligner->transforms()
                  << " transforms read from the bag's /tf_static and /tf ("
                  << aligner->rejectedTransforms() << " refused by tf2), "
                  << aligner->droppedTotal() << " values dropped: not rotatable into '"
                  << aligner->baseFrame() << "'" << std::endl;
      }
      if (strict && (failures > 0 || resets > 0 || s.dropped > 0 || unrotated > 0)) {
        std::cerr << program << ": --strict: " << failures << " failed steps, " << resets
                  << " filter resets, " << s.dropped + unrotated << " dropped values" << std::endl;
        return EXIT_FAILURE;
      }
    } catch (const std::exception& e) {
      std::cerr << program << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  };
  return sf_filter::runContained(replayBag, [&](int signal) {
    for (const std::string& path : {options.csvPath, options.outputBag}) {
      if (!path.empty()) std::remove(sf_filter::partialPath(path).c_str());
    }
    if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP) {
      std::cerr << program << ": interrupted (" << strsignal(signal) << "), no output written"
                << std::endl;
    } else {
      std::cerr << program << ": reading bag " << options.inputBag << " crashed the bag library ("
                << strsignal(signal) << "): the bag is corrupt; no output written" << std::endl;
    }
  });
}

/// The online node. Everything from reading the parameters to the first estimate's timer is
/// start-up: any exception there is the one-line refusal of doc/filter_node.md, exit status 1.
int nodeMain(int argc, char** argv, const NodeDefinition& def) {
  ros::init(argc, argv, "sf_filter");
  std::optional<ros::NodeHandle> nh, pnh;
  std::optional<sf_filter::FrameAligner> aligner;  // outlives the node's subscriptions
  std::optional<sf_filter::FusionNode> node;
  try {
    nh.emplace();
    pnh.emplace("~");
    const sf_filter::RosParameterSource params(*pnh);
    for (const std::string& line : sf_filter::unknownParameterWarnings(params)) {
      ROS_WARN("%s", line.c_str());
    }
    if (def.frameAlignment) aligner.emplace(params, def.baseFrame, def.description.inputs);
    const sf_filter::FilterParameters parameters =
        sf_filter::loadParameters<sf_filter::FilterParameters>(params, def.defaultParameters,
                                                               def.estimationPeriodMs);
    std::vector<sf_filter::InputOptions> inputs = def.inputOptions;
    double lagMs = def.maxMeasurementLagMs;
    sf_filter::loadInputParameters(params, inputs, lagMs, def.capabilities);
    const sf_filter::FaultSettings faults =
        sf_filter::loadFaultParameters(params, inputs, def.capabilities);
    auto options =
        coreOptions(parameters.estimation_period_ms, inputs, lagMs, faults.maxFutureStampMs);
    options.nisWindow = static_cast<std::size_t>(faults.nisWindow);
    const std::string baseFrame = aligner ? aligner->baseFrame() : def.baseFrame;
    node.emplace(*nh, *pnh, def.makeEngine(parameters, options), describe(def, baseFrame),
                 aligner ? &*aligner : nullptr, faults.diagnosticPeriod,
                 sf_filter::loadOutputParameters(params));
    node->gps().setOptions(sf_filter::loadGpsParameters(params));
    for (const sf_filter::TopicReader& reader : def.topics) node->subscribe(reader);
    node->start();
  } catch (const std::exception& e) {
    ROS_FATAL("%s: refusing to start: %s", ros::this_node::getName().c_str(), e.what());
    return EXIT_FAILURE;
  }
  ros::spin();
  // On stdout: ros::shutdown() has ended rosconsole, so ROS_INFO would print nothing now.
  std::cout << ros::this_node::getName() << ": "
            << inputCountersLine(node->core(), def.description.inputs) << std::endl;
  return EXIT_SUCCESS;
}

}  // namespace

int sf_filter::runFusionNode(int argc, char** argv, const NodeDefinition& def) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--replay" || std::string(argv[i]) == "--help") {
      return replayMain(argc, argv, def);
    }
  }
  return nodeMain(argc, argv, def);
}
