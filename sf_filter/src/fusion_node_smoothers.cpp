// The smoothers of one configuration header's filter (the replay's offline RTS and batch MAP
// smoothers, the fixed-lag smoother; core/*smoother_of.hpp), at the header's sizes with its
// model. sf_add_filter() compiles this file beside the header's node unit
// (fusion_node_main.cpp), which declares them extern: two units of about half the compile
// time and memory each, built side by side (doc/build_cost.md, "The smoothers' unit").
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#include <sf_filter/config/configuration.hpp>

// A configuration mistake is reported by the node's unit. The window filters have no
// smoothers (and their engines are compiled once, in the core library).
#if SF_CONFIG_OK && !SF_CFG_IS_AVERAGING

#include "sf_filter/config/filter_binding.hpp"
#include "sf_filter/core/fusion_engine_of.hpp"

SF_CFG_THIRD_UNIT_INSTANCES(extern)     // the step's unit (fusion_node_step.cpp)
SF_CFG_JACOBIAN_UNIT_INSTANCES(extern)  // fusion_node_jacobians.cpp
namespace sf_filter {
SF_FILTER_SMOOTHER_INSTANCES(, FusionCore<generated::Filter>)
}  // namespace sf_filter
SF_CFG_SECOND_UNIT_INSTANCES()

#endif  // SF_CONFIG_OK
