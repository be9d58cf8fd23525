// The fusion node as a nodelet: the same node as the executable (startFusionNode), on the
// nodelet's node handles, so in its manager's process and on the manager's callback queue
// (topics between nodelets of one manager are handed over without serialisation). A
// configuration header's plugin (sf_add_filter(... NODELET ...), fusion_nodelet_plugin.cpp)
// derives from it with the header's NodeDefinition.
#pragma once

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <nodelet/nodelet.h>

#include "sf_filter/definition/node_definition.hpp"
#include "sf_filter/node/fusion_node_instance.hpp"

namespace sf_filter {

class FusionNodelet : public nodelet::Nodelet {
 public:
  explicit FusionNodelet(NodeDefinition definition) : definition_(std::move(definition)) {}

  ~FusionNodelet() override {
    // On stdout like the node's: when the manager shuts down, rosconsole may be gone.
    if (node_) std::cout << getName() << ": " << node_->inputCountersLine() << std::endl;
  }

 private:
  /// A refused start (a bad parameter) fails the load with the reason: the manager logs it and
  /// `nodelet load` exits with an error.
  void onInit() override {
    try {
      node_ = startFusionNode(getNodeHandle(), getPrivateNodeHandle(), definition_);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s: refusing to start: %s", getName().c_str(), e.what());
      throw std::runtime_error(getName() + ": refusing to start: " + e.what());
    }
  }

  NodeDefinition definition_;
  std::unique_ptr<FusionNodeInstance> node_;
};

}  // namespace sf_filter
