// The simulated drive that the step benchmarks replay (bench_estimation.cpp, and the side-by-
// side run against mherb/kalman in peer/): the nav3ctrl model driven with smoothly varying
// speed and turn rate, observed with the sensor noise of R. nav3red observes the same
// quantities.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "sf_estimation/models/navigation.hpp"

namespace sf_bench {

constexpr double kPeriod = 0.1;           // T [s]
constexpr double kRadius = 0.3;           // R [m]
constexpr std::size_t kDriveSteps = 400;  // 40 s of driving, replayed in a loop

struct Nav3Drive {
  std::vector<estimation::Vector<2>> controls;  // (v, omega) commands
  std::vector<estimation::Vector<4>> readings;  // gyro, accelerometer, wheels
};

/// One step of the drive without sensor noise: the command and what the sensors would read.
struct Nav3Step {
  estimation::Vector<2> control;      // (v, omega)
  estimation::Vector<4> observation;  // h(x) after the step
};

/// `steps` steps of the nav3ctrl model under smoothly varying speed and turn rate (also the
/// fusion core's benchmark's drive, which adds its own sensor streams).
inline std::vector<Nav3Step> simulateNav3Motion(std::size_t steps) {
  using estimation::Vector;
  const estimation::models::Nav3Ctrl model{kPeriod, kRadius};
  std::vector<Nav3Step> motion;
  Vector<7> x = Vector<7>::Zero();
  for (std::size_t k = 0; k < steps; ++k) {
    const double t = kPeriod * static_cast<double>(k);
    Nav3Step step;
    step.control = Vector<2>(0.6 + 0.4 * std::sin(0.15 * t), 0.5 * std::sin(0.4 * t));
    Vector<7> next;
    model.transition(x, step.control, next);
    x = next;
    model.observation(x, step.observation);
    motion.push_back(step);
  }
  return motion;
}

inline Nav3Drive simulateNav3Drive() {
  const estimation::Vector<4> sigma =
      estimation::models::nav3MeasurementNoise().diagonal().cwiseSqrt();
  std::mt19937_64 engine(7);
  std::normal_distribution<double> normal;
  Nav3Drive drive;
  for (const Nav3Step& step : simulateNav3Motion(kDriveSteps)) {
    estimation::Vector<4> z = step.observation;
    for (int i = 0; i < 4; ++i) z(i) += sigma(i) * normal(engine);
    drive.controls.push_back(step.control);
    drive.readings.push_back(z);
  }
  return drive;
}

}  // namespace sf_bench
