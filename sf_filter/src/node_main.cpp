// The prebuilt main of every fusion node (runFusionNode, node_definition.hpp): the online
// ROS node, or with --replay the offline bag replay. Compiled once into the node library;
// the translation unit of each configuration header only builds its NodeDefinition.
#include <algorithm>
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
#include "sf_filter/node/extractor_parameters.hpp"
#include "sf_filter/node/frame_aligner.hpp"
#include "sf_filter/node/fusion_node.hpp"
#include "sf_filter/node/fusion_node_instance.hpp"
#include "sf_filter/node/gps_parameters.hpp"
#include "sf_filter/node/ros_parameters.hpp"
#include "sf_filter/replay/bag_replay.hpp"
#include "sf_filter/replay/contained_run.hpp"
#include "sf_filter/replay/library_messages.hpp"
#include "sf_filter/replay/nis_report.hpp"
#include "sf_filter/replay/replay_frame_aligner.hpp"
#include "sf_filter/replay/yaml_parameters.hpp"
#include "sf_filter/tuning/event_log.hpp"
#include "sf_filter/tuning/noise_tuning.hpp"
#include "sf_filter/tuning/tuned_parameters_file.hpp"

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
  std::optional<double> rotated(sf_filter::Index input, const std::string& frame, std::uint32_t sec,
                                std::uint32_t nsec, const std::array<double, 3>& vector,
                                int axis) override {
    return aligner_.align(static_cast<std::size_t>(input), frame, ros::Time(sec, nsec), vector,
                          axis);
  }

 private:
  sf_filter::ReplayFrameAligner& aligner_;
};

/// One line with what became of every input's values, logged by the node at shutdown (the
/// soak test compares `received` with what its driver published).
std::string inputCountersLine(const sf_filter::FusionEngine& core,
                              const std::vector<std::string>& names) {
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

/// The number of option `option`, all of `text`; a clear error otherwise.
double numberOption(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::logic_error&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw std::invalid_argument(option + " '" + text + "' is not a finite number");
  }
  return value;
}

/// The replay summary's line per input: what it received, used, dropped (by reason), gated,
/// the stamp-to-arrival delays; and for an input with late values, why and the lag to set.
void printInputCounters(const std::string& name, const sf_filter::FusionEngine& core,
                        const std::vector<std::string>& inputs) {
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const sf_filter::InputCounters& c = core.counters(i);
    std::cout << name << ": input " << i << ": " << c.received << " received, " << c.used
              << " used, dropped: " << sf_filter::dropReasons(c) << ", " << c.gated << " gated, "
              << c.timedOutPeriods << " periods timed out, stamp-to-arrival delay "
              << sf_filter::delayFigures(c.delays) << std::endl;
  }
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    const auto index = static_cast<std::size_t>(i);
    if (core.counters(i).late == 0) continue;
    std::cout << name << ": "
              << sf_filter::lateAdvice(index, inputs.at(index), core.counters(i),
                                       core.maxMeasurementLag(), "--max-lag (~max_measurement_lag)")
              << std::endl;
  }
}

/// The replay's NIS lines: all inputs together, then each input (nis_report.hpp).
void printNis(const std::string& name, const sf_filter::FusionEngine& core,
              const std::vector<std::string>& inputs) {
  const sf_filter::InnovationRecord& r = core.innovations();
  sf_filter::printNisLine(std::cout, name, "all inputs", r.overall());
  for (sf_filter::Index i = 0; i < core.inputCount(); ++i) {
    sf_filter::printNisLine(
        std::cout, name,
        "input " + std::to_string(i) + " (" + inputs.at(static_cast<std::size_t>(i)) + ")",
        r.input(static_cast<std::size_t>(i)));
  }
  std::cout << std::flush;
}

/// --tune after the first replay of the bag (recorded in `events`): the prediction-error
/// identification of the free entries, its report, the tuned replay's NIS and the YAML file
/// `out` (if enabled). Throws ReplayError, writing nothing, when the bag identifies nothing.
int tuneFromEvents(const std::string& name, const NodeDefinition& def,
                   const sf_filter::EventLog& events, const sf_filter::EngineMaker& makeEngine,
                   const sf_filter::FilterParameters& start,
                   const std::vector<sf_filter::FreeEntry>& free,
                   const sf_filter::TuningOptions& tuning, sf_filter::AtomicOutput& out,
                   const std::string& baseParams, double periodMs, int argc, char** argv) {
  const auto begin = std::chrono::steady_clock::now();
  const sf_filter::TuningResult r = sf_filter::tuneNoise(events, makeEngine, start, free, tuning);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::printf(
      "%s: --tune: %d replays of %zu recorded events in %.3g s (%.3g ms each); stopped: "
      "%s\n",
      name.c_str(), r.evaluations, events.size(), wall, 1e3 * wall / std::max(1, r.evaluations),
      r.stop.c_str());
  std::printf("%s: --tune: prediction-error cost sum(log det S + NIS): start %.10g, tuned %.10g\n",
              name.c_str(), r.startCost, r.cost);
  auto entry = [](const sf_filter::FilterParameters& p, const sf_filter::FreeEntry& e) {
    const Eigen::MatrixXd& m = e.matrix == "Q"   ? p.process_noise_covariance
                               : e.matrix == "R" ? p.measurement_noise_covariance
                                                 : p.initial_error_covariance;
    return m(e.index, e.index);
  };
  for (std::size_t k = 0; k < free.size(); ++k) {
    std::printf("%s: --tune: %-6s start %-12.6g tuned %-12.6g (x %.4g)%s\n", name.c_str(),
                free[k].name().c_str(), entry(start, free[k]), entry(r.tuned, free[k]),
                r.factors[k],
                r.atBound[k] ? "  at the bound of --tune-range: not identified by this bag" : "");
  }
  const std::string refusal = sf_filter::identificationRefusal(r);
  if (!refusal.empty()) {
    throw sf_filter::ReplayError("--tune: " + refusal + (out.enabled() ? "; nothing written" : ""));
  }
  std::unique_ptr<sf_filter::FusionEngine> tuned = makeEngine(r.tuned);
  auto ignore = [](const sf_filter::EstimateRef&) {};
  events.replay(*tuned, ignore);
  printNis(name + " (tuned)", *tuned, def.description.inputs);
  if (out.enabled()) {
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    char costs[160];
    std::snprintf(costs, sizeof costs,
                  "sum(log det S + NIS): start %.10g, tuned %.10g (%d replays)", r.startCost,
                  r.cost, r.evaluations);
    out.write(sf_filter::tunedParametersYaml(
        {"Noise identified by the prediction-error method (doc/tuning.md):", command, costs,
         "Load it into the node (rosparam load, filter.launch params:=) or the replay (--params)."},
        r.tuned, free, periodMs / 1000.0, baseParams));
    std::printf("%s: --tune: wrote %s\n", name.c_str(), out.path().c_str());
  }
  return EXIT_SUCCESS;
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
              << sink.gps().implausibleFixes(i) << " dropped as not on the Earth"
              << (sink.gps().implausibleFixes(i)
                      ? " (newest: " + sink.gps().implausibleReason(i) + ")"
                      : std::string())
              << ", " << sink.covarianceFallbacks(input)
              << " with an unknown covariance (header R used)" << std::endl;
  }
}

/// Offline replay: `<node> --replay in.bag [more.bag...] [--csv out.csv] [--bag out.bag]
/// [options]`.
int replayMain(int argc, char** argv, const NodeDefinition& def) {
  const std::string program = argv[0];
  const std::string usage =
      "usage: " + program +
      " --replay INPUT.bag [INPUT.bag]... [--csv OUT.csv] [--bag OUT.bag] [--smooth]\n"
      "       [--name NODE]\n"
      "       [--estimation-period S | --estimation-period-ms MS] [--scale-q FACTOR]\n"
      "       [--scale-r FACTOR] [--seed N] [--strict]\n"
      "       [--frame-id FRAME] [--child-frame-id FRAME] [--base-frame FRAME]\n"
      "       [--align INPUT=POLICY]... [--gate INPUT=THRESHOLD]... [--align-by-stamp INPUT]...\n"
      "       [--align-by-arrival INPUT]... [--max-lag S] [--allow-missing-topics]\n"
      "       [--params FILE.yaml] [FROM:=TO]...\n"
      "       [--static-transform X Y Z YAW PITCH ROLL PARENT CHILD]...\n"
      "   or: " +
      program +
      " --tune INPUT.bag [INPUT.bag]... [--free LIST] [--out TUNED.yaml]\n"
      "       [--tune-range F] [--max-evaluations N] [the replay's options but --csv, --bag]\n"
      "Replays the bag through this node's filter without a ROS master, in recorded-time\n"
      "order, and writes the estimates. Without --csv and --bag only a summary is printed.\n"
      "Several bags are one recording: their messages are merged in recorded-time order\n"
      "(the parts of rosbag record --split, or topics recorded into separate bags).\n"
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
      "--smooth: after the replay, the Rauch-Tung-Striebel backward pass over every period\n"
      "(KF, EKF; the unscented one for a UKF); the CSV gets smoothed_* columns after the\n"
      "filtered ones (doc/smoothing.md).\n"
      "POLICY: AVERAGE, LAST, SAMPLED, 'HOLD LAGRANGE|BEZIER|TAYLOR ORDER [VARIANCE]' or\n"
      "'FILL OMEGA N [VARIANCE]'; THRESHOLD 0 removes a gate (doc/alignment_policies.md).\n"
      "INPUT: the input's index, or its record name in a header with INPUTS records.\n"
      "--tune: identifies the free noise entries from the bag by the prediction-error method\n"
      "(minimum of sum(log det S + NIS) over in-memory replays; KF, EKF, UKF) and writes them\n"
      "with --out as a YAML file of private parameters for the node and --params\n"
      "(doc/tuning.md). LIST: comma-separated Q, R, P0 (their non-zero diagonal entries) or\n"
      "Q.i, R.i, P0.i; default Q,R. --tune-range F: each variance within a factor F of its\n"
      "start (default 1000); --max-evaluations N: replays at most (default 2000).";
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
  std::string paramsPath;
  sf_filter::gps::GpsOptions gpsOptions;  // ~datum, ~gps_yaw_offset of --params
  sf_config::extractors::ParameterValues extractorParameters;  // e.g. ~magnetic_declination
  std::optional<double> periodOverrideMs;
  std::optional<sf_filter::FilterParameters> fileParameters;
  double maxFutureStampMs = sf_filter::kDefaultMaxFutureStampMs;
  sf_filter::FaultSettings nis;  // ~nis_window, ~nis_tolerance, as the node's
  std::map<std::string, std::string> remaps;
  std::vector<geometry_msgs::TransformStamped> staticTransforms;
  bool tune = false;
  std::string freeList = "Q,R", tunedPath;
  sf_filter::TuningOptions tuning;
  std::vector<sf_filter::FreeEntry> freeEntries;
  try {
    // --params first: the options override the file whatever their order.
    for (int i = 1; i + 1 < argc; ++i) {
      if (std::string(argv[i]) != "--params") continue;
      if (params) throw std::invalid_argument("--params given twice");
      paramsPath = argv[i + 1];
      options.parametersFile = paramsPath;
      params.emplace(paramsPath);
      for (const std::string& line : sf_filter::unknownParameterWarnings(
               *params, sf_filter::extractorParameterNames(def.extractorParameters))) {
        std::cerr << program << ": warning: --params " << argv[i + 1] << ": " << line << std::endl;
      }
      periodMs = sf_filter::loadPeriodMs(*params, periodMs);
      sf_filter::loadInputParameters(*params, inputs, lagMs, can);
      const sf_filter::FaultSettings faults = sf_filter::loadFaultParameters(*params, inputs, can);
      maxFutureStampMs = faults.maxFutureStampMs;
      nis = faults;
      const sf_filter::OutputSettings out = sf_filter::loadOutputParameters(*params);
      options.frameId = out.frameId;
      options.childFrameId = out.childFrameId;
      baseFrame = sf_filter::detail::frameParameter(*params, "base_frame", baseFrame);
      gpsOptions = sf_filter::loadGpsParameters(*params);
      extractorParameters = sf_filter::loadExtractorParameters(*params, def.extractorParameters);
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
      } else if (arg == "--replay" || arg == "--tune") {
        if (!options.inputBags.empty()) {
          throw std::invalid_argument(arg + ": the bags are given once, after --replay or --tune");
        }
        // the bags: the value, and every following argument up to the next option or remap
        options.inputBags.push_back(value());
        while (i + 1 < argc && argv[i + 1][0] != '-' &&
               std::string(argv[i + 1]).find(":=") == std::string::npos) {
          options.inputBags.push_back(argv[++i]);
        }
        tune = tune || arg == "--tune";
      } else if (arg == "--free") {
        freeList = value();
      } else if (arg == "--out") {
        tunedPath = value();
      } else if (arg == "--tune-range") {
        tuning.range = numberOption(arg, value());
      } else if (arg == "--max-evaluations") {
        const double n = numberOption(arg, value());
        if (n != std::floor(n) || n < 1 || n > 1e9) {
          throw std::invalid_argument("--max-evaluations must be a whole number from 1 to 1e9");
        }
        tuning.maxEvaluations = static_cast<int>(n);
      } else if (arg == "--csv") {
        options.csvPath = value();
      } else if (arg == "--bag") {
        options.outputBag = value();
      } else if (arg == "--smooth") {
        options.smooth = true;
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
          const long input = sf_filter::inputIndexOf(given.substr(0, equals), can);
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
          sf_filter::overrideAlignByStamp(inputs, sf_filter::inputIndexOf(given, can),
                                          arg == "--align-by-stamp", can);
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
    if (tune) {
      const std::string refusal = sf_filter::tuningRefusal(def.description.method);
      if (!refusal.empty()) throw std::invalid_argument("--tune: " + refusal);
      if (!options.csvPath.empty() || !options.outputBag.empty()) {
        throw std::invalid_argument(
            "--tune writes no estimates (--csv, --bag): replay with --params TUNED.yaml for them");
      }
      if (!(tuning.range > 1.0) || !std::isfinite(tuning.range)) {
        throw std::invalid_argument("--tune-range must be a finite factor above 1");
      }
      if (tuning.maxEvaluations < 1) throw std::invalid_argument("--max-evaluations must be >= 1");
      sf_filter::FilterParameters start =
          fileParameters ? *fileParameters : def.defaultParameters(periodMs);
      freeEntries = sf_filter::parseFreeEntries(freeList, start);
    } else if (freeList != "Q,R" || !tunedPath.empty()) {
      throw std::invalid_argument("--free and --out belong to --tune");
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
      sf_filter::FusionCoreOptions engineOptions =
          coreOptions(periodMs, inputs, lagMs, maxFutureStampMs);
      engineOptions.nisWindow = sf_filter::nisWindowPeriods(nis, periodMs);
      engineOptions.nisTolerance = nis.nisTolerance;
      sf_filter::EventLog events;
      // --tune's --out, checked like --csv and --bag before anything is read
      sf_filter::AtomicOutput tunedFile("--out", tunedPath, sf_filter::inputFiles(options));
      if (tune) {
        // The cost sums over the values that reach the filter: a gate would let the optimiser
        // lower it by gating values away, so the identification runs without gates; the NIS
        // needs its window on.
        std::size_t gates = 0;
        for (sf_filter::InputOptions& in : engineOptions.inputs) {
          gates += in.gated() ? 1 : 0;
          in.gateThreshold = std::numeric_limits<double>::infinity();
        }
        if (gates > 0) {
          std::cout << options.nodeName << ": --tune: the Mahalanobis gates of " << gates
                    << " inputs are off while identifying (a gate would remove values from "
                       "the likelihood); the YAML file leaves them as configured"
                    << std::endl;
        }
        if (engineOptions.nisWindow == 0)
          engineOptions.nisWindow = sf_filter::nisWindowPeriods({}, periodMs);
      }
      sf_filter::BagReplay replay(def.makeEngine(parameters, engineOptions),
                                  describe(def, baseFrame), options);
      if (tune) replay.recordEvents(&events);
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
      replay.extractorParameters() = extractorParameters;
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
      // Values dropped before the core: not rotatable, GPS fixes not on the Earth.
      std::uint64_t beforeCore = aligner ? aligner->droppedTotal() : 0;
      for (std::size_t i = 0; i < def.description.inputs.size(); ++i) {
        beforeCore += replay.gps().implausibleFixes(i);
      }
      std::cout << options.nodeName << ": " << s.messages << " messages, " << s.estimates
                << " estimates, " << failures << " failed steps, " << resets << " filter resets, "
                << s.skippedGaps << " gaps skipped, " << s.dropped << " dropped values (" << late
                << " late), " << gated << " gated, " << substituted << " substitutes, "
                << (s.estimates ? 1e6 * s.estimatorSeconds / static_cast<double>(s.estimates) : 0.0)
                << " us per estimation step, " << wall << " s in all" << std::endl;
      if (options.smooth) {
        std::cout << options.nodeName << ": smoothed " << s.smoothedPeriods << " periods ("
                  << s.smoothedSegments << " segments) in " << s.smoothingSeconds << " s, "
                  << s.smoothingBytesPerPeriod << " bytes per period" << std::endl;
      }
      printInputCounters(options.nodeName, replay.core(), def.description.inputs);
      printNis(options.nodeName, replay.core(), def.description.inputs);
      printGpsCounters(options.nodeName, replay, def.description.inputs);
      if (aligner) {
        std::cout << options.nodeName << ": " << aligner->transforms()
                  << " transforms read from the bag's /tf_static and /tf ("
                  << aligner->rejectedTransforms() << " refused by tf2), "
                  << aligner->droppedTotal() << " values dropped: not rotatable into '"
                  << aligner->baseFrame() << "'" << std::endl;
        if (aligner->repeatedTransforms() > 0) {  // one line, not tf2's one per transform
          std::cerr << program << ": tf2: TF_REPEATED_DATA: " << aligner->repeatedTransforms()
                    << " transforms ignored, each with the stamp of one its frame already had "
                       "(overlapping bags, or a transform recorded twice); the first is kept"
                    << std::endl;
        }
      }
      if (tune) {
        const auto maker = [&](const sf_filter::FilterParameters& p) {
          return def.makeEngine(p, engineOptions);
        };
        return tuneFromEvents(options.nodeName, def, events, maker, parameters, freeEntries, tuning,
                              tunedFile, paramsPath, periodMs, argc, argv);
      }
      if (strict && (failures > 0 || resets > 0 || s.dropped > 0 || beforeCore > 0)) {
        std::cerr << program << ": --strict: " << failures << " failed steps, " << resets
                  << " filter resets, " << s.dropped + beforeCore << " dropped values" << std::endl;
        return EXIT_FAILURE;
      }
    } catch (const std::exception& e) {
      std::cerr << program << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  };
  return sf_filter::runContained(replayBag, [&](int signal) {
    for (const std::string& path : {options.csvPath, options.outputBag, tunedPath}) {
      if (!path.empty()) std::remove(sf_filter::partialPath(path).c_str());
    }
    if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP) {
      std::cerr << program << ": interrupted (" << strsignal(signal) << "), no output written"
                << std::endl;
    } else {
      std::cerr << program << ": reading bag " << sf_filter::commaSeparated(options.inputBags)
                << " crashed the bag library (" << strsignal(signal)
                << "): the bag is corrupt; no output written" << std::endl;
    }
  });
}

/// The online node. Everything from reading the parameters to the start of the schedule is
/// start-up: any exception there is the one-line refusal of doc/filter_node.md, exit status 1.
int nodeMain(int argc, char** argv, const NodeDefinition& def) {
  ros::init(argc, argv, "sf_filter");
  // The handles outlive the refusal's log line: when the last one goes, ros::shutdown() ends
  // rosconsole.
  std::optional<ros::NodeHandle> nh, pnh;
  std::unique_ptr<sf_filter::FusionNodeInstance> node;
  try {
    nh.emplace();
    pnh.emplace("~");
    node = sf_filter::startFusionNode(*nh, *pnh, def);
  } catch (const std::exception& e) {
    ROS_FATAL("%s: refusing to start: %s", ros::this_node::getName().c_str(), e.what());
    return EXIT_FAILURE;
  }
  ros::spin();
  // On stdout: ros::shutdown() has ended rosconsole, so ROS_INFO would print nothing now.
  std::cout << ros::this_node::getName() << ": " << node->inputCountersLine() << std::endl;
  return EXIT_SUCCESS;
}

/// A started node: the spatial alignment outlives the node's subscriptions.
class StartedFusionNode final : public sf_filter::FusionNodeInstance {
 public:
  StartedFusionNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeDefinition& def)
      : def_(def) {
    const sf_filter::RosParameterSource params(pnh);
    for (const std::string& line : sf_filter::unknownParameterWarnings(
             params, sf_filter::extractorParameterNames(def.extractorParameters))) {
      ROS_WARN("%s", line.c_str());
    }
    if (def.frameAlignment) aligner_.emplace(params, def.baseFrame, def.description.inputs);
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
    options.nisWindow = sf_filter::nisWindowPeriods(faults, parameters.estimation_period_ms);
    options.nisTolerance = faults.nisTolerance;
    const std::string baseFrame = aligner_ ? aligner_->baseFrame() : def.baseFrame;
    node_.emplace(nh, pnh, def.makeEngine(parameters, options), describe(def, baseFrame),
                  aligner_ ? &*aligner_ : nullptr, faults.diagnosticPeriod,
                  sf_filter::loadOutputParameters(params));
    node_->gps().setOptions(sf_filter::loadGpsParameters(params));
    node_->extractorParameters() =
        sf_filter::loadExtractorParameters(params, def.extractorParameters);
    for (const sf_filter::TopicReader& reader : def.topics) node_->subscribe(reader);
    node_->start();
  }

  std::string inputCountersLine() const override {
    return ::inputCountersLine(node_->core(), def_.description.inputs);
  }

 private:
  const NodeDefinition& def_;
  std::optional<sf_filter::FrameAligner> aligner_;
  std::optional<sf_filter::FusionNode> node_;
};

}  // namespace

std::unique_ptr<sf_filter::FusionNodeInstance> sf_filter::startFusionNode(
    ros::NodeHandle nh, ros::NodeHandle pnh, const NodeDefinition& definition) {
  return std::make_unique<StartedFusionNode>(nh, pnh, definition);
}

int sf_filter::runFusionNode(int argc, char** argv, const NodeDefinition& def) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--replay" || std::string(argv[i]) == "--tune" ||
        std::string(argv[i]) == "--help") {
      return replayMain(argc, argv, def);
    }
  }
  return nodeMain(argc, argv, def);
}
