// One simulated run of Wang et al.'s set-up (section V): a robot moving along a line, its
// encoders at 1000 Hz and its vision at 32 Hz.
//
//   speed     s(k+1) = a s(k) + sqrt(1 - a^2) sigma_s n,   a = exp(-Delta / tau_s)
//   position  x(k+1) = x(k) + Delta (s(k) + s(k+1)) / 2
//   bias      b(k+1) = c b(k) + sqrt(1 - c^2) sigma_b n,   c = exp(-Delta / T)
//             (eq. 4 sampled exactly; b starts from its stationary distribution)
//   encoder   v(k+1) = v(k) + (x(k+1) - x(k)) + Delta b(k) + sqrt(q_w Delta) n
//             so that v' = x' + b_x + omega_x (eq. 1), omega_x white with density q_w
//   rate      v'(k) = (v(k) - v(k - d)) / (d Delta), the filters' control input
//   vision    u(i) = x(i Delta_u) + sigma_u n_i (x interpolated linearly between steps)
//
// Every n is an independent standard normal draw. The vision noise is stored as the unit
// draws n_i, so one run serves every column of Table II (sigma_u) and every method: the
// comparisons are made on common random numbers.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "parameters.hpp"

namespace wang_table2 {

struct VisionSample {
  double time = 0.0;       ///< [s]
  double position = 0.0;   ///< true x at `time`
  double unitNoise = 0.0;  ///< n_i: u = position + sigma_u n_i
};

struct SimulatedRun {
  std::vector<double> position;      ///< x(k) at t = k Delta_v, k = 0 .. steps
  std::vector<double> encoderRate;   ///< v'(k), k = 0 .. steps
  std::vector<double> bias;          ///< b(k), k = 0 .. steps (for tests and inspection)
  std::vector<VisionSample> vision;  ///< by time, 0 <= time < duration

  /// Number of encoder periods: k runs from 0 to steps().
  int steps() const { return static_cast<int>(position.size()) - 1; }
};

/// Steps of Delta_v in `duration` (rounded to the nearest whole step).
inline int stepsIn(double duration, double period) {
  return static_cast<int>(std::lround(duration / period));
}

inline SimulatedRun simulateRun(const Parameters& parameters, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double dt = parameters.encoderPeriod;
  const int steps = stepsIn(parameters.duration, dt);
  const int d = parameters.differenceSteps;
  const double speedDecay = std::exp(-dt / parameters.speedTimeConstant);
  const double speedKick = parameters.speedStd * std::sqrt(1.0 - speedDecay * speedDecay);
  const double biasDecay = std::exp(-dt / parameters.biasTimeConstant);
  const double biasKick = parameters.biasStd * std::sqrt(1.0 - biasDecay * biasDecay);
  const double encoderKick = std::sqrt(parameters.encoderNoiseDensity * dt);

  // The encoder runs d steps before t = 0 so that v'(0) is already a d-step difference;
  // index i of the local arrays is step k = i - d.
  const int total = steps + d;
  std::vector<double> x(static_cast<std::size_t>(total + 1)), v(x.size()), b(x.size());
  double speed = parameters.speedStd * normal(rng);
  b[0] = parameters.biasStd * normal(rng);
  for (int i = 0; i < total; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double nextSpeed = speedDecay * speed + speedKick * normal(rng);
    x[k + 1] = x[k] + dt * 0.5 * (speed + nextSpeed);
    v[k + 1] = v[k] + (x[k + 1] - x[k]) + dt * b[k] + encoderKick * normal(rng);
    b[k + 1] = biasDecay * b[k] + biasKick * normal(rng);
    speed = nextSpeed;
  }

  SimulatedRun run;
  run.position.assign(x.begin() + d, x.end());
  run.bias.assign(b.begin() + d, b.end());
  run.encoderRate.resize(run.position.size());
  for (int k = 0; k <= steps; ++k) {
    const auto i = static_cast<std::size_t>(k + d);
    run.encoderRate[static_cast<std::size_t>(k)] =
        (v[i] - v[i - static_cast<std::size_t>(d)]) / (d * dt);
  }
  for (int i = 0;; ++i) {
    const double t = i * parameters.visionPeriod;
    if (t >= parameters.duration) break;
    const double step = t / dt;
    const auto k = static_cast<std::size_t>(std::floor(step));
    const double fraction = step - static_cast<double>(k);
    const double position = k + 1 < run.position.size() ? (1.0 - fraction) * run.position[k] +
                                                              fraction * run.position[k + 1]
                                                        : run.position.back();
    run.vision.push_back({t, position, normal(rng)});
  }
  return run;
}

}  // namespace wang_table2
