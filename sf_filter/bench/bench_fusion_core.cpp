// Cost of the fusion node's own work beside the estimator, on the ROS-free FusionCore, for the
// nav3ctrl UKF node (config/nav3ctrl_ukf.h): per 100 ms estimation period the node receives
//   angular_velocity (Vector3Stamped)  100 Hz -> 10 values of input 0 (with header stamp)
//   acceleration     (Vector3Stamped)  100 Hz -> 10 values of input 1 (with header stamp)
//   velocity_wheel_left  (Float32)      10 Hz ->  1 value  of input 2 (no header)
//   velocity_wheel_right (Float32)      10 Hz ->  1 value  of input 3 (no header)
//   cmd_vel          (Twist)            10 Hz ->  1 message, 2 controls
// Like FusionNode, every message first advances the core to its arrival time (advanceTo), then
// hands its values over (addMeasurement / addControl); the period's timer tick advances the
// core to the period end, which aligns the inputs, runs the estimator and hands out the estimate.
//
// Benchmarks (one iteration = one 100 ms period, 23 messages + 1 timer tick):
//   FusionCore_period/UKF_nav3ctrl    (a) the whole period through FusionCore, estimate included
//   FusionCore_period/UKF_nav3ctrl_nis100  (a) with the NIS window of the node's default
//   UKF_nav3ctrl_step                 (b) the estimator alone: setControl + estimate on the
//                                         same aligned data (period means) the core produces
//   FusionCore_period/NullEstimator   the core around an estimator that does nothing: a direct
//                                     reading of the work outside the estimator
//   FusionCore_overhead/UKF_nav3ctrl  (a) and (b) interleaved in one loop, each timed with
//                                     steady_clock; counters period_us, estimator_us and
//                                     outside_us = (a) - (b) (means over the periods) and
//                                     their medians *_med_us. Iteration time = (a) (manual).
// Counters: allocs_per_period = heap allocations per period (operator new and malloc are
// replaced by sf_estimation/bench/support/allocation_counter.cpp; AllocationCounter_check shows
// they are counted); estimates_per_period
// must be 1.
//
// Run: rosrun sf_pkg sf_fusion_core_benchmark --benchmark_repetitions=10
//        --benchmark_report_aggregates_only=true
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>
#include <optional>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "sf_estimation/measurement.hpp"
#include "sf_estimation/models/navigation.hpp"
#include "sf_estimation/unscented_kalman_filter.hpp"
#include "sf_filter/core/fusion_core.hpp"
#include "sf_filter/core/period_average.hpp"
#include "support/allocation_counter.hpp"
#include "support/nav3_drive.hpp"

namespace {

using namespace estimation;
using models::Nav3Ctrl;
using Ukf = UnscentedKalmanFilter<Nav3Ctrl>;

using sf_bench::kPeriod;                    // ESTIMATION_PERIOD 100 ms (the drive's T)
using sf_bench::kRadius;                    // effective skid-steer radius [m]
constexpr std::size_t kDrivePeriods = 400;  // 40 s of driving, replayed in a loop
constexpr double kEpoch = 1.7e9;            // ROS wall-clock seconds: same double resolution

// -----------------------------------------------------------------------------
// The inputs of one period, as the node receives them.
// -----------------------------------------------------------------------------
enum class Kind { Measurement, Control };

struct Event {
  Kind kind;
  double offset;  ///< arrival time after the period start [s]
  Index input;    ///< measurement input (Kind::Measurement)
  double value;   ///< measurement value, or cmd_vel.linear.x
  double value2;  ///< cmd_vel.angular.z
  bool stamped;   ///< message with a header (Vector3Stamped): the stamp is checked
};

struct Period {
  std::vector<Event> events;  // in arrival order
  Measurement<4> aligned;     // what the core hands the estimator at the period end
  Vector<2> control;          // the control in force at the period end
};

// A simulated drive of the nav3ctrl model (smoothly varying speed and turn rate), observed
// with the sensor noise of R: gyro and accelerometer at 100 Hz, wheels and cmd_vel at 10 Hz.
std::vector<Period> simulateDrive() {
  const Vector<4> sigma = models::nav3MeasurementNoise().diagonal().cwiseSqrt();
  std::mt19937_64 engine(7);
  std::normal_distribution<double> normal;
  std::vector<Period> drive;
  for (const sf_bench::Nav3Step& step : sf_bench::simulateNav3Motion(kDrivePeriods)) {
    const Vector<2>& u = step.control;
    const Vector<4>& z = step.observation;

    Period p;
    p.control = u;
    p.events.push_back({Kind::Control, 0.020, 0, u(0), u(1), false});
    for (int j = 0; j < 10; ++j) {
      const double at = 0.01 * j;
      p.events.push_back(
          {Kind::Measurement, at + 0.003, 0, z(0) + sigma(0) * normal(engine), 0.0, true});
      p.events.push_back(
          {Kind::Measurement, at + 0.006, 1, z(1) + sigma(1) * normal(engine), 0.0, true});
    }
    p.events.push_back({Kind::Measurement, 0.045, 2, z(2) + sigma(2) * normal(engine), 0.0, false});
    p.events.push_back({Kind::Measurement, 0.047, 3, z(3) + sigma(3) * normal(engine), 0.0, false});
    std::stable_sort(p.events.begin(), p.events.end(),
                     [](const Event& a, const Event& b) { return a.offset < b.offset; });

    // The aligned measurement, computed exactly as FusionCore does (PeriodAverage::mean).
    std::vector<sf_filter::PeriodAverage> average(4);
    for (const Event& e : p.events) {
      if (e.kind == Kind::Measurement)
        average[static_cast<std::size_t>(e.input)].add(e.value, std::nullopt);
    }
    p.aligned = Measurement<4>(4);
    for (int i = 0; i < 4; ++i) {
      p.aligned.available(i) = true;
      p.aligned.varianceGiven(i) = false;
      p.aligned.value(i) = average[static_cast<std::size_t>(i)].mean();
      p.aligned.variance(i) = 0.0;
    }
    drive.push_back(std::move(p));
  }
  return drive;
}

const std::vector<Period>& drive() {
  static const std::vector<Period> instance = simulateDrive();
  return instance;
}

// The node's filter: UKF with nav3ctrl, Q, R of the header, x0 = 0, P0 = I, default UT.
Ukf makeUkf() {
  return Ukf(Nav3Ctrl{kPeriod, kRadius}, models::nav3ProcessNoise(), models::nav3MeasurementNoise(),
             Vector<7>::Zero(), Matrix<7, 7>::Identity());
}

/// An estimator that does nothing: FusionCore around it is the work outside the estimator.
struct NullEstimator {
  static constexpr int StateSize = 7;
  static constexpr int MeasurementSize = 4;
  static constexpr int ControlSize = 2;

  Index measurementSize() const { return MeasurementSize; }
  Index controlSize() const { return ControlSize; }
  void setControl(const Vector<2>& u) { u_ = u; }
  void estimate(const Measurement<4>& z) {
    benchmark::DoNotOptimize(&z);
    benchmark::DoNotOptimize(&u_);
  }
  const Vector<7>& state() const { return x_; }
  const Matrix<7, 7>& covariance() const { return P_; }

  Vector<7> x_ = Vector<7>::Zero();
  Matrix<7, 7> P_ = Matrix<7, 7>::Identity();
  Vector<2> u_ = Vector<2>::Zero();
};

// -----------------------------------------------------------------------------
// Feeding the core, as FusionNode does.
// -----------------------------------------------------------------------------
template <class Filter>
struct CoreDriver {
  using Core = sf_filter::FusionCore<Filter>;

  /// `nisWindow`: Options::nisWindow (0: no NIS, as the core's default; the node uses 100).
  explicit CoreDriver(Filter filter, std::size_t nisWindow = 0)
      : core(std::move(filter), options(nisWindow)) {
    core.advanceTo(kEpoch, sink());  // starts the schedule: the first period ends at kEpoch + T
  }

  static typename Core::Options options(std::size_t nisWindow) {
    typename Core::Options o;
    o.period = kPeriod;
    o.nisWindow = nisWindow;
    return o;
  }

  auto sink() {
    return [this](const typename Core::Estimate& e) {
      ++estimates;
      benchmark::DoNotOptimize(e.state.data());
      benchmark::DoNotOptimize(e.covariance.data());
    };
  }

  /// One period: every message (advanceTo its arrival, then its values), then the timer tick
  /// at the period end, which runs the estimate.
  void runPeriod(const Period& p) {
    const double start = kEpoch + static_cast<double>(index) * kPeriod;
    for (const Event& e : p.events) {
      const double now = start + e.offset;
      core.advanceTo(now, sink());
      if (e.kind == Kind::Measurement) {
        const double stamp = e.stamped ? now : std::numeric_limits<double>::quiet_NaN();
        benchmark::DoNotOptimize(core.addMeasurement(e.input, now, e.value, std::nullopt, stamp));
      } else {
        benchmark::DoNotOptimize(core.addControl(0, e.value));
        benchmark::DoNotOptimize(core.addControl(1, e.value2));
      }
    }
    ++index;
    core.advanceTo(kEpoch + static_cast<double>(index) * kPeriod, sink());
    benchmark::ClobberMemory();
  }

  Core core;
  std::uint64_t index = 0;  ///< periods run (the schedule never restarts)
  std::uint64_t estimates = 0;
};

/// Runs the drive in a loop; at its end the filter is reset outside the timed region.
template <class Filter>
void runPeriods(benchmark::State& state, Filter filter, std::size_t nisWindow = 0) {
  const auto& d = drive();
  CoreDriver<Filter> driver(std::move(filter), nisWindow);
  std::size_t k = 0, untimedAllocations = 0;
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    if (k == d.size()) {
      state.PauseTiming();
      const std::size_t start = sf_bench::heapAllocations();
      driver.core.reset();
      k = 0;
      untimedAllocations += sf_bench::heapAllocations() - start;
      state.ResumeTiming();
    }
    driver.runPeriod(d[k++]);
  }
  const auto allocations =
      static_cast<double>(sf_bench::heapAllocations() - before - untimedAllocations);
  state.counters["allocs_per_period"] =
      benchmark::Counter(allocations, benchmark::Counter::kAvgIterations);
  state.counters["estimates_per_period"] =
      benchmark::Counter(static_cast<double>(driver.estimates), benchmark::Counter::kAvgIterations);
  if (driver.core.estimationFailures() != 0) state.SkipWithError("estimation failed");
}

// (a) the whole period through FusionCore, estimate included.
void FusionCore_period_UKF_nav3ctrl(benchmark::State& state) { runPeriods(state, makeUkf()); }

// (a) with the NIS consistency check of the node's default (~nis_window 100): one more
// unscented transform per period for the predicted measurement.
void FusionCore_period_UKF_nav3ctrl_nis(benchmark::State& state) {
  runPeriods(state, makeUkf(), 100);
}

// The core around an estimator that does nothing.
void FusionCore_period_NullEstimator(benchmark::State& state) {
  runPeriods(state, NullEstimator{});
}

// (b) the estimator step alone on the aligned data of each period.
void UKF_nav3ctrl_step(benchmark::State& state) {
  const auto& d = drive();
  Ukf filter = makeUkf();
  std::size_t k = 0, untimedAllocations = 0;
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    if (k == d.size()) {
      state.PauseTiming();
      const std::size_t start = sf_bench::heapAllocations();
      filter.reset();
      k = 0;
      untimedAllocations += sf_bench::heapAllocations() - start;
      state.ResumeTiming();
    }
    filter.setControl(d[k].control);
    filter.estimate(d[k].aligned);
    ++k;
    benchmark::DoNotOptimize(filter.state().data());
    benchmark::ClobberMemory();
  }
  const auto allocations =
      static_cast<double>(sf_bench::heapAllocations() - before - untimedAllocations);
  state.counters["allocs_per_period"] =
      benchmark::Counter(allocations, benchmark::Counter::kAvgIterations);
}

// (a) and (b) interleaved, each timed with steady_clock: outside = (a) - (b) per period. A twin
// filter gets the aligned data directly; its state must equal the core's filter state after
// every period (the check that (b) estimates exactly what (a) does). Wall-clock intervals
// include any preemption of the thread, so besides the means the medians over the periods
// are reported (robust on a loaded machine): *_us are means, *_med_us medians, and
// outside_med_us is the median of the per-period differences (a) - (b).
void FusionCore_overhead_UKF_nav3ctrl(benchmark::State& state) {
  using Clock = std::chrono::steady_clock;
  const auto& d = drive();
  CoreDriver<Ukf> driver(makeUkf());
  Ukf twin = makeUkf();
  std::vector<double> full, estimator, outside;  // per period [s]
  const auto reserve =
      static_cast<std::size_t>(std::min<benchmark::IterationCount>(state.max_iterations, 10000000));
  full.reserve(reserve);
  estimator.reserve(reserve);
  outside.reserve(reserve);
  std::size_t k = 0;
  std::size_t periodAllocations = 0, estimatorAllocations = 0;
  bool identical = true;
  for (auto _ : state) {
    if (k == d.size()) {
      driver.core.reset();
      twin.reset();
      k = 0;
    }
    const Period& p = d[k++];

    std::size_t a0 = sf_bench::heapAllocations();
    const auto t0 = Clock::now();
    driver.runPeriod(p);
    const auto t1 = Clock::now();
    periodAllocations += sf_bench::heapAllocations() - a0;

    a0 = sf_bench::heapAllocations();
    const auto t2 = Clock::now();
    twin.setControl(p.control);
    twin.estimate(p.aligned);
    benchmark::DoNotOptimize(twin.state().data());
    benchmark::ClobberMemory();
    const auto t3 = Clock::now();
    estimatorAllocations += sf_bench::heapAllocations() - a0;

    const double a = std::chrono::duration<double>(t1 - t0).count();
    const double b = std::chrono::duration<double>(t3 - t2).count();
    state.SetIterationTime(a);
    if (full.size() < reserve) {
      full.push_back(a);
      estimator.push_back(b);
      outside.push_back(a - b);
    }
    if (twin.state() != driver.core.filter().state()) identical = false;
  }
  auto mean = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
  };
  auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  const auto n = static_cast<double>(state.iterations());
  state.counters["period_us"] = mean(full) * 1e6;
  state.counters["estimator_us"] = mean(estimator) * 1e6;
  state.counters["outside_us"] = mean(outside) * 1e6;
  state.counters["period_med_us"] = median(full) * 1e6;
  state.counters["estimator_med_us"] = median(estimator) * 1e6;
  state.counters["outside_med_us"] = median(outside) * 1e6;
  state.counters["allocs_per_period"] = static_cast<double>(periodAllocations) / n;
  state.counters["allocs_estimator"] = static_cast<double>(estimatorAllocations) / n;
  if (!identical) state.SkipWithError("the twin filter diverged from the core's filter");
}

// Check of the counter itself: one std::vector and one Eigen::VectorXd per iteration must
// read allocs_per_iteration=2, or the zeros above would mean nothing.
void AllocationCounter_check(benchmark::State& state) {
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    std::vector<double> v(16);
    Eigen::VectorXd e(16);
    benchmark::DoNotOptimize(v.data());
    benchmark::DoNotOptimize(e.data());
  }
  state.counters["allocs_per_iteration"] =
      benchmark::Counter(static_cast<double>(sf_bench::heapAllocations() - before),
                         benchmark::Counter::kAvgIterations);
}

}  // namespace

BENCHMARK(FusionCore_period_UKF_nav3ctrl)->Name("FusionCore_period/UKF_nav3ctrl");
BENCHMARK(FusionCore_period_UKF_nav3ctrl_nis)->Name("FusionCore_period/UKF_nav3ctrl_nis100");
BENCHMARK(UKF_nav3ctrl_step)->Name("UKF_nav3ctrl_step");
BENCHMARK(FusionCore_period_NullEstimator)->Name("FusionCore_period/NullEstimator");
BENCHMARK(FusionCore_overhead_UKF_nav3ctrl)
    ->Name("FusionCore_overhead/UKF_nav3ctrl")
    ->UseManualTime();
BENCHMARK(AllocationCounter_check);

BENCHMARK_MAIN();
