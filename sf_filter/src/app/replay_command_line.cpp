// The offline replay's command line: its usage text, and the options read in two passes
// (--params first, so that the options override the file whatever their order), then checked
// against the node's definition.
#include <cmath>
#include <stdexcept>
#include <string>

#include <tf2/LinearMath/Quaternion.h>

#include "app/app_support.hpp"
#include "app/replay_command.hpp"
#include "sf_filter/node/gps_parameters.hpp"
#include "sf_filter/replay/yaml_parameters.hpp"

namespace sf_filter::app {

std::string replayUsage(const std::string& program) {
  return "usage: " + program +
         " --replay INPUT.bag [INPUT.bag]... [--csv OUT.csv] [--bag OUT.bag]\n"
         "       [--smooth [batch]] [--smooth-lag SECONDS]\n"
         "       [--name NODE]\n"
         "       [--estimation-period S | --estimation-period-ms MS] [--scale-q FACTOR]\n"
         "       [--scale-r FACTOR] [--seed N] [--strict]\n"
         "       [--frame-id FRAME] [--child-frame-id FRAME] [--base-frame FRAME]\n"
         "       [--align INPUT=POLICY]... [--gate INPUT=THRESHOLD]... [--align-by-stamp "
         "INPUT]...\n"
         "       [--align-by-arrival INPUT]... [--max-lag S] [--allow-missing-topics]\n"
         "       [--params FILE.yaml] [FROM:=TO]...\n"
         "       [--static-transform X Y Z YAW PITCH ROLL PARENT CHILD]...\n"
         "   or: " +
         program +
         " --tune INPUT.bag [INPUT.bag]... [--free LIST] [--out TUNED.yaml]\n"
         "       [--tune-range F] [--max-evaluations N] [--tune-holdout F]\n"
         "       [--tune-keep-unidentified] [the replay's options but --csv, --bag]\n"
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
         "the filter was reset or a value was dropped. --params: the node's private parameters "
         "from a YAML file\n"
         "(as rosparam load takes it), parsed and checked as the node does; options given\n"
         "here override it. FROM:=TO reads the configured topic FROM from the bag's topic TO.\n"
         "--static-transform: a transform as static_transform_publisher takes it (metres,\n"
         "radians), for a bag without /tf_static.\n"
         "--smooth: after the replay, the Rauch-Tung-Striebel backward pass over every period\n"
         "(KF, EKF; the unscented one for a UKF); the CSV gets smoothed_* columns after the\n"
         "filtered ones (doc/smoothing.md). --smooth batch: the maximum-a-posteriori track\n"
         "of the whole recording instead (Gauss-Newton, the iterated Kalman smoother; KF,\n"
         "EKF, UKF), in the same columns. --smooth-lag: the fixed-lag smoother of that lag\n"
         "(whole periods, as ~smoothing_lag online): each row gets lagged_* columns of its own\n"
         "period smoothed with the readings up to the lag later (NaN for the last lag's rows);\n"
         "the output bag gets odometry/smoothed and ~state/smoothed.\n"
         "POLICY: AVERAGE, LAST, SAMPLED, 'HOLD LAGRANGE|BEZIER|TAYLOR ORDER [VARIANCE]' or\n"
         "'FILL OMEGA N [VARIANCE]'; THRESHOLD 0 removes a gate (doc/alignment_policies.md).\n"
         "INPUT: the input's index, or its record name in a header with INPUTS records.\n"
         "--tune: identifies the free noise entries from the bag by the prediction-error method\n"
         "(minimum of sum(log det S + NIS) over in-memory replays; KF, EKF, UKF) and writes them\n"
         "with --out as a YAML file of private parameters for the node and --params\n"
         "(doc/tuning.md). LIST: comma-separated Q, R, P0 (their non-zero diagonal entries) or\n"
         "Q.i, R.i, P0.i; default Q,R. --tune-range F: each variance within a factor F of its\n"
         "start (default 1000); --max-evaluations N: replays at most (default 2000). An entry\n"
         "at a bound or whose cost is flat (rises by less than 3.84 at half and twice its value)\n"
         "keeps its start value unless --tune-keep-unidentified. --tune-holdout F: the guard\n"
         "tunes on the first 1 - F of the recording (default 0.3 held out, 0: no guard) and\n"
         "writes the start values (exit status 0) unless the tuned ones predict the rest better.";
}

namespace {

/// The arguments after the program's name, one at a time.
class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}

  /// Moves to the next argument; false after the last.
  bool next() {
    if (++i_ >= argc_) return false;
    arg_ = argv_[i_];
    return true;
  }
  const std::string& arg() const { return arg_; }

  /// The option's value: the next argument.
  std::string value() {
    if (i_ + 1 >= argc_) throw std::invalid_argument("option " + arg_ + " needs a value");
    return argv_[++i_];
  }

  /// Whether the next argument is `word`.
  bool nextIs(const char* word) const {
    return i_ + 1 < argc_ && std::string(argv_[i_ + 1]) == word;
  }

  /// The arguments left after the current one.
  int left() const { return argc_ - i_ - 1; }

  /// Whether the next argument is a bag: neither an option nor a remap.
  bool nextIsBag() const {
    return i_ + 1 < argc_ && argv_[i_ + 1][0] != '-' &&
           std::string(argv_[i_ + 1]).find(":=") == std::string::npos;
  }

 private:
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string arg_;
};

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

/// The header's values, before the file and the options.
ReplayCommand initialCommand(int argc, char** argv, const NodeDefinition& def) {
  ReplayCommand c;
  c.program = argv[0];
  c.arguments.assign(argv, argv + argc);
  c.options.nodeName = c.program.substr(c.program.find_last_of('/') + 1);
  c.periodMs = def.estimationPeriodMs;
  c.lagMs = def.maxMeasurementLagMs;
  c.baseFrame = def.baseFrame;
  c.inputs = def.inputOptions;
  return c;
}

/// --params FILE: the node's private parameters of the file, read before the options.
void readParametersFile(ReplayCommand& c, int argc, char** argv, const NodeDefinition& def,
                        std::optional<YamlParameterSource>& params) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) != "--params") continue;
    if (params) throw std::invalid_argument("--params given twice");
    c.paramsPath = argv[i + 1];
    c.options.parametersFile = c.paramsPath;
    params.emplace(c.paramsPath);
    for (const std::string& line :
         unknownParameterWarnings(*params, extractorParameterNames(def.extractorParameters))) {
      std::cerr << c.program << ": warning: --params " << argv[i + 1] << ": " << line << std::endl;
    }
    c.periodMs = loadPeriodMs(*params, c.periodMs);
    loadInputParameters(*params, c.inputs, c.lagMs, def.capabilities);
    const FaultSettings faults = loadFaultParameters(*params, c.inputs, def.capabilities);
    c.maxFutureStampMs = faults.maxFutureStampMs;
    c.nis = faults;
    const OutputSettings out = loadOutputParameters(*params);
    c.options.frameId = out.frameId;
    c.options.childFrameId = out.childFrameId;
    c.options.smoothLag = out.smoothingLag;
    c.baseFrame = detail::frameParameter(*params, "base_frame", c.baseFrame);
    c.gpsOptions = loadGpsParameters(*params);
    c.extractorParameters = loadExtractorParameters(*params, def.extractorParameters);
  }
}

/// FROM:=TO (not a private parameter's _name:=value).
bool readRemap(ReplayCommand& c, const std::string& arg) {
  const std::size_t remap = arg.find(":=");
  if (remap == std::string::npos || remap == 0 || arg[0] == '_') return false;
  c.remaps[relativeName(arg.substr(0, remap))] = arg.substr(remap + 2);
  return true;
}

/// --replay, --tune and their bags; --tune's options.
bool readRunOption(ReplayCommand& c, Arguments& a) {
  const std::string& arg = a.arg();
  if (arg == "--replay" || arg == "--tune") {
    if (!c.options.inputBags.empty()) {
      throw std::invalid_argument(arg + ": the bags are given once, after --replay or --tune");
    }
    // the bags: the value, and every following argument up to the next option or remap
    c.options.inputBags.push_back(a.value());
    while (a.nextIsBag()) c.options.inputBags.push_back(a.value());
    c.tune = c.tune || arg == "--tune";
  } else if (arg == "--free") {
    c.freeList = a.value();
  } else if (arg == "--out") {
    c.tunedPath = a.value();
  } else if (arg == "--tune-range") {
    c.tuning.range = numberOption(arg, a.value());
  } else if (arg == "--tune-holdout") {
    c.tuning.holdout = numberOption(arg, a.value());
  } else if (arg == "--tune-keep-unidentified") {
    c.tuning.keepUnidentified = true;
  } else if (arg == "--max-evaluations") {
    const double n = numberOption(arg, a.value());
    if (n != std::floor(n) || n < 1 || n > 1e9) {
      throw std::invalid_argument("--max-evaluations must be a whole number from 1 to 1e9");
    }
    c.tuning.maxEvaluations = static_cast<int>(n);
  } else {
    return false;
  }
  return true;
}

/// --static-transform X Y Z YAW PITCH ROLL PARENT CHILD, as static_transform_publisher.
geometry_msgs::TransformStamped staticTransform(Arguments& a) {
  if (a.left() < 8) {
    throw std::invalid_argument("--static-transform needs X Y Z YAW PITCH ROLL PARENT CHILD");
  }
  double v[6];
  for (double& x : v) {
    x = std::stod(a.value());
    if (!std::isfinite(x)) throw std::invalid_argument("--static-transform: not finite");
  }
  geometry_msgs::TransformStamped t;
  t.header.frame_id = a.value();
  t.child_frame_id = a.value();
  t.transform.translation.x = v[0];
  t.transform.translation.y = v[1];
  t.transform.translation.z = v[2];
  tf2::Quaternion q;
  q.setRPY(v[5], v[4], v[3]);
  t.transform.rotation.x = q.x();
  t.transform.rotation.y = q.y();
  t.transform.rotation.z = q.z();
  t.transform.rotation.w = q.w();
  return t;
}

/// The outputs, their frames and names; --params (read before), --static-transform.
bool readOutputOption(ReplayCommand& c, Arguments& a) {
  const std::string& arg = a.arg();
  if (arg == "--csv") {
    c.options.csvPath = a.value();
  } else if (arg == "--bag") {
    c.options.outputBag = a.value();
  } else if (arg == "--smooth") {
    c.options.smooth = true;
    if (a.nextIs("batch")) c.options.smoothBatch = a.value() == "batch";
  } else if (arg == "--smooth-lag") {
    c.options.smoothLag = smoothingLagSeconds("--smooth-lag", std::stod(a.value()));
  } else if (arg == "--params") {
    a.value();  // read first (readParametersFile)
  } else if (arg == "--static-transform") {
    c.staticTransforms.push_back(staticTransform(a));
  } else if (arg == "--name") {
    c.options.nodeName = a.value();
  } else if (arg == "--frame-id") {
    c.options.frameId = a.value();
  } else if (arg == "--child-frame-id") {
    c.options.childFrameId = a.value();
  } else if (arg == "--base-frame") {
    c.baseFrame = a.value();
  } else {
    return false;
  }
  return true;
}

/// The period, the noise scales, the seed, the lag; --strict, --allow-missing-topics.
bool readFilterOption(ReplayCommand& c, Arguments& a) {
  const std::string& arg = a.arg();
  if (arg == "--estimation-period" || arg == "--estimation-period-ms") {
    const double seconds = std::stod(a.value()) / (arg == "--estimation-period" ? 1.0 : 1000.0);
    c.periodMs = secondsToMs(arg, seconds, kMinPeriodSeconds, kMaxPeriodSeconds, false);
    c.periodOverrideMs = c.periodMs;
  } else if (arg == "--strict") {
    c.strict = true;
  } else if (arg == "--scale-q") {
    c.scaleQ = std::stod(a.value());
  } else if (arg == "--scale-r") {
    c.scaleR = std::stod(a.value());
  } else if (arg == "--seed") {
    c.seed = std::stol(a.value());
  } else if (arg == "--allow-missing-topics") {
    c.options.allowMissingTopics = true;
  } else if (arg == "--max-lag") {
    c.lagMs =
        checkedLagMs(secondsToMs("--max-lag", std::stod(a.value()), 0.0, kMaxLagSeconds, true));
  } else {
    return false;
  }
  return true;
}

/// --align INPUT=POLICY, --gate INPUT=THRESHOLD, --align-by-stamp/--align-by-arrival INPUT.
bool readInputOption(ReplayCommand& c, Arguments& a, const InputCapabilities& can) {
  const std::string& arg = a.arg();
  if (arg == "--align" || arg == "--gate") {
    const std::string given = a.value();
    const std::size_t equals = given.find('=');
    if (equals == std::string::npos) {
      throw std::invalid_argument(
          arg + " " + given + ": expected INPUT=" + (arg == "--align" ? "POLICY" : "THRESHOLD"));
    }
    try {
      const long input = inputIndexOf(given.substr(0, equals), can);
      if (arg == "--align") {
        overrideAlignment(c.inputs, input, given.substr(equals + 1), can);
      } else {
        overrideGate(c.inputs, input, std::stod(given.substr(equals + 1)), can);
      }
    } catch (const std::logic_error& e) {  // invalid_argument and stod's out_of_range
      throw std::invalid_argument(arg + " " + given + ": " + e.what());
    }
  } else if (arg == "--align-by-stamp" || arg == "--align-by-arrival") {
    const std::string given = a.value();
    try {
      overrideAlignByStamp(c.inputs, inputIndexOf(given, can), arg == "--align-by-stamp", can);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(arg + " " + given + ": " + e.what());
    }
  } else {
    return false;
  }
  return true;
}

/// --tune's options checked, its free entries parsed; --free and --out refused without it.
void checkTuning(ReplayCommand& c, const NodeDefinition& def) {
  if (!c.tune) {
    if (c.freeList != "Q,R" || !c.tunedPath.empty()) {
      throw std::invalid_argument("--free and --out belong to --tune");
    }
    return;
  }
  const std::string refusal = tuningRefusal(def.description.method);
  if (!refusal.empty()) throw std::invalid_argument("--tune: " + refusal);
  if (!c.options.csvPath.empty() || !c.options.outputBag.empty()) {
    throw std::invalid_argument(
        "--tune writes no estimates (--csv, --bag): replay with --params TUNED.yaml for them");
  }
  if (!(c.tuning.range > 1.0) || !std::isfinite(c.tuning.range)) {
    throw std::invalid_argument("--tune-range must be a finite factor above 1");
  }
  if (c.tuning.maxEvaluations < 1) throw std::invalid_argument("--max-evaluations must be >= 1");
  if (!(c.tuning.holdout >= 0.0 && c.tuning.holdout <= 0.9)) {
    throw std::invalid_argument("--tune-holdout must be a fraction from 0 (no guard) to 0.9");
  }
  const FilterParameters start =
      c.fileParameters ? *c.fileParameters : def.defaultParameters(c.periodMs);
  c.freeEntries = parseFreeEntries(c.freeList, start);
}

/// The transforms, remaps and base frame against the node's topics and alignment.
void checkNames(const ReplayCommand& c, const NodeDefinition& def) {
  if (!c.staticTransforms.empty() && !def.frameAlignment) {
    throw std::invalid_argument("--static-transform: this node has no FRAME_ALIGNED_INPUTS");
  }
  for (const auto& [from, to] : c.remaps) {
    bool known = false;
    for (const TopicReader& reader : def.topics) {
      known = known || relativeName(reader.topic) == from;
    }
    if (!known) throw std::invalid_argument(from + ":=" + to + ": no configured topic " + from);
  }
  if (def.frameAlignment && (c.baseFrame.empty() || c.baseFrame.front() == '/')) {
    throw std::invalid_argument("--base-frame '" + c.baseFrame +
                                "' is not a tf2 frame name (not empty, no leading '/')");
  }
}

/// The checks after every option is read.
void checkCommand(ReplayCommand& c, const NodeDefinition& def,
                  const std::optional<YamlParameterSource>& params) {
  if (!(c.scaleQ > 0.0) || !(c.scaleR > 0.0))
    throw std::invalid_argument("scale factors must be positive");
  if (c.seed && *c.seed < 0) throw std::invalid_argument("--seed must not be negative");
  // With --params: the file's Q, R, x0, P0, ... through the node's own parsing, the
  // header's entries evaluated for the final period (an option overrides the file's).
  if (params) {
    const double periodMs = c.periodMs;
    c.fileParameters = loadParameters<FilterParameters>(
        *params, [&](double) { return def.defaultParameters(periodMs); },
        c.periodOverrideMs.value_or(periodMs));
  }
  checkTuning(c, def);
  checkNames(c, def);
}

}  // namespace

ReplayCommand parseReplayCommand(int argc, char** argv, const NodeDefinition& def) {
  ReplayCommand c = initialCommand(argc, argv, def);
  std::optional<YamlParameterSource> params;
  readParametersFile(c, argc, argv, def, params);
  Arguments a(argc, argv);
  while (a.next()) {
    if (readRemap(c, a.arg())) continue;
    if (a.arg() == "--help") {
      c.help = true;
      return c;
    }
    if (!readRunOption(c, a) && !readOutputOption(c, a) && !readFilterOption(c, a) &&
        !readInputOption(c, a, def.capabilities)) {
      throw std::invalid_argument("unknown option " + a.arg());
    }
  }
  checkCommand(c, def, params);
  return c;
}

}  // namespace sf_filter::app
