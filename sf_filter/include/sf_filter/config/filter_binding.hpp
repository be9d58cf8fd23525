// Which estimator type a configuration header selects and how it is built from the (possibly
// overridden) parameters: what the methods share here, each method's own part in its traits
// header. Included by the generated translation unit after the configuration header and
// configuration.hpp.
#pragma once

#include <sf_estimation/angles.hpp>
#include <sf_estimation/filters.hpp>

namespace sf_filter {
namespace generated {

constexpr double periodSeconds(const sf_config::Parameters& p) {
  return p.estimation_period_ms / 1000.0;
}

/// ANGLE_STATES and ANGLE_INPUTS of the configuration header, for the model-based filters.
inline estimation::AngularComponents angularComponents() {
  estimation::AngularComponents angles;
  for (std::size_t i = 0; i < sf_config::kAngleStates.size(); ++i) {
    if (sf_config::kAngleStates[i]) angles.states.push_back(static_cast<estimation::Index>(i));
  }
  for (std::size_t i = 0; i < sf_config::kAngleInputs.size(); ++i) {
    if (sf_config::kAngleInputs[i])
      angles.measurements.push_back(static_cast<estimation::Index>(i));
  }
  return angles;
}

#if SF_CFG_IS_MODEL_BASED
/// An EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER or PARTICLE_FILTER_SIR of the header's
/// model: the arguments they share, with the method's own parameters (`own`) before the angles.
template <class Filter, class... Own>
Filter makeModelFilter(const sf_config::Parameters& p, const Own&... own) {
  sf_config::Model model;
  model.T = periodSeconds(p);
  return Filter(model, p.process_noise_covariance, p.measurement_noise_covariance, p.initial_state,
                p.initial_error_covariance, own..., angularComponents());
}
#endif

}  // namespace generated
}  // namespace sf_filter

// Filter and makeFilter(const sf_config::Parameters&) of the chosen method, from its traits
// header (config/methods/<method>.hpp, SF_METHOD_PART_BINDING). A model-based method's
// makeFilter is a template (of a defaulted, unused parameter): an inline function's body is
// compiled, and the filter's construction instantiated, in every unit that includes it, the
// node's second unit too, which never builds the filter (doc/build_cost.md).
#define SF_METHOD_PART SF_METHOD_PART_BINDING
#include "sf_filter/config/methods.hpp"
#undef SF_METHOD_PART

// What of the header's filter a node built by sf_add_filter() compiles in its second unit
// (fusion_node_smoothers.cpp) besides the smoothers: declared extern (PREFIX extern) in the
// node's unit, instantiated (PREFIX empty) in the second, at global scope. A method whose
// model-dependent code is too large for one unit defines it in its binding part; nothing
// otherwise (doc/build_cost.md, "The 3D headers' Jacobians and the particle filter's step").
#ifndef SF_CFG_SECOND_UNIT_INSTANCES
#define SF_CFG_SECOND_UNIT_INSTANCES(PREFIX)
#endif
// Likewise the third unit (fusion_node_step.cpp), which includes the configuration layer only
// for a header with QUATERNION_STATES: the layout filters' step (doc/build_cost.md, "The 3D
// headers' step").
#ifndef SF_CFG_THIRD_UNIT_INSTANCES
#define SF_CFG_THIRD_UNIT_INSTANCES(PREFIX)
#endif
// And the Jacobians' unit (fusion_node_jacobians.cpp): an EXTENDED_KALMAN_FILTER header's
// AutoDiff Jacobians (doc/build_cost.md, "The Jacobians' unit"). sf_add_filter() compiles it,
// and defines SF_FILTER_JACOBIAN_UNIT, for a header in which it finds EXTENDED_KALMAN_FILTER
// or QUATERNION_STATES by a look at the text; where it did not (a header that names the
// method through a macro of another file, a unit of a test or tool), the Jacobians are
// instantiated where they are used, as before the unit. This file is not part of the
// precompiled prelude, which a macro tested there would disable (GCC refuses a precompiled
// header when a command-line macro appears in it).
#if !defined(SF_FILTER_JACOBIAN_UNIT)
#undef SF_CFG_JACOBIAN_UNIT_INSTANCES
#endif
#ifndef SF_CFG_JACOBIAN_UNIT_INSTANCES
#define SF_CFG_JACOBIAN_UNIT_INSTANCES(PREFIX)
#endif
