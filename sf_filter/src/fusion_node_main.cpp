// The fusion node generated from one configuration header. sf_add_filter() compiles this
// file once per header, with -DSF_CONFIG_HEADER="path/to/header.h", and links it with the
// prebuilt node library (the ROS node, the bag replay, diagnostics, parameters): only the
// header's model, filter and message readers are compiled here.
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#include <sf_filter/config/configuration.hpp>

// A configuration mistake has been reported above; generating the node would only add
// follow-up errors.
#if SF_CONFIG_OK

#include "sf_filter/generated/node_definition_of.hpp"

int main(int argc, char** argv) {
  return sf_filter::runFusionNode(argc, argv, sf_filter::generated::nodeDefinition());
}

#endif  // SF_CONFIG_OK
