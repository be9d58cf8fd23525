// The AutoDiff Jacobians of an EXTENDED_KALMAN_FILTER header, which the node's other units
// declare extern (doc/build_cost.md, "The Jacobians' unit"):
// - a planar header (no QUATERNION_STATES): the model's transition and observation Jacobians,
//   which the EKF's step (node unit) and the three smoothers (second unit) call; compiled in
//   both they took a 13-state header's two units over 500 MB; compiled here once, each EKF
//   header's largest unit is 30-70 MB smaller, for about 0.7 s more CPU in all;
// - a header with QUATERNION_STATES: the layout EKF's observation Jacobian (AutoDiff of
//   h(x [+] e) over the tangent); beside the transition Jacobian in the second unit
//   (fusion_node_smoothers.cpp) the two took it to 500 MB and over, as they instantiate much
//   of the same code (the layout's x [+] e, the rotation helpers on AutoDiff scalars) each.
// sf_add_filter() compiles this file for a header in which it finds EXTENDED_KALMAN_FILTER or
// QUATERNION_STATES (and then defines SF_FILTER_JACOBIAN_UNIT); for another method it stops
// after the header.
#ifndef SF_CONFIG_HEADER
#error "SF_CONFIG_HEADER is not defined: build fusion nodes with sf_add_filter(<name> <header>)"
#endif
#include SF_CONFIG_HEADER

#include <sf_filter/config/methods.hpp>

#if METHOD == EXTENDED_KALMAN_FILTER
#include <sf_filter/config/configuration.hpp>

// A configuration mistake is reported by the node's unit.
#if SF_CONFIG_OK
#include "sf_filter/config/filter_binding.hpp"

SF_CFG_JACOBIAN_UNIT_INSTANCES()
#endif  // SF_CONFIG_OK
#endif
