// The step of a configuration header's filter on a state layout (QUATERNION_STATES: the
// layout EKF's corrections and a measured rotation's rows, UKF-M's propagation and
// corrections), which the node's unit (fusion_node_main.cpp) and its second unit
// (fusion_node_smoothers.cpp) declare extern: with the Jacobians and the smoothers in the
// second, the 3D headers' units were still over the package's 500 MB (doc/build_cost.md,
// "The 3D headers' step"). sf_add_filter() compiles this file beside the other two for a header
// that names QUATERNION_STATES (for any other it would stop after the header).
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#ifdef QUATERNION_STATES
#include <sf_filter/config/configuration.hpp>

// A configuration mistake is reported by the node's unit.
#if SF_CONFIG_OK && !SF_CFG_IS_AVERAGING
#include "sf_filter/config/filter_binding.hpp"

SF_CFG_SECOND_UNIT_INSTANCES(extern)    // the Jacobians, in the second unit
SF_CFG_JACOBIAN_UNIT_INSTANCES(extern)  // or that one in fusion_node_jacobians.cpp
SF_CFG_THIRD_UNIT_INSTANCES()
#endif  // SF_CONFIG_OK
#endif  // QUATERNION_STATES
