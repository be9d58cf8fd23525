// The offline replay (--replay, --tune): the command line parsed (replay_command_line.cpp),
// the bag replayed through the node's filter in a child process (contained_run.hpp), then the
// summary (replay_summary.cpp) or the noise identification (replay_tuning.cpp).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

#include <ros/time.h>

#include "app/app_support.hpp"
#include "app/replay_command.hpp"
#include "sf_filter/replay/bag_replay.hpp"
#include "sf_filter/replay/contained_run.hpp"
#include "sf_filter/replay/library_messages.hpp"
#include "sf_filter/replay/replay_frame_aligner.hpp"
#include "sf_filter/tuning/event_log.hpp"

namespace sf_filter::app {

namespace {

/// The filter's parameters of the replay: the header's or the --params file's, scaled.
FilterParameters replayParameters(const ReplayCommand& c, const NodeDefinition& def) {
  FilterParameters parameters =
      c.fileParameters ? *c.fileParameters : def.defaultParameters(c.periodMs);
  parameters.process_noise_covariance *= c.scaleQ;
  parameters.measurement_noise_covariance *= c.scaleR;
  if (c.seed) parameters.random_seed = static_cast<unsigned>(*c.seed);
  return parameters;
}

/// The fusion core's options of the replay; with --tune without gates and with a NIS window.
FusionCoreOptions replayCoreOptions(const ReplayCommand& c) {
  FusionCoreOptions options = coreOptions(c.periodMs, c.inputs, c.lagMs, c.maxFutureStampMs);
  options.nisWindow = nisWindowPeriods(c.nis, c.periodMs);
  options.nisTolerance = c.nis.nisTolerance;
  options.periodsOnClockGrid = c.nis.periodsOnClockGrid;
  options.unstampedCadence = c.nis.unstampedCadence;
  if (!c.tune) return options;
  // The cost sums over the values that reach the filter: a gate would let the optimiser lower
  // it by gating values away, so the identification runs without gates; the NIS needs its
  // window on.
  std::size_t gates = 0;
  for (InputOptions& in : options.inputs) {
    gates += in.gated() ? 1 : 0;
    in.gateThreshold = std::numeric_limits<double>::infinity();
  }
  if (gates > 0) {
    std::cout << c.options.nodeName << ": --tune: the Mahalanobis gates of " << gates
              << " inputs are off while identifying (a gate would remove values from "
                 "the likelihood); the YAML file leaves them as configured"
              << std::endl;
  }
  if (options.nisWindow == 0) options.nisWindow = nisWindowPeriods({}, c.periodMs);
  return options;
}

/// FRAME_ALIGNED_INPUTS in the replay: the bag's transforms through ReplayFrameAligner.
class ReplayAlignerRotation final : public ReplayRotation {
 public:
  explicit ReplayAlignerRotation(ReplayFrameAligner& aligner) : aligner_(aligner) {}
  std::optional<double> rotated(Index input, const std::string& frame, std::uint32_t sec,
                                std::uint32_t nsec, const std::array<double, 3>& vector,
                                int axis) override {
    return aligner_.align(static_cast<std::size_t>(input), frame, ros::Time(sec, nsec), vector,
                          axis);
  }

 private:
  ReplayFrameAligner& aligner_;
};

/// The aligner reads the bag's transforms and --static-transform's.
void connectAligner(BagReplay& replay, ReplayFrameAligner& aligner, ReplayAlignerRotation& rotation,
                    const std::vector<geometry_msgs::TransformStamped>& staticTransforms) {
  replay.setRotation(&rotation);
  replay.readTransforms([&aligner](const tf2_msgs::TFMessage& msg, bool isStatic) {
    aligner.addTransforms(msg, isStatic);
  });
  if (!staticTransforms.empty()) {
    tf2_msgs::TFMessage given;
    given.transforms = staticTransforms;
    aligner.addTransforms(given, true);
  }
}

/// Every configured topic's reader, on its remapped topic.
void subscribeTopics(BagReplay& replay, const ReplayCommand& c, const NodeDefinition& def) {
  for (TopicReader reader : def.topics) {
    const auto remapped = c.remaps.find(relativeName(reader.topic));
    if (remapped != c.remaps.end()) reader.topic = remapped->second;
    replay.subscribe(reader);
  }
}

/// The replay of the command's bags; its summary, then --tune or --strict's exit status.
int replayBag(const ReplayCommand& c, const NodeDefinition& def) {
  ros::Time::init();
  const FilterParameters parameters = replayParameters(c, def);
  std::optional<ReplayFrameAligner> aligner;
  if (def.frameAlignment) aligner.emplace(c.baseFrame, def.description.inputs);
  std::optional<ReplayAlignerRotation> rotation;
  const FusionCoreOptions engineOptions = replayCoreOptions(c);
  EventLog events;
  // --tune's --out, checked like --csv and --bag before anything is read
  AtomicOutput tunedFile("--out", c.tunedPath, inputFiles(c.options));
  BagReplay replay(def.makeEngine(parameters, engineOptions), describe(def, c.baseFrame),
                   c.options);
  if (c.tune) replay.recordEvents(&events);
  if (aligner) {
    rotation.emplace(*aligner);
    connectAligner(replay, *aligner, *rotation, c.staticTransforms);
  }
  replay.inputState().gps().setOptions(c.gpsOptions);
  replay.inputState().extractorParameters() = c.extractorParameters;
  subscribeTopics(replay, c, def);
  const auto start = std::chrono::steady_clock::now();
  const ReplaySummary s = replay.run();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const FusionStatistics statistics = replay.core().statistics();
  const ReplayOutcome outcome{
      s, replay.core(), statistics, replay.inputState(), aligner ? &*aligner : nullptr, wall};
  printReplaySummary(c, def, outcome);
  if (c.tune) return tuneFromEvents(c, def, events, engineOptions, parameters, tunedFile);
  return strictStatus(c, def, outcome);
}

/// In the child process: the replay with the bag library's messages as one line each, an
/// error as one line and exit status 1.
int containedReplay(const ReplayCommand& c, const NodeDefinition& def) {
  static ReplayLibraryMessages libraryMessages(c.program);
  console_bridge::useOutputHandler(&libraryMessages);
  try {
    return replayBag(c, def);
  } catch (const std::exception& e) {
    std::cerr << c.program << ": " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}

/// The child ended by a signal: no partial output stays, one line says why.
void reportAbort(const ReplayCommand& c, int signal) {
  for (const std::string& path : {c.options.csvPath, c.options.outputBag, c.tunedPath}) {
    if (!path.empty()) std::remove(partialPath(path).c_str());
  }
  if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP) {
    std::cerr << c.program << ": interrupted (" << strsignal(signal) << "), no output written"
              << std::endl;
  } else {
    std::cerr << c.program << ": reading bag " << commaSeparated(c.options.inputBags)
              << " crashed the bag library (" << strsignal(signal)
              << "): the bag is corrupt; no output written" << std::endl;
  }
}

}  // namespace

int replayMain(int argc, char** argv, const NodeDefinition& def) {
  const std::string program = argv[0];
  ReplayCommand command;
  try {
    command = parseReplayCommand(argc, argv, def);
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n" << replayUsage(program) << std::endl;
    return 2;
  }
  if (command.help) {
    std::cout << replayUsage(program) << std::endl;
    return EXIT_SUCCESS;
  }
  // In a child process: a library crashing on a corrupt bag, or an interrupt, still ends
  // with one line and without partial outputs (contained_run.hpp).
  return runContained([&] { return containedReplay(command, def); },
                      [&](int signal) { reportAbort(command, signal); });
}

}  // namespace sf_filter::app
