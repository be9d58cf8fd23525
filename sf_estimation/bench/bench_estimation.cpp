// Time of ONE estimation step (time update with the control, correction with a full
// measurement) of every filter on the thesis's robot models (section 5.1.2):
//   nav3ctrl  7 states, 4 measurements, 2 controls   (EKF, UKF, SIR PF)
//   nav3red   3 states, 4 measurements, 2 controls   (KF, EKF, UKF)
// each on the fixed-size path (template sizes, no heap) and on the factory's run-time-sized
// path (EstimatorFactory::create + IEstimator::estimate, as a ROS node uses it).
//
// Inputs come from a simulated drive replayed in a loop; at the end of the drive the filter
// is reset outside the timed region, so it never runs far from the data it was tuned for.
// The counter allocs_per_step is the number of heap allocations per step
// (support/allocation_counter.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include "sf_estimation/estimator_factory.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/function_model.hpp"
#include "sf_estimation/kalman_filter.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/particle_filter.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "support/allocation_counter.hpp"
#include "support/nav3_drive.hpp"

namespace {

using namespace estimation;
using models::Nav3Ctrl;
using models::Nav3Reduced;

using sf_bench::kPeriod;
using sf_bench::kRadius;

// -----------------------------------------------------------------------------
// Inputs: the simulated drive of support/nav3_drive.hpp, as each path takes them.
// -----------------------------------------------------------------------------
struct Drive {
  std::vector<Vector<2>> controls;
  std::vector<Measurement<4>> measurements;
  std::vector<Input> controlInputs, measurementInputs;  // the same, for IEstimator
};

Drive simulateDrive() {
  const sf_bench::Nav3Drive simulated = sf_bench::simulateNav3Drive();
  Drive drive;
  for (std::size_t k = 0; k < simulated.controls.size(); ++k) {
    const double t = kPeriod * static_cast<double>(k);
    const Vector<2>& u = simulated.controls[k];
    const Vector<4>& z = simulated.readings[k];
    drive.controls.push_back(u);
    drive.measurements.push_back(Measurement<4>::complete(z));
    Input controlInput, measurementInput;
    for (int i = 0; i < 2; ++i) controlInput.add(InputValue(u(i), t));
    for (int i = 0; i < 4; ++i) measurementInput.add(InputValue(z(i), t));
    drive.controlInputs.push_back(controlInput);
    drive.measurementInputs.push_back(measurementInput);
  }
  return drive;
}

const Drive& drive() {
  static const Drive instance = simulateDrive();
  return instance;
}

// -----------------------------------------------------------------------------
// The models as generic lambdas, for makeFunctionModel (factory path).
// -----------------------------------------------------------------------------
auto nav3ctrlTransition = [](const auto& x, const auto& u, auto& next) {
  using S = typename std::decay_t<decltype(next)>::Scalar;
  using std::cos;
  using std::sin;
  next(0) = x(0) + x(4) * cos(x(2));
  next(1) = x(1) + x(4) * sin(x(2));
  next(2) = x(2) + x(3) * kPeriod;
  next(3) = S(u(1));
  next(4) = x(5) * kPeriod;
  next(5) = x(5) + x(6) * kPeriod;
  next(6) = (u(0) - x(5)) / kPeriod;
};

auto nav3redTransition = [](const auto& x, const auto& u, auto& next) {
  using S = typename std::decay_t<decltype(next)>::Scalar;
  next(0) = S(u(1));
  next(1) = x(1) + x(2) * kPeriod;
  next(2) = (u(0) - x(1)) / kPeriod;
};

// Gyro, accelerometer and wheel speeds [mm/s] from omega, v and a at the given indices.
template <int Omega, int Speed, int Acceleration>
auto observationAt = [](const auto& x, auto& z) {
  z(0) = x(Omega);
  z(1) = x(Acceleration);
  z(2) = (x(Speed) - x(Omega) * kRadius) * 1000.0;
  z(3) = (x(Speed) + x(Omega) * kRadius) * 1000.0;
};

FunctionModel nav3ctrlFunctionModel() {
  return makeFunctionModel(7, 4, 2, nav3ctrlTransition, observationAt<3, 5, 6>);
}

FunctionModel nav3redFunctionModel() {
  return makeFunctionModel(3, 4, 2, nav3redTransition, observationAt<0, 1, 2>);
}

// -----------------------------------------------------------------------------
// Filters and their parameters.
// -----------------------------------------------------------------------------
const Matrix<3, 3> kReducedQ = models::nav3ReducedProcessNoise();
const Matrix<7, 7> kQ = models::nav3ProcessNoise();
const Matrix<7, 7> kParticleQ = models::nav3ParticleProcessNoise();
const Matrix<4, 4> kR = models::nav3MeasurementNoise();
constexpr std::uint64_t kSeed = 42;

KalmanFilter<3, 4, 2> makeKalman() {
  const Nav3Reduced m{kPeriod, kRadius};
  return KalmanFilter<3, 4, 2>(m.transitionMatrix(), m.controlMatrix(), m.observationMatrix(),
                               kReducedQ, kR);
}

ParameterMap gaussianParameters(const Eigen::MatrixXd& Q) {
  return {{"Q", Q}, {"R", Eigen::MatrixXd(kR)}};
}

std::unique_ptr<IEstimator> createKalman() {
  const Nav3Reduced m{kPeriod, kRadius};
  ParameterMap p = gaussianParameters(kReducedQ);
  p["A"] = Eigen::MatrixXd(m.transitionMatrix());
  p["B"] = Eigen::MatrixXd(m.controlMatrix());
  p["H"] = Eigen::MatrixXd(m.observationMatrix());
  return EstimatorFactory::create("KalmanFilter", p);
}

std::unique_ptr<IEstimator> createWithModel(const std::string& method, FunctionModel model,
                                            const Eigen::MatrixXd& Q) {
  ParameterMap p = gaussianParameters(Q);
  p["model"] = std::move(model);
  return EstimatorFactory::create(method, p);
}

std::unique_ptr<IEstimator> createParticle(int particles) {
  ParameterMap p = gaussianParameters(kParticleQ);
  p["model"] = nav3ctrlFunctionModel();
  p["particles"] = particles;
  p["seed"] = static_cast<int>(kSeed);
  return EstimatorFactory::create("ParticleFilterSIR", p);
}

ParticleFilterSIR<Nav3Ctrl> makeParticle(Index particles, bool sharedDeadReckoning = false) {
  ParticleFilterParameters params;
  params.particles = particles;
  params.sharedDeadReckoning = sharedDeadReckoning;
  params.seed = kSeed;
  return ParticleFilterSIR<Nav3Ctrl>(Nav3Ctrl{kPeriod, kRadius}, kParticleQ, kR, Vector<7>::Zero(),
                                     Matrix<7, 7>::Identity(), params);
}

// -----------------------------------------------------------------------------
// The timed loop, shared by both paths.
// -----------------------------------------------------------------------------

// One step of a fixed-size filter, or of an IEstimator.
template <class Filter>
void step(Filter& filter, const Drive& d, std::size_t k) {
  filter.setControl(d.controls[k]);
  filter.estimate(d.measurements[k]);
  benchmark::DoNotOptimize(filter.state().data());
  benchmark::ClobberMemory();
}

void step(IEstimator& estimator, const Drive& d, std::size_t k) {
  estimator.setControlInput(d.controlInputs[k]);
  benchmark::DoNotOptimize(estimator.estimate(d.measurementInputs[k]));
  benchmark::ClobberMemory();
}

template <class Filter>
void runSteps(benchmark::State& state, Filter& filter) {
  const Drive& d = drive();
  std::size_t k = 0, resetAllocations = 0;
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    if (k == d.controls.size()) {  // end of the drive: start again, untimed
      state.PauseTiming();
      const std::size_t start = sf_bench::heapAllocations();
      filter.reset();
      k = 0;
      resetAllocations += sf_bench::heapAllocations() - start;
      state.ResumeTiming();
    }
    step(filter, d, k++);
  }
  const auto allocations =
      static_cast<double>(sf_bench::heapAllocations() - before - resetAllocations);
  state.counters["allocs_per_step"] =
      benchmark::Counter(allocations, benchmark::Counter::kAvgIterations);
}

// -----------------------------------------------------------------------------
// Benchmarks: <method>_<model>_<path>.
// -----------------------------------------------------------------------------
void KF_nav3red_fixed(benchmark::State& state) {
  auto filter = makeKalman();
  runSteps(state, filter);
}

void KF_nav3red_factory(benchmark::State& state) {
  auto estimator = createKalman();
  runSteps(state, *estimator);
}

void EKF_nav3ctrl_fixed(benchmark::State& state) {
  ExtendedKalmanFilter<Nav3Ctrl> filter(Nav3Ctrl{kPeriod, kRadius}, kQ, kR);
  runSteps(state, filter);
}

void EKF_nav3ctrl_factory(benchmark::State& state) {
  auto estimator = createWithModel("ExtendedKalmanFilter", nav3ctrlFunctionModel(), kQ);
  runSteps(state, *estimator);
}

void EKF_nav3red_fixed(benchmark::State& state) {
  ExtendedKalmanFilter<Nav3Reduced> filter(Nav3Reduced{kPeriod, kRadius}, kReducedQ, kR);
  runSteps(state, filter);
}

void EKF_nav3red_factory(benchmark::State& state) {
  auto estimator = createWithModel("ExtendedKalmanFilter", nav3redFunctionModel(), kReducedQ);
  runSteps(state, *estimator);
}

void UKF_nav3ctrl_fixed(benchmark::State& state) {
  UnscentedKalmanFilter<Nav3Ctrl> filter(Nav3Ctrl{kPeriod, kRadius}, kQ, kR, Vector<7>::Zero(),
                                         Matrix<7, 7>::Identity());
  runSteps(state, filter);
}

void UKF_nav3ctrl_factory(benchmark::State& state) {
  auto estimator = createWithModel("UnscentedKalmanFilter", nav3ctrlFunctionModel(), kQ);
  runSteps(state, *estimator);
}

void UKF_nav3red_fixed(benchmark::State& state) {
  UnscentedKalmanFilter<Nav3Reduced> filter(Nav3Reduced{kPeriod, kRadius}, kReducedQ, kR,
                                            Vector<3>::Zero(), Matrix<3, 3>::Identity());
  runSteps(state, filter);
}

void UKF_nav3red_factory(benchmark::State& state) {
  auto estimator = createWithModel("UnscentedKalmanFilter", nav3redFunctionModel(), kReducedQ);
  runSteps(state, *estimator);
}

void PF_nav3ctrl_fixed(benchmark::State& state) {
  auto filter = makeParticle(state.range(0));
  runSteps(state, filter);
}

// The pose, heading and step length carried as one shared Gaussian (particle_filter.hpp).
void PF_nav3ctrl_shared_fixed(benchmark::State& state) {
  auto filter = makeParticle(state.range(0), true);
  runSteps(state, filter);
}

void PF_nav3ctrl_factory(benchmark::State& state) {
  auto estimator = createParticle(static_cast<int>(state.range(0)));
  runSteps(state, *estimator);
}

}  // namespace

BENCHMARK(KF_nav3red_fixed);
BENCHMARK(KF_nav3red_factory);
BENCHMARK(EKF_nav3ctrl_fixed);
BENCHMARK(EKF_nav3ctrl_factory);
BENCHMARK(EKF_nav3red_fixed);
BENCHMARK(EKF_nav3red_factory);
BENCHMARK(UKF_nav3ctrl_fixed);
BENCHMARK(UKF_nav3ctrl_factory);
BENCHMARK(UKF_nav3red_fixed);
BENCHMARK(UKF_nav3red_factory);
BENCHMARK(PF_nav3ctrl_fixed)->Arg(500)->Arg(700)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(PF_nav3ctrl_shared_fixed)->Arg(700)->Unit(benchmark::kMicrosecond);
BENCHMARK(PF_nav3ctrl_factory)->Arg(500)->Arg(700)->Arg(1000)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
