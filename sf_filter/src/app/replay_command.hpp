// The offline replay's command line, parsed (replay_command_line.cpp), and the steps of the
// replay that read it: the run (replay_main.cpp, which also builds the filter and the core
// from it), the summary and --strict (replay_summary.cpp), --tune (replay_tuning.cpp).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>

#include "sf_filter/definition/filter_parameters.hpp"
#include "sf_filter/definition/node_definition.hpp"
#include "sf_filter/gps/gps_inputs.hpp"
#include "sf_filter/io/ros_parameters.hpp"
#include "sf_filter/io/extractor_parameters.hpp"
#include "sf_filter/replay/bag_replay.hpp"
#include "sf_filter/tuning/noise_tuning.hpp"

namespace sf_filter {
class ReplayFrameAligner;
class EventLog;
}  // namespace sf_filter

namespace sf_filter::app {

/// Everything the command line says, the --params file's values under the options'.
struct ReplayCommand {
  std::string program;                 ///< argv[0], which starts every error line
  std::vector<std::string> arguments;  ///< argv, for the tuned file's comment
  bool help = false;                   ///< --help: print the usage, nothing else
  ReplayOptions options;
  double periodMs = 0.0, scaleQ = 1.0, scaleR = 1.0;
  double lagMs = 0.0;
  bool strict = false;
  std::optional<long> seed;
  std::string baseFrame;
  std::vector<InputOptions> inputs;
  std::string paramsPath;
  gps::GpsOptions gpsOptions;  // ~datum, ~gps_yaw_offset of --params
  sf_config::extractors::ParameterValues extractorParameters;  // e.g. ~magnetic_declination
  std::optional<double> periodOverrideMs;
  std::optional<FilterParameters> fileParameters;
  double maxFutureStampMs = kDefaultMaxFutureStampMs;
  FaultSettings nis;  // ~nis_window, ~nis_tolerance, as the node's
  std::map<std::string, std::string> remaps;
  std::vector<geometry_msgs::TransformStamped> staticTransforms;
  bool tune = false;
  std::string freeList = "Q,R", tunedPath;
  TuningOptions tuning;
  std::vector<FreeEntry> freeEntries;
};

/// The replay's usage text, for --help and after an error in the command line.
std::string replayUsage(const std::string& program);

/// The command line parsed and checked against the node's definition. Throws
/// std::invalid_argument (or another std::exception) naming the problem.
ReplayCommand parseReplayCommand(int argc, char** argv, const NodeDefinition& def);

/// What the replay's summary reads besides the engine.
struct ReplayOutcome {
  const ReplaySummary& summary;
  const FusionEngine& core;
  const FusionStatistics& statistics;  ///< the core's, after the run
  const InputState& inputs;            ///< the replay's, after the run
  const ReplayFrameAligner* aligner;   ///< nullptr without FRAME_ALIGNED_INPUTS
  double wallSeconds;
};

/// The summary's lines on stdout (and tf2's repeated data on stderr).
void printReplaySummary(const ReplayCommand& command, const NodeDefinition& def,
                        const ReplayOutcome& outcome);

/// --strict: the exit status 1 and its line when a step failed, the filter was reset or a
/// value was dropped; EXIT_SUCCESS otherwise.
int strictStatus(const ReplayCommand& command, const NodeDefinition& def,
                 const ReplayOutcome& outcome);

/// The replay's NIS lines: all inputs together, then each input (nis_report.hpp).
void printNis(const std::string& name, const FusionEngine& core,
              const std::vector<std::string>& inputs);

/// --tune after the first replay of the bag (recorded in `events`): the prediction-error
/// identification of the free entries, its report, the tuned replay's NIS and the YAML file
/// `out` (if enabled). Throws ReplayError, writing nothing, when the bag identifies nothing.
int tuneFromEvents(const ReplayCommand& command, const NodeDefinition& def, const EventLog& events,
                   const FusionCoreOptions& engineOptions, const FilterParameters& start,
                   AtomicOutput& out);

}  // namespace sf_filter::app
