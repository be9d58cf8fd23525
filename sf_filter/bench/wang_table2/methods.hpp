// The three rows of Wang et al.'s Table II, each run through the fusion node's ROS-free core
// (sf_filter::FusionCore) exactly as the node would run it: one input (vision), one control
// (the encoder rate), estimation period Delta_v = 1 ms, the input's alignment policy:
//
//   Kalman filter     SAMPLED: the vision value in the period it arrives in, missing in the
//                     others (time update only) - the filter of [10], footnote 3
//   Multi-rate hold   HOLD BEZIER (N_m - 1): between samples the Bezier extrapolation of the
//                     newest N_m vision samples, filter R = R_m (footnote 4)
//   Filling           FILL omega N: Wang et al.'s Algorithm 1, filter R (footnote 2)
//
// Events reach the core in time order, as they would reach the node: at t_k = k Delta_v the
// encoder's rate v'(k) arrives (addControl) and is used by the period ending at t_{k+1}; a
// vision sample arrives at its own time and belongs to the period containing it. The error
// of the estimate handed out at t_k is x^(t_k) - x(t_k).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include <sf_filter/core/fusion_core.hpp>

#include "bias_model.hpp"
#include "error_statistics.hpp"
#include "simulation.hpp"

namespace wang_table2 {

enum class Method { Kalman, Hold, Fill };

constexpr Method kMethods[] = {Method::Kalman, Method::Hold, Method::Fill};

inline const char* nameOf(Method m) {
  switch (m) {
    case Method::Kalman:
      return "Kalman filter";
    case Method::Hold:
      return "Multi-rate hold";
    case Method::Fill:
      return "Filling (FILL)";
  }
  return "?";
}

inline sf_filter::AlignmentPolicy policyOf(Method m, const Parameters& parameters) {
  switch (m) {
    case Method::Kalman:
      return sf_filter::AlignmentPolicy::sampled();
    case Method::Hold:
      return sf_filter::AlignmentPolicy::hold(sf_filter::HoldPrimitive::Bezier,
                                              parameters.holdSamples - 1);
    case Method::Fill:
      return sf_filter::AlignmentPolicy::fill(parameters.omega, parameters.fillSamples);
  }
  return {};
}

inline double measurementVarianceOf(Method m, const Parameters& parameters) {
  switch (m) {
    case Method::Kalman:
      return parameters.kalmanR;
    case Method::Hold:
      return parameters.holdR;
    case Method::Fill:
      return parameters.fillR;
  }
  return parameters.kalmanR;
}

using Core = sf_filter::FusionCore<BiasFilter>;

/// Runs one method on one simulated run with vision noise `visionStd` and returns the error
/// series from the warm-up on. Throws std::runtime_error if the filter failed a step.
inline ErrorSeries runMethod(const SimulatedRun& run, const Parameters& parameters, Method method,
                             double visionStd) {
  Core::Options options;
  options.period = parameters.encoderPeriod;
  sf_filter::InputOptions vision;
  vision.alignment = policyOf(method, parameters);
  options.inputs = {vision};
  Core core(makeBiasFilter(parameters, measurementVarianceOf(method, parameters), run.position[0]),
            options);

  ErrorSeries errors;
  const auto collect = [&](const Core::Estimate& e) {
    if (e.time < parameters.warmup - 1e-9) return;
    const auto k = static_cast<std::size_t>(std::lround(e.time / parameters.encoderPeriod));
    errors.add(e.state(0) - run.position.at(k));
  };
  core.advanceTo(0.0, collect);
  std::size_t nextVision = 0;
  for (int step = 0; step < run.steps(); ++step) {
    core.addControl(0, run.encoderRate[static_cast<std::size_t>(step)]);
    const double periodEnd = (step + 1) * parameters.encoderPeriod;
    // The vision samples of the period [t_k, t_k+1). The node would also advance the clock to
    // each arrival; no period ends inside, so that would change nothing here - except that a
    // second advanceTo() to the time of a period end already reached is taken as the clock
    // jumping backwards and resets the filter (doc/wang_table2.md, "Core issue found").
    for (; nextVision < run.vision.size() && run.vision[nextVision].time < periodEnd - 1e-9;
         ++nextVision) {
      const VisionSample& u = run.vision[nextVision];
      core.addMeasurement(0, u.time, u.position + visionStd * u.unitNoise);
    }
    core.advanceTo(periodEnd, collect);
  }
  if (core.clockResets() > 0) {
    throw std::runtime_error(std::string(nameOf(method)) + ": the core reset its clock " +
                             std::to_string(core.clockResets()) + " times");
  }
  if (core.estimationFailures() > 0) {
    throw std::runtime_error(std::string(nameOf(method)) + ": the filter failed " +
                             std::to_string(core.estimationFailures()) +
                             " steps, last: " + core.lastFailure());
  }
  return errors;
}

}  // namespace wang_table2
