// One online fusion node made from a NodeDefinition on two node handles: the node's main
// (sf_filter/src/node_main.cpp) and the nodelet (fusion_nodelet.hpp) start it the same way,
// so both read the same parameters and have the same topics, diagnostics and set_pose service.
#pragma once

#include <memory>
#include <string>

#include <ros/node_handle.h>

#include "sf_filter/definition/node_definition.hpp"

namespace sf_filter {

class FusionNodeInstance {
 public:
  virtual ~FusionNodeInstance() = default;
  /// What became of every input's values (received, used, dropped, gated), one line.
  virtual std::string inputCountersLine() const = 0;
};

/// Reads and checks the private parameters of `pnh`, builds the header's filter and starts the
/// node in `nh`'s namespace on their callback queue; returns at once (the schedule starts with
/// the first valid clock reading). Throws std::exception naming the problem when it refuses to
/// start (a bad parameter, say). `definition` must outlive the node.
std::unique_ptr<FusionNodeInstance> startFusionNode(ros::NodeHandle nh, ros::NodeHandle pnh,
                                                    const NodeDefinition& definition);

}  // namespace sf_filter
