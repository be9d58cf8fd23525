// What the online node's set-up (node_setup.cpp) and the offline replay (replay_*.cpp) of the
// prebuilt main (runFusionNode) share: the input names as logged, the fusion core's options.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sf_filter/core/fusion_core_options.hpp"
#include "sf_filter/core/input_overrides.hpp"
#include "sf_filter/definition/node_definition.hpp"

namespace sf_filter::app {

/// A topic name without its leading '/': the configured and the remapped names compare so.
inline std::string relativeName(const std::string& topic) {
  return !topic.empty() && topic[0] == '/' ? topic.substr(1) : topic;
}

/// The input names with what FRAME_ALIGNED_INPUTS do to them, for the log and diagnostics.
inline NodeDescription describe(const NodeDefinition& def, const std::string& baseFrame) {
  NodeDescription d = def.description;
  for (std::size_t i = 0; i < d.inputs.size(); ++i) {
    if (!def.alignedAxis[i].empty()) {
      d.inputs[i] += " rotated into " + baseFrame + ", " + def.alignedAxis[i];
    }
  }
  return d;
}

/// The fusion core's options: the period and the per-input options with the lag [ms]; stamps
/// more than `maxFutureStampMs` ahead of the clock are dropped.
inline FusionCoreOptions coreOptions(double periodMs, std::vector<InputOptions> inputs,
                                     double lagMs,
                                     double maxFutureStampMs = kDefaultMaxFutureStampMs) {
  FusionCoreOptions options;
  options.period = periodMs / 1000.0;
  options.inputs = std::move(inputs);
  options.maxMeasurementLag = lagMs / 1000.0;
  options.maxFutureStamp = maxFutureStampMs / 1000.0;
  return options;
}

/// The offline replay: `<node> --replay in.bag [more.bag...] [--csv out.csv] [--bag out.bag]
/// [options]`, or --tune, or --help (replay_main.cpp).
int replayMain(int argc, char** argv, const NodeDefinition& def);

}  // namespace sf_filter::app
