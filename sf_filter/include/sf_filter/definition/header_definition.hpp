// The NodeDefinition of the configuration header a translation unit was compiled with, for
// its nodelet plugin: defined by sf_filter/src/fusion_node_unit.cpp (the header's unit when
// sf_add_filter() is given NODELET), called by sf_filter/src/fusion_nodelet_plugin.cpp.
#pragma once

#include "sf_filter/definition/node_definition.hpp"

namespace sf_filter {
namespace generated {

NodeDefinition headerDefinition();

}  // namespace generated
}  // namespace sf_filter
