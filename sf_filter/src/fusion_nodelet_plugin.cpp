// The nodelet plugin of one configuration header: sf_add_filter(<name> <header> NODELET ...)
// compiles this file with -DSF_NODELET_CLASS=<name> and links it with the header's own
// translation unit (fusion_node_unit.cpp, compiled once for the node and the plugin), whose
// headerDefinition() it loads. Only nodelet and pluginlib headers are compiled here.
#ifndef SF_NODELET_CLASS
#error \
    "SF_NODELET_CLASS is not defined: build nodelets with sf_add_filter(<name> <header> NODELET <xml>)"
#endif

#include <pluginlib/class_list_macros.hpp>

#include "sf_filter/definition/header_definition.hpp"
#include "sf_filter/node/fusion_nodelet.hpp"

namespace sf_nodelets {

class SF_NODELET_CLASS final : public sf_filter::FusionNodelet {
 public:
  SF_NODELET_CLASS() : FusionNodelet(sf_filter::generated::headerDefinition()) {}
};

}  // namespace sf_nodelets

PLUGINLIB_EXPORT_CLASS(sf_nodelets::SF_NODELET_CLASS, nodelet::Nodelet)
