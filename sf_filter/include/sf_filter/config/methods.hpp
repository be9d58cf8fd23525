// The registry of the estimation methods selectable in a configuration header with
//   #define METHOD <one of the names below>
// (thesis section 4.3.5, "pre_config.h"). Each method is a distinct integer so that the
// configuration machinery can compare METHOD in #if directives. The value 0 is deliberately
// unused: an unknown identifier evaluates to 0 in #if.
//
// Everything else about a method is in its traits header, config/methods/<method>.hpp: its
// name and kind, the macros it needs or refuses, the checks of its own macros and how its
// filter is built. The configuration reads the traits in passes (SF_METHOD_PART below): each
// pass includes every traits header, and each header answers the pass for its own method
// only (or, for SF_METHOD_PART_UNUSED, when its method is NOT the chosen one). Preprocessor
// passes rather than C++ traits because the macro checks must be #error directives: only those
// stop the compilation before the follow-up errors (configuration.hpp).
//
// The order of the #includes below is that of the parameters (FilterParameters, the list of
// known ROS parameters) and of the unused-macro warnings.
//
// Adding a method: its traits header, and three lines here (its value, its #include, its name
// in the lists of the METHOD checks). doc/configuration.md, "Adding a filter method".
#ifndef SF_FILTER_CONFIG_METHODS_HPP
#define SF_FILTER_CONFIG_METHODS_HPP

#define KALMAN_FILTER 1
#define EXTENDED_KALMAN_FILTER 2
#define UNSCENTED_KALMAN_FILTER 3
#define PARTICLE_FILTER_SIR 4
#define MOVING_AVERAGE 5
#define MOVING_MEDIAN 6
#define CONFIDENCE_WEIGHTED_AVERAGING 7

// Kinds of method (SF_CFG_METHOD_KIND): what the shared checks and the generated model need.
#define SF_METHOD_KIND_LINEAR 1  // matrices A, B, H (KALMAN_FILTER)
#define SF_METHOD_KIND_MODEL 2   // STATE_TRANSITION_MODEL and OBSERVATION_MODEL as expressions
#define SF_METHOD_KIND_WINDOW 3  // averages the inputs, no model, no controls

// The passes, in the order configuration.hpp runs them.
#define SF_METHOD_PART_DECLARE 1  // SF_CFG_METHOD_NAME, SF_CFG_METHOD_KIND (validation.hpp)
#define SF_METHOD_PART_MACROS 2   // #error for macros the method needs or refuses (validation.hpp)
#define SF_METHOD_PART_UNUSED 3   // #pragma GCC warning for its own macros when not chosen
#define SF_METHOD_PART_CHECKS 4   // static_assert on the values of its own macros (checks.hpp)
#define SF_METHOD_PART_BINDING 5  // Filter and makeFilter (filter_binding.hpp)
// Not a pass of the configuration: SF_METHOD_PARAMETER(type, name, default, header_default)
// per run-time parameter of every method, whatever METHOD (sf_config::Parameters,
// FilterParameters, ros_parameters.hpp and the conversions between them expand it).
#define SF_METHOD_PART_PARAMETERS 6
// Not a pass either: SF_METHOD_TUNING(name, refusal) of the methods that declare one, read by
// tuningRefusal (noise_tuning.cpp); a method without one is refused as having no innovation.
#define SF_METHOD_PART_TUNING 7

// The names, for the messages of the METHOD checks (an #error cannot expand a macro, so the
// #error lines below spell them too).
#define SF_METHOD_NAMES                                                                   \
  "KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER, PARTICLE_FILTER_SIR, " \
  "MOVING_AVERAGE, MOVING_MEDIAN, CONFIDENCE_WEIGHTED_AVERAGING"

#endif  // SF_FILTER_CONFIG_METHODS_HPP

// clang-format off
#if defined(SF_METHOD_CHECK_DEFINED) && !defined(SF_METHOD_CHECKED_DEFINED)
#define SF_METHOD_CHECKED_DEFINED
// Included by validation.hpp with SF_METHOD_CHECK_DEFINED: METHOD is defined and not empty.
#if !defined(METHOD)
#error METHOD is not defined: add e.g. #define METHOD EXTENDED_KALMAN_FILTER to the configuration header (one of KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER, PARTICLE_FILTER_SIR, MOVING_AVERAGE, MOVING_MEDIAN, CONFIDENCE_WEIGHTED_AVERAGING)
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif BOOST_PP_IS_EMPTY(METHOD)
#error METHOD is defined but empty: expected one of KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER, PARTICLE_FILTER_SIR, MOVING_AVERAGE, MOVING_MEDIAN, CONFIDENCE_WEIGHTED_AVERAGING
#define SF_CFG_FATAL
#define SF_CFG_STOP
#endif
#endif

#if defined(SF_METHOD_PART)
#include "sf_filter/config/methods/kalman_filter.hpp"
#include "sf_filter/config/methods/extended_kalman_filter.hpp"
#include "sf_filter/config/methods/particle_filter_sir.hpp"
#include "sf_filter/config/methods/unscented_kalman_filter.hpp"
#include "sf_filter/config/methods/moving_average.hpp"
#include "sf_filter/config/methods/moving_median.hpp"
#include "sf_filter/config/methods/confidence_weighted_averaging.hpp"
#endif
// clang-format on
