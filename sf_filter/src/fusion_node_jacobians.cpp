// The observation Jacobian of an EXTENDED_KALMAN_FILTER header on a state layout
// (QUATERNION_STATES: AutoDiff of h(x [+] e) over the tangent), which the node's other units
// declare extern: beside the transition Jacobian in the second unit (fusion_node_smoothers.cpp)
// the two took it to 500 MB and over, as they instantiate much of the same code (the layout's
// x [+] e, the rotation helpers on AutoDiff scalars) each (doc/build_cost.md, "The observation
// Jacobian's unit"). sf_add_filter() compiles this file beside the step's unit
// (fusion_node_step.cpp) for a header that names QUATERNION_STATES; for another method it stops
// after the header.
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#include <sf_filter/config/methods.hpp>

#if defined(QUATERNION_STATES) && METHOD == EXTENDED_KALMAN_FILTER
#include <sf_filter/config/configuration.hpp>

// A configuration mistake is reported by the node's unit.
#if SF_CONFIG_OK
#include "sf_filter/config/filter_binding.hpp"

SF_CFG_OBSERVATION_UNIT_INSTANCES()
#endif  // SF_CONFIG_OK
#endif
