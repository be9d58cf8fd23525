// Cost and gain of fixed-lag smoothing (fixed_lag_smoother.hpp): per period, one step of an EKF
// on the smoother tests' unicycle (x, y, heading; speed and turn rate as controls; a position
// fix every third period, the truth perturbed by Q; smoother_test_problems.hpp) and the
// fixed-lag smoother's add() with the lag given in periods (0: the filter alone). Besides the
// time, the counters give the position RMSE against the truth of the filtered estimate and of
// the estimate smoothed with the lag (each at the period it estimates), and the heap
// allocations per period. The drive of 400 periods restarts, untimed, when it ends.
#include <cstddef>

#include <benchmark/benchmark.h>

#include "../test/smoother_test_problems.hpp"
#include "sf_estimation/extended_kalman_filter.hpp"
#include "sf_estimation/fixed_lag_smoother.hpp"
#include "support/allocation_counter.hpp"

namespace {

using Filter = estimation::ExtendedKalmanFilter<sftest::Unicycle>;
using Period = estimation::FilteredPeriod<3, 2>;

/// Squared position errors summed over the periods scored.
struct PositionErrors {
  double sum = 0.0;
  std::size_t periods = 0;
  void add(const estimation::Vector<3>& estimate, const estimation::Vector<3>& truth) {
    sum += (estimate.head<2>() - truth.head<2>()).squaredNorm();
    ++periods;
  }
  double rmse() const { return std::sqrt(sum / static_cast<double>(periods)); }
};

void EKF_unicycle_fixed_lag(benchmark::State& state) {
  static const sftest::UnicycleDrive drive(400, 11, 1.0);
  const auto& p = drive.problem;
  const auto lag = static_cast<std::size_t>(state.range(0));
  Filter filter(p.model, p.Q, p.R, p.x0, p.P0, p.angles);
  auto smoother = estimation::fixedLagSmootherFor(filter, lag);
  PositionErrors filtered, lagged;
  std::size_t k = 0, untimedAllocations = 0;
  const std::size_t before = sf_bench::heapAllocations();
  for (auto _ : state) {
    if (k == 0 || k == p.z.size()) {  // (re)start: the initial belief as period 0, untimed
      state.PauseTiming();
      const std::size_t start = sf_bench::heapAllocations();
      filter.reset();
      smoother.clear();
      if (lag > 0) smoother.add(Period::of(filter, false));
      k = 1;
      untimedAllocations += sf_bench::heapAllocations() - start;
      state.ResumeTiming();
    }
    filter.setControl(p.u[k]);
    filter.estimate(p.z[k]);
    const auto* smoothed = lag > 0 ? smoother.add(Period::of(filter)) : nullptr;
    benchmark::DoNotOptimize(smoothed);
    // Scoring is timed too: a few flops beside a step of microseconds, cheaper than pausing.
    filtered.add(filter.state(), drive.truth[k]);
    if (smoothed) lagged.add(smoothed->x, drive.truth[k - lag]);
    ++k;
  }
  const auto allocations =
      static_cast<double>(sf_bench::heapAllocations() - before - untimedAllocations);
  state.counters["allocs_per_step"] =
      benchmark::Counter(allocations, benchmark::Counter::kAvgIterations);
  state.counters["rmse_filtered_m"] = filtered.rmse();
  if (lagged.periods > 0) state.counters["rmse_lagged_m"] = lagged.rmse();
}

}  // namespace

BENCHMARK(EKF_unicycle_fixed_lag)->Arg(0)->Arg(1)->Arg(3)->Arg(10)->Arg(30)->Arg(100);
