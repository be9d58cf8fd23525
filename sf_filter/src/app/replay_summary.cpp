// What the replay prints after the run: the totals line, each input's counters and NIS, the
// GPS inputs' and the alignment's losses; and --strict's exit status.
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "app/replay_command.hpp"
#include "sf_filter/core/health.hpp"
#include "sf_filter/replay/nis_report.hpp"
#include "sf_filter/replay/replay_frame_aligner.hpp"

namespace sf_filter::app {

namespace {

/// Values dropped before the core: not rotatable, GPS fixes not on the Earth.
std::uint64_t droppedBeforeCore(const NodeDefinition& def, const ReplayOutcome& o) {
  std::uint64_t n = o.aligner ? o.aligner->droppedTotal() : 0;
  for (std::size_t i = 0; i < def.description.inputs.size(); ++i) {
    n += o.inputs.gps().implausibleFixes(i);
  }
  return n;
}

/// The summary's first line: the run's totals.
void printTotals(const std::string& name, const ReplayOutcome& o) {
  const ReplaySummary& s = o.summary;
  const FusionStatistics& f = o.statistics;
  std::cout << name << ": " << s.messages << " messages, " << s.estimates << " estimates, "
            << f.estimationFailures << " failed steps, " << f.filterResets << " filter resets, "
            << f.skippedGaps << " gaps skipped, " << s.dropped << " dropped values ("
            << f.totals.late << " late), " << f.totals.gated << " gated, " << f.totals.substituted
            << " substitutes, "
            << (s.estimates ? 1e6 * f.estimatorSeconds / static_cast<double>(s.estimates) : 0.0)
            << " us per estimation step, " << o.wallSeconds << " s in all" << std::endl;
}

/// The replay summary's line per input: what it received, used, dropped (by reason), gated,
/// the stamp-to-arrival delays; and for an input with late values, why and the lag to set.
void printInputCounters(const std::string& name, const ReplayOutcome& o,
                        const std::vector<std::string>& inputs) {
  const std::vector<InputCounters>& counters = o.statistics.inputs;
  for (std::size_t i = 0; i < counters.size(); ++i) {
    const InputCounters& c = counters[i];
    std::cout << name << ": input " << i << ": " << c.received << " received, " << c.used
              << " used, dropped: " << dropReasons(c) << ", " << c.gated << " gated, "
              << c.timedOutPeriods << " periods timed out, stamp-to-arrival delay "
              << delayFigures(c.delays) << std::endl;
  }
  for (std::size_t i = 0; i < counters.size(); ++i) {
    if (counters[i].late == 0) continue;
    std::cout << name << ": "
              << lateAdvice(i, inputs.at(i), counters[i], o.core.maxMeasurementLag(),
                            "--max-lag (~max_measurement_lag)")
              << std::endl;
  }
}

/// The GPS inputs' fixes without a valid status and unknown covariances (for the inputs that
/// received a fix).
void printGpsCounters(const std::string& name, const InputState& state,
                      const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!state.gps().receivedFix(i)) continue;
    const auto input = static_cast<Index>(i);
    std::cout << name << ": input " << i << " (GPS): " << state.gps().noFix(i)
              << " fixes dropped without a fix (status < STATUS_FIX), "
              << state.gps().implausibleFixes(i) << " dropped as not on the Earth"
              << (state.gps().implausibleFixes(i)
                      ? " (newest: " + state.gps().implausibleReason(i) + ")"
                      : std::string())
              << ", " << state.covarianceFallbacks(input)
              << " with an unknown covariance (header R used)" << std::endl;
  }
}

/// The transforms read and the values not rotatable into the base frame.
void printAlignment(const ReplayCommand& c, const ReplayFrameAligner& aligner) {
  std::cout << c.options.nodeName << ": " << aligner.transforms()
            << " transforms read from the bag's /tf_static and /tf ("
            << aligner.rejectedTransforms() << " refused by tf2), " << aligner.droppedTotal()
            << " values dropped: not rotatable into '" << aligner.baseFrame() << "'" << std::endl;
  if (aligner.repeatedTransforms() > 0) {  // one line, not tf2's one per transform
    std::cerr << c.program << ": tf2: TF_REPEATED_DATA: " << aligner.repeatedTransforms()
              << " transforms ignored, each with the stamp of one its frame already had "
                 "(overlapping bags, or a transform recorded twice); the first is kept"
              << std::endl;
  }
}

/// --smooth, --smooth-lag: the smoother's size and cost, and what stands for its NIS: how far
/// it moved the filtered means, in the filtered standard deviations (SmoothingCorrection), as
/// the RMS over the smoothed periods beside its expectation for a consistent smoother, and
/// the newest period's.
void printSmoothing(const ReplayCommand& c, const ReplayOutcome& o) {
  const std::string& name = c.options.nodeName;
  const ReplaySummary& s = o.summary;
  if (c.options.smooth) {
    std::cout << name << ": smoothed " << s.smoothedPeriods << " periods (" << s.smoothedSegments
              << " segments) in " << s.smoothingSeconds << " s, " << s.smoothingBytesPerPeriod
              << " bytes per period" << std::endl;
  } else if (c.options.smoothLag > 0.0) {
    std::cout << name << ": fixed-lag smoother, lag " << s.lagPeriods << " periods ("
              << static_cast<double>(s.lagPeriods) * o.core.period() << " s; "
              << c.options.smoothLag << " s asked), " << s.lagPeriodsHeld << " periods held, "
              << s.lagBytes << " bytes held" << std::endl;
  } else {
    return;
  }
  std::cout << name << ": smoothing correction over " << s.corrections.periods << " periods: RMS "
            << s.corrections.rms() << " filtered standard deviations (expected "
            << s.corrections.expectedRms() << "), last period "
            << std::sqrt(s.lastCorrection.meanSquare) << " (expected "
            << std::sqrt(s.lastCorrection.expected) << ")" << std::endl;
  if (s.batch) {
    std::cout << name << ": batch MAP track: " << s.batch->iterations << " iterations, cost "
              << s.batch->cost << " (filtered track " << s.batch->initialCost << "), "
              << (s.batch->converged ? "converged" : "NOT converged") << ", " << s.batch->halvings
              << " step halvings" << std::endl;
  }
}

}  // namespace

void printNis(const std::string& name, const FusionEngine& core,
              const std::vector<std::string>& inputs) {
  const InnovationRecord& r = core.innovations();
  printNisLine(std::cout, name, "all inputs", r.overall());
  for (Index i = 0; i < core.inputCount(); ++i) {
    printNisLine(std::cout, name,
                 "input " + std::to_string(i) + " (" + inputs.at(static_cast<std::size_t>(i)) + ")",
                 r.input(static_cast<std::size_t>(i)));
  }
  std::cout << std::flush;
}

void printReplaySummary(const ReplayCommand& c, const NodeDefinition& def, const ReplayOutcome& o) {
  const std::string& name = c.options.nodeName;
  const ReplaySummary& s = o.summary;
  printTotals(name, o);
  printSmoothing(c, o);
  printInputCounters(name, o, def.description.inputs);
  printNis(name, o.core, def.description.inputs);
  printGpsCounters(name, o.inputs, def.description.inputs);
  if (o.aligner) printAlignment(c, *o.aligner);
}

int strictStatus(const ReplayCommand& c, const NodeDefinition& def, const ReplayOutcome& o) {
  const std::uint64_t failures = o.statistics.estimationFailures;
  const std::uint64_t resets = o.statistics.filterResets;
  const std::uint64_t dropped = o.summary.dropped + droppedBeforeCore(def, o);
  if (c.strict && (failures > 0 || resets > 0 || dropped > 0)) {
    std::cerr << c.program << ": --strict: " << failures << " failed steps, " << resets
              << " filter resets, " << dropped << " dropped values" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

}  // namespace sf_filter::app
