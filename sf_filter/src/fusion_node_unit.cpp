// The translation unit of a header built with sf_add_filter(... NODELET ...): the node's own
// unit (fusion_node_main.cpp: the header's NodeDefinition and the node's main) and
// headerDefinition() for the nodelet plugin (fusion_nodelet_plugin.cpp). Compiled once and
// linked into both the node and the plugin, which never calls main. A separate file, so that
// the units of the headers without a nodelet stay as they were (and in the compiler cache).
#include "fusion_node_main.cpp"

#if SF_CONFIG_OK
#include "sf_filter/definition/header_definition.hpp"

sf_filter::NodeDefinition sf_filter::generated::headerDefinition() { return nodeDefinition(); }
#endif
