// The prebuilt main of every fusion node (runFusionNode, node_definition.hpp): the online
// ROS node set up from its private parameters, or with --replay, --tune or --help the offline
// replay (replay_main.cpp). Compiled once into the node library; the translation unit of each
// configuration header only builds its NodeDefinition.
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "app/app_support.hpp"
#include "sf_filter/definition/node_definition.hpp"
#include "sf_filter/io/extractor_parameters.hpp"
#include "sf_filter/io/ros_parameters.hpp"
#include "sf_filter/node/frame_aligner.hpp"
#include "sf_filter/node/fusion_node.hpp"
#include "sf_filter/node/fusion_node_instance.hpp"
#include "sf_filter/node/gps_parameters.hpp"

namespace sf_filter::app {

namespace {

/// One line with what became of every input's values, logged by the node at shutdown (the
/// soak test compares `received` with what its driver published).
std::string inputCountersLine(const FusionEngine& core, const std::vector<std::string>& names) {
  std::ostringstream line;
  line << "input counters at shutdown:";
  const FusionStatistics statistics = core.statistics();
  for (std::size_t i = 0; i < statistics.inputs.size(); ++i) {
    const InputCounters& c = statistics.inputs[i];
    line << (i ? ";" : "") << " input " << i << " (" << names.at(i) << "): received " << c.received
         << ", used " << c.used << ", dropped " << c.dropped() << ", gated " << c.gated;
  }
  return line.str();
}

/// The online node. Everything from reading the parameters to the start of the schedule is
/// start-up: any exception there is the one-line refusal of doc/filter_node.md, exit status 1.
int nodeMain(int argc, char** argv, const NodeDefinition& def) {
  ros::init(argc, argv, "sf_filter");
  // The handles outlive the refusal's log line: when the last one goes, ros::shutdown() ends
  // rosconsole.
  std::optional<ros::NodeHandle> nh, pnh;
  std::unique_ptr<FusionNodeInstance> node;
  try {
    nh.emplace();
    pnh.emplace("~");
    node = startFusionNode(*nh, *pnh, def);
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
class StartedFusionNode final : public FusionNodeInstance {
 public:
  StartedFusionNode(ros::NodeHandle nh, ros::NodeHandle pnh, const NodeDefinition& def)
      : def_(def) {
    const RosParameterSource params(pnh);
    for (const std::string& line :
         unknownParameterWarnings(params, extractorParameterNames(def.extractorParameters))) {
      ROS_WARN("%s", line.c_str());
    }
    if (def.frameAlignment) aligner_.emplace(params, def.baseFrame, def.description.inputs);
    const FilterParameters parameters =
        loadParameters<FilterParameters>(params, def.defaultParameters, def.estimationPeriodMs);
    std::vector<InputOptions> inputs = def.inputOptions;
    double lagMs = def.maxMeasurementLagMs;
    loadInputParameters(params, inputs, lagMs, def.capabilities);
    const FaultSettings faults = loadFaultParameters(params, inputs, def.capabilities);
    FusionCoreOptions options =
        coreOptions(parameters.estimation_period_ms, inputs, lagMs, faults.maxFutureStampMs);
    options.nisWindow = nisWindowPeriods(faults, parameters.estimation_period_ms);
    options.nisTolerance = faults.nisTolerance;
    options.periodsOnClockGrid = faults.periodsOnClockGrid;
    options.unstampedCadence = faults.unstampedCadence;
    const std::string baseFrame = aligner_ ? aligner_->baseFrame() : def.baseFrame;
    node_.emplace(nh, pnh, def.makeEngine(parameters, options), describe(def, baseFrame),
                  aligner_ ? &*aligner_ : nullptr, faults.diagnosticPeriod,
                  loadOutputParameters(params));
    node_->inputState().gps().setOptions(loadGpsParameters(params));
    node_->inputState().extractorParameters() =
        loadExtractorParameters(params, def.extractorParameters);
    for (const TopicReader& reader : def.topics) node_->subscribe(reader);
    node_->start();
  }

  std::string inputCountersLine() const override {
    return app::inputCountersLine(node_->core(), def_.description.inputs);
  }

 private:
  const NodeDefinition& def_;
  std::optional<FrameAligner> aligner_;
  std::optional<FusionNode> node_;
};

}  // namespace

}  // namespace sf_filter::app

std::unique_ptr<sf_filter::FusionNodeInstance> sf_filter::startFusionNode(
    ros::NodeHandle nh, ros::NodeHandle pnh, const NodeDefinition& definition) {
  return std::make_unique<app::StartedFusionNode>(nh, pnh, definition);
}

int sf_filter::runFusionNode(int argc, char** argv, const NodeDefinition& def) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--replay" || std::string(argv[i]) == "--tune" ||
        std::string(argv[i]) == "--help") {
      return app::replayMain(argc, argv, def);
    }
  }
  return app::nodeMain(argc, argv, def);
}
