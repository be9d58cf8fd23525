// Everything the prebuilt fusion node and bag replay need to know about one configuration
// header, in run-time form. The header's translation unit fills it in (generated/
// node_definition_of.hpp) and passes it to runFusionNode(); nothing else crosses the boundary.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/core/fusion_core_options.hpp"
#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/input_overrides.hpp"
#include "sf_filter/definition/filter_parameters.hpp"
#include "sf_filter/definition/message_sink.hpp"
#include "sf_filter/definition/node_description.hpp"

namespace sf_filter {

struct NodeDefinition {
  // Declared here, defined (as the defaults) once in the core library
  // (sf_filter/src/definition/node_definition.cpp): otherwise every header's translation unit
  // would compile the destruction of all the members below.
  NodeDefinition();
  ~NodeDefinition();
  NodeDefinition(const NodeDefinition&);
  NodeDefinition(NodeDefinition&&) noexcept;
  NodeDefinition& operator=(const NodeDefinition&);
  NodeDefinition& operator=(NodeDefinition&&) noexcept;

  NodeDescription description;             ///< method, inputs, controls, outputs, pose
  InputCapabilities capabilities;          ///< for checking run-time overrides of the input options
  double estimationPeriodMs = 100.0;       ///< ESTIMATION_PERIOD
  double maxMeasurementLagMs = 0.0;        ///< MAX_MEASUREMENT_LAG
  std::vector<InputOptions> inputOptions;  ///< the header's per-input options
  /// FRAME_ALIGNED_INPUTS: per input the axis name ("x", "y", "z") of the rotated vector it
  /// reads, empty when it reads its field as configured; and BASE_FRAME.
  std::vector<std::string> alignedAxis;
  bool frameAlignment = false;
  std::string baseFrame;
  std::vector<TopicReader> topics;
  /// The private parameters of the extractor kinds its inputs are read by (e.g.
  /// ~magnetic_declination), loaded by the node and the replay into their sink.
  std::vector<sf_config::extractors::ExtractorParameter> extractorParameters;
  /// The header's numeric parameters, evaluated for an estimation period (entries may use T).
  std::function<FilterParameters(double estimationPeriodMs)> defaultParameters;
  /// The header's filter made from (possibly overridden) parameters, in its fusion core.
  /// Throws estimation::ParameterError (or std::invalid_argument) for a bad parameter.
  std::function<std::unique_ptr<FusionEngine>(const FilterParameters&, const FusionCoreOptions&)>
      makeEngine;
};

/// The prebuilt main of every fusion node: the online node, or with --replay the offline bag
/// replay (sf_filter/src/node_main.cpp).
int runFusionNode(int argc, char** argv, const NodeDefinition& definition);

}  // namespace sf_filter
