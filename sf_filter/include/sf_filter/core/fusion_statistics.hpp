// What the fusion core counted, at one moment, in one plain struct: read by the node's
// diagnostics and log lines, the replay's summary and --strict, and the node's shutdown line,
// instead of a virtual accessor per counter (FusionEngine::statistics()).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <sf_estimation/numerical_repairs.hpp>

#include "sf_filter/core/estimation_totals.hpp"
#include "sf_filter/core/input_counters.hpp"

namespace sf_filter {

/// The sums over every input's counters that the summaries print.
struct InputTotals {
  std::uint64_t received = 0;
  std::uint64_t used = 0;
  std::uint64_t dropped = 0;  ///< InputCounters::dropped(): refused on arrival
  std::uint64_t late = 0;
  std::uint64_t gated = 0;
  std::uint64_t substituted = 0;
};

struct FusionStatistics : EstimationTotals {
  std::vector<InputCounters> inputs;  ///< per input, in the configuration's order
  InputTotals totals;                 ///< of `inputs` (sumInputs())
  /// Forward gaps crossed with one estimate, and the periods they skipped without estimating.
  std::uint64_t skippedGaps = 0;
  std::uint64_t skippedPeriods = 0;
  double maxStepSeconds = 0.0;
  std::string lastFailure;
  double clock = 0.0;      ///< the last clock reading
  double startTime = 0.0;  ///< the clock reading the schedule (re)started at

  /// `totals` from `inputs`.
  void sumInputs() {
    totals = InputTotals();
    for (const InputCounters& c : inputs) {
      totals.received += c.received;
      totals.used += c.used;
      totals.dropped += c.dropped();
      totals.late += c.late;
      totals.gated += c.gated;
      totals.substituted += c.substituted;
    }
  }
};

}  // namespace sf_filter
