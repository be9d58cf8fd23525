// The thesis's moving-train example (section 2.2.1) estimated by every method of sf_estimation.
//
// A train accelerates, cruises, brakes and stops. Three simulated sensors observe it:
//   v1  speedometer           v + N(0, 0.5^2)  [m/s]
//   a   accelerometer         a + N(0, 0.2^2)  [m/s^2], drops every 3rd sample (missing)
//   v2  second speedometer    v + N(0, 1.0^2)  [m/s], noisier
// Every method is built by EstimatorFactory::create and driven through IEstimator only:
//   KF, EKF, UKF, PF: state (v, a), measurements (v1, a, v2), i.e. the thesis's model with a
//                     third row of H for the second speedometer
//   MovingAverage, MovingMedian: (v1, a), each entry smoothed on its own
//   ConfidenceWeightedAveraging: (v1, v2), fused by their variances
// The table gives the RMSE against the true v and a and the mean time of one estimate() call.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/function_model.hpp"
#include "sf_estimation/probability/gaussian.hpp"

namespace {

using estimation::EstimatorFactory;
using estimation::Input;
using estimation::InputValue;
using estimation::ParameterMap;

constexpr double kSigma[3] = {0.5, 0.2, 1.0};  // noise of v1, a, v2
constexpr int kAccelerometer = 1;              // row of the accelerometer in the sensor matrix
constexpr int kDropEvery = 3;                  // the accelerometer misses every 3rd sample

struct Options {
  long seed = 42;
  long steps = 1200;
  double period = 0.1;  // T of the model and of the simulation
};

const char kUsage[] =
    "usage: sf_moving_train [--seed N] [--steps N] [--period T] [--help]\n"
    "  --seed N    seed of the sensor noise and of the particle filter (default 42)\n"
    "  --steps N   number of estimation steps (default 1200)\n"
    "  --period T  estimation period T in seconds (default 0.1)\n";

// A number in [low, high] (whole when `integer`), or throws. All of the text must parse: "12x"
// must not silently become 12.
double parseNumber(const std::string& option, const std::string& text, double low, double high,
                   bool integer) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= low && value <= high) ||
      (integer && value != std::floor(value))) {
    char range[64];
    std::snprintf(range, sizeof range, " in [%.10g, %.10g]", low, high);
    throw std::invalid_argument(option + " needs " + (integer ? "an integer" : "a number") + range +
                                ", got '" + text + "'");
  }
  return value;
}

// Returns false when --help was given. Accepts "--option value" and "--option=value".
bool parseOptions(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    std::string option = argv[i], value;
    if (option == "--help" || option == "-h") return false;
    if (const std::size_t equals = option.find('='); equals != std::string::npos) {
      value = option.substr(equals + 1);
      option.erase(equals);
    } else if (option == "--seed" || option == "--steps" || option == "--period") {
      if (i + 1 >= argc) throw std::invalid_argument(option + " needs a value");
      value = argv[++i];
    }
    if (option == "--seed") {  // the factory takes the PF seed as a non-negative int
      options.seed = static_cast<long>(parseNumber(option, value, 0, 2147483647, true));
    } else if (option == "--steps") {
      options.steps = static_cast<long>(parseNumber(option, value, 1, 1e7, true));
    } else if (option == "--period") {
      options.period = parseNumber(option, value, 1e-3, 10, false);
    } else {
      throw std::invalid_argument("unknown option '" + std::string(argv[i]) + "'");
    }
  }
  return true;
}

// 1 inside [begin, end) with linear ramps at both ends: limited jerk, as a real train has.
double trapezoid(double t, double begin, double end) {
  if (t < begin || t >= end) return 0.0;
  const double ramp = std::min(2.0, 0.5 * (end - begin));
  return std::min({1.0, (t - begin) / ramp, (end - t) / ramp});
}

struct Simulation {
  Eigen::VectorXd v, a;  // truth at each step
  Eigen::MatrixXd z;     // sensors (v1, a, v2) x steps
};

Simulation simulate(const Options& o) {
  const long n = o.steps;
  const double T = o.period, duration = static_cast<double>(n) * T;
  Eigen::VectorXd accelerate(n), brake(n);
  for (long k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * T;
    accelerate(k) = trapezoid(t, 0.05 * duration, 0.40 * duration);
    brake(k) = trapezoid(t, 0.68 * duration, 0.92 * duration);
  }
  Simulation s;
  // Braking is scaled to cancel the acceleration exactly, so the train ends at standstill.
  const double braking = brake.sum() > 0.0 ? 0.6 * accelerate.sum() / brake.sum() : 0.0;
  s.a = 0.6 * accelerate - braking * brake;
  s.v = Eigen::VectorXd::Zero(n);
  for (long k = 1; k < n; ++k) s.v(k) = s.v(k - 1) + s.a(k - 1) * T;  // exactly the model
  // Boost's normal sampler (used by the library) gives the same draws on every platform.
  estimation::probability::RandomEngine engine(static_cast<std::uint64_t>(o.seed));
  s.z.resize(3, n);
  estimation::probability::fillStandardNormal(engine, s.z);
  for (int row = 0; row < 3; ++row) {
    s.z.row(row) = kSigma[row] * s.z.row(row) + (row == kAccelerometer ? s.a : s.v).transpose();
  }
  return s;
}

bool accelerometerPresent(long k) { return k % kDropEvery != kDropEvery - 1; }

struct Setup {
  std::vector<int> sensors;  // rows of the sensor matrix fed to the method, in this order
  ParameterMap parameters;
};

std::map<std::string, Setup> makeSetups(const Options& o) {
  const double T = o.period;
  Eigen::MatrixXd A(2, 2), H(3, 2);
  A << 1, T, 0, 1;  // v' = v + a T, a' = a
  H << 1, 0, 0, 1, 1, 0;
  // White-noise jerk of spectral density q: the model's "a' = a" is wrong while a ramps.
  const double q = 0.02;
  Eigen::MatrixXd Q(2, 2);
  Q << q * T * T * T / 3, q * T * T / 2, q * T * T / 2, q * T;
  const Eigen::Vector3d variances = Eigen::Map<const Eigen::Vector3d>(kSigma).array().square();
  const Eigen::MatrixXd R = variances.asDiagonal();
  // Generic lambdas: instantiated with AutoDiff scalars too, so the EKF gets exact Jacobians.
  const estimation::FunctionModel model = estimation::makeFunctionModel(
      2, 3, 0,
      [T](const auto& x, const auto& /*u*/, auto& next) {
        next(0) = x(0) + x(1) * T;
        next(1) = x(1);
      },
      [](const auto& x, auto& z) {
        z(0) = x(0);
        z(1) = x(1);
        z(2) = x(0);
      });
  const std::vector<int> all = {0, 1, 2};
  // Window of about 1 s: a longer one lags behind the ramps, a shorter one keeps more noise.
  const int window = static_cast<int>(std::max(1L, std::lround(1.0 / T)));
  return {
      {"KalmanFilter", {all, {{"A", A}, {"H", H}, {"Q", Q}, {"R", R}}}},
      {"ExtendedKalmanFilter", {all, {{"model", model}, {"Q", Q}, {"R", R}}}},
      {"UnscentedKalmanFilter", {all, {{"model", model}, {"Q", Q}, {"R", R}}}},
      {"ParticleFilterSIR",
       {all,
        {{"model", model},
         {"Q", Q},
         {"R", R},
         {"particles", 1000},
         {"seed", static_cast<int>(o.seed)}}}},
      {"MovingAverage", {{0, 1}, {{"input-count", 2}, {"window-size", window}}}},
      {"MovingMedian", {{0, 1}, {{"input-count", 2}, {"window-size", window}}}},
      {"ConfidenceWeightedAveraging",
       {{0, 2}, {{"variances", Eigen::VectorXd(Eigen::Vector2d(variances(0), variances(2)))}}}},
  };
}

struct Row {
  std::string name;
  double rmseV = NAN, rmseA = NAN, micros = NAN;  // NaN prints as "-"
};

// Output entry 0 is v for every method; entry 1, where there is one, is a. The time is the
// best of 3 identical runs (reset() in between), so that a run preempted by another process
// does not dominate; the runs are identical because reset() also re-seeds the PF.
Row run(const std::string& name, const Setup& setup, const Simulation& s, double T) {
  auto estimator = EstimatorFactory::create(name, setup.parameters);
  Row result{name, NAN, NAN, INFINITY};
  const long n = s.z.cols();
  for (int repeat = 0; repeat < 3; ++repeat) {
    estimator->reset();
    double squaresV = 0.0, squaresA = 0.0;
    std::chrono::steady_clock::duration spent{};
    for (long k = 0; k < n; ++k) {
      Input input;
      for (int row : setup.sensors) {
        const bool present = row != kAccelerometer || accelerometerPresent(k);
        input.add(present ? InputValue(s.z(row, k), static_cast<double>(k) * T)
                          : InputValue::missing());
      }
      const auto start = std::chrono::steady_clock::now();
      const estimation::Output x = estimator->estimate(input);
      spent += std::chrono::steady_clock::now() - start;
      squaresV += std::pow(x[0].getValue() - s.v(k), 2);
      if (x.size() > 1) squaresA += std::pow(x[1].getValue() - s.a(k), 2);
    }
    result.micros =
        std::min(result.micros, std::chrono::duration<double, std::micro>(spent).count() / n);
    result.rmseV = std::sqrt(squaresV / n);
    if (estimator->getLastEstimate().size() > 1) result.rmseA = std::sqrt(squaresA / n);
  }
  return result;
}

void printCell(double value, int width, int precision) {
  if (std::isnan(value)) return (void)std::printf("%*s", width, "-");
  std::printf("%*.*f", width, precision, value);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    if (!parseOptions(argc, argv, options)) {
      std::cout << kUsage;
      return 0;
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "sf_moving_train: error: " << e.what() << "\n" << kUsage;
    return 2;
  }
  const Simulation s = simulate(options);
  std::printf("Moving train (thesis 2.2.1): %ld steps, T = %g s, seed %ld, peak v = %.2f m/s\n",
              options.steps, options.period, options.seed, s.v.maxCoeff());
  std::printf("Sensor noise (std. dev.): v1 %.2f m/s, a %.2f m/s^2, v2 %.2f m/s\n", kSigma[0],
              kSigma[1], kSigma[2]);
  std::printf(
      "Missing measurements: the accelerometer misses 1 sample in %d (%ld of %ld), given\n"
      "  as InputValue::missing() to KF/EKF/UKF/PF and to MovingAverage/MovingMedian\n\n",
      kDropEvery, options.steps / kDropEvery, options.steps);

  // Raw sensors as the baseline; the accelerometer only over the samples that arrived.
  Row raw{"raw sensors (v1; a)", 0.0, 0.0, NAN};
  long arrived = 0;
  for (long k = 0; k < options.steps; ++k) {
    raw.rmseV += std::pow(s.z(0, k) - s.v(k), 2);
    if (!accelerometerPresent(k)) continue;
    raw.rmseA += std::pow(s.z(1, k) - s.a(k), 2);
    ++arrived;
  }
  raw.rmseV = std::sqrt(raw.rmseV / options.steps);
  raw.rmseA = arrived ? std::sqrt(raw.rmseA / arrived) : NAN;
  std::vector<Row> rows = {raw};

  // Every registered method; one without a setup here is an error, not a silent omission.
  const auto setups = makeSetups(options);
  try {
    for (const std::string& name : EstimatorFactory::methods()) {
      const auto setup = setups.find(name);
      if (setup == setups.end()) throw std::logic_error("no setup for method " + name);
      rows.push_back(run(name, setup->second, s, options.period));
    }
  } catch (const std::exception& e) {
    std::cerr << "sf_moving_train: error: " << e.what() << "\n";
    return 1;
  }

  std::printf("%-30s %14s %16s %16s\n", "method", "RMSE v [m/s]", "RMSE a [m/s^2]",
              "time/step [us]");  // time: mean per estimate() call
  for (const Row& row : rows) {
    std::printf("%-30s ", row.name.c_str());
    printCell(row.rmseV, 14, 4);
    printCell(row.rmseA, 17, 4);
    printCell(row.micros, 17, 2);
    std::printf("\n");
  }
  return 0;
}
