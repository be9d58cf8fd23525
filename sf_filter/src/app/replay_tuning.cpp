// --tune after the replay (doc/tuning.md): the prediction-error identification over the
// recorded events, its report, the tuned replay's NIS and the tuned parameters' YAML file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/replay_command.hpp"
#include "sf_filter/core/nis_window.hpp"
#include "sf_filter/tuning/event_log.hpp"
#include "sf_filter/tuning/tuned_parameters_file.hpp"

namespace sf_filter::app {

namespace {

/// The diagonal entry of Q, R or P0 that `e` frees.
double entry(const FilterParameters& p, const FreeEntry& e) {
  const Eigen::MatrixXd& m = e.matrix == "Q"   ? p.process_noise_covariance
                             : e.matrix == "R" ? p.measurement_noise_covariance
                                               : p.initial_error_covariance;
  return m(e.index, e.index);
}

/// The identification's lines: its replays and cost, each free entry start and tuned.
void printTuneReport(const std::string& name, const TuningResult& r, std::size_t events,
                     double wall, const FilterParameters& start,
                     const std::vector<FreeEntry>& free) {
  std::printf(
      "%s: --tune: %d replays of %zu recorded events in %.3g s (%.3g ms each); stopped: "
      "%s\n",
      name.c_str(), r.evaluations, events, wall, 1e3 * wall / std::max(1, r.evaluations),
      r.stop.c_str());
  std::printf("%s: --tune: prediction-error cost sum(log det S + NIS): start %.10g, tuned %.10g\n",
              name.c_str(), r.startCost, r.cost);
  for (std::size_t k = 0; k < free.size(); ++k) {
    std::printf("%s: --tune: %-6s start %-12.6g tuned %-12.6g (x %.4g)%s\n", name.c_str(),
                free[k].name().c_str(), entry(start, free[k]), entry(r.tuned, free[k]),
                r.factors[k],
                r.atBound[k] ? "  at the bound of --tune-range: not identified by this bag" : "");
  }
}

/// One identification, timed, and its report.
TuningResult runTuning(const std::string& name, const EventLog& events,
                       const EngineMaker& makeEngine, const FilterParameters& start,
                       const std::vector<FreeEntry>& free, const TuningOptions& options) {
  const auto begin = std::chrono::steady_clock::now();
  TuningResult r = tuneNoise(events, makeEngine, start, free, options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  printTuneReport(name, r, events.size(), wall, start, free);
  return r;
}

/// Each entry's identification printed; the entries to write (all with `keepUnidentified`).
std::vector<FreeEntry> reportIdentification(const std::string& name,
                                            const std::vector<FreeEntry>& free,
                                            const std::vector<EntryIdentification>& ids,
                                            bool keepUnidentified) {
  std::vector<FreeEntry> kept;
  for (std::size_t k = 0; k < free.size(); ++k) {
    const EntryIdentification& id = ids[k];
    std::string why;
    if (!id.identified()) {
      char flat[48];
      std::snprintf(flat, sizeof flat, " (below %g: flat)", kIdentifiedRise);
      why = id.atBound ? " (at the bound of --tune-range)" : flat;
      if (keepUnidentified) why += "; written (--tune-keep-unidentified)";
    }
    std::printf("%s: --tune: %-6s %s: the cost rises by %.4g at x 1/%g and by %.4g at x %g%s\n",
                name.c_str(), free[k].name().c_str(),
                id.identified() ? "identified" : "not identified", id.riseDown,
                kIdentificationProbe, id.riseUp, kIdentificationProbe, why.c_str());
    if (id.identified() || keepUnidentified) {
      kept.push_back(free[k]);
    } else {
      std::printf(
          "%s: --tune: %-6s kept at its start value (--tune-keep-unidentified writes the "
          "tuned one)\n",
          name.c_str(), free[k].name().c_str());
    }
  }
  return kept;
}

/// The gain the guard requires on the held-out part: the held-out cost of the start values
/// minus the tuned ones' (summed over its periods: J is twice the negative log-likelihood, so
/// this is the likelihood-ratio statistic) must exceed the chi-square 95 % quantile with one
/// degree of freedom per tuned entry, what fitting that many entries gains by chance on the
/// data it was fitted on (Wilks). A smaller gain is not told from noise.
double holdoutThreshold(std::size_t entries) {
  const double k = static_cast<double>(entries);
  return k * chiSquareBandPerDof(k, 0.10).upper;  // one-sided 95 %: the two-sided 90 % band's top
}

/// The hold-out guard: the free entries tuned again on the first part of the recording, and
/// whether those values predict the held-out rest significantly better than `start` does
/// (holdoutThreshold; the filter run through the first part).
bool holdoutGuard(const ReplayCommand& c, const EventLog& events, const EngineMaker& makeEngine,
                  const FilterParameters& start, const std::vector<FreeEntry>& free) {
  const std::string& name = c.options.nodeName;
  const std::size_t split = events.splitIndex(1.0 - c.tuning.holdout);
  const TuningResult first = tuneNoise(events.head(split), makeEngine, start, free, c.tuning);
  const HeldOutCost before = heldOutCost(events, split, makeEngine, start);
  const HeldOutCost after = heldOutCost(events, split, makeEngine, first.tuned);
  const double percent = 100.0 * c.tuning.holdout;
  if (before.periods == 0) {
    std::printf(
        "%s: --tune: hold-out: the last %.3g %% of the recording has no innovation: the "
        "guard cannot judge; the start values are kept (--tune-holdout 0: no guard)\n",
        name.c_str(), percent);
    return false;
  }
  const double gain = (before.mean - after.mean) * static_cast<double>(before.periods);
  const double threshold = holdoutThreshold(free.size());
  const bool better = gain > threshold;  // false for NaN, and for a failed tuned step (+inf)
  std::printf(
      "%s: --tune: hold-out: tuned on the first %.3g %% of the recording (%d replays), "
      "on the last %.3g %% (%llu periods) mean log det S + NIS per period: start %.6g, "
      "tuned %.6g; gain %.4g against %.4g (chi-square 95 %%, %zu entries): %s\n",
      name.c_str(), 100.0 - percent, first.evaluations, percent,
      static_cast<unsigned long long>(before.periods), before.mean, after.mean, gain, threshold,
      free.size(),
      better ? "better"
             : "not better: the tuning does not predict unseen data significantly better; "
               "the start values are kept");
  return better;
}

/// --out: the written parameters with the command and the costs as comments.
void writeTuned(const ReplayCommand& c, const TuningResult& r, const FilterParameters& written,
                bool guarded, AtomicOutput& out) {
  std::string command;
  for (std::size_t i = 0; i < c.arguments.size(); ++i) {
    command += (i ? " " : "") + c.arguments[i];
  }
  char costs[160];
  std::snprintf(costs, sizeof costs, "sum(log det S + NIS): start %.10g, tuned %.10g (%d replays)",
                r.startCost, r.cost, r.evaluations);
  out.write(tunedParametersYaml(
      {guarded ? "Noise identified by the prediction-error method (doc/tuning.md):"
               : "The start values: the hold-out guard kept them (doc/tuning.md):",
       command, costs,
       "Load it into the node (rosparam load, filter.launch params:=) or the replay (--params)."},
      written, c.freeEntries, c.periodMs / 1000.0, c.paramsPath));
  std::printf("%s: --tune: wrote %s%s\n", c.options.nodeName.c_str(), out.path().c_str(),
              guarded ? "" : " with the start values");
}

}  // namespace

int tuneFromEvents(const ReplayCommand& c, const NodeDefinition& def, const EventLog& events,
                   const FusionCoreOptions& engineOptions, const FilterParameters& start,
                   AtomicOutput& out) {
  const std::string& name = c.options.nodeName;
  const EngineMaker makeEngine = [&](const FilterParameters& p) {
    return def.makeEngine(p, engineOptions);
  };
  TuningResult r = runTuning(name, events, makeEngine, start, c.freeEntries, c.tuning);
  const std::string refusal = identificationRefusal(r);
  if (!refusal.empty()) {
    throw ReplayError("--tune: " + refusal + (out.enabled() ? "; nothing written" : ""));
  }
  const std::vector<FreeEntry> kept = reportIdentification(
      name, c.freeEntries, identifyEntries(events, makeEngine, start, c.freeEntries, r),
      c.tuning.keepUnidentified);
  if (kept.empty()) {
    throw ReplayError(
        "--tune: the recording identifies none of the free entries (each at a bound "
        "or with a flat cost)" +
        std::string(out.enabled() ? "; nothing written" : ""));
  }
  if (kept.size() < c.freeEntries.size()) {
    std::printf("%s: --tune: again with the identified entries only\n", name.c_str());
    r = runTuning(name, events, makeEngine, start, kept, c.tuning);
  }
  const bool better = c.tuning.holdout <= 0.0 || holdoutGuard(c, events, makeEngine, start, kept);
  if (better) {
    std::unique_ptr<FusionEngine> tuned = makeEngine(r.tuned);
    auto ignore = [](const EstimateRef&) {};
    events.replay(*tuned, ignore);
    printNis(name + " (tuned)", *tuned, def.description.inputs);
  }
  if (out.enabled()) writeTuned(c, r, better ? r.tuned : start, better, out);
  return EXIT_SUCCESS;
}

}  // namespace sf_filter::app
