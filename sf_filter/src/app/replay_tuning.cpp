// --tune after the replay (doc/tuning.md): the prediction-error identification over the
// recorded events, its report, the tuned replay's NIS and the tuned parameters' YAML file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "app/replay_command.hpp"
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

/// --out: the tuned parameters with the command and the costs as comments.
void writeTuned(const ReplayCommand& c, const TuningResult& r, AtomicOutput& out) {
  std::string command;
  for (std::size_t i = 0; i < c.arguments.size(); ++i) {
    command += (i ? " " : "") + c.arguments[i];
  }
  char costs[160];
  std::snprintf(costs, sizeof costs, "sum(log det S + NIS): start %.10g, tuned %.10g (%d replays)",
                r.startCost, r.cost, r.evaluations);
  out.write(tunedParametersYaml(
      {"Noise identified by the prediction-error method (doc/tuning.md):", command, costs,
       "Load it into the node (rosparam load, filter.launch params:=) or the replay (--params)."},
      r.tuned, c.freeEntries, c.periodMs / 1000.0, c.paramsPath));
  std::printf("%s: --tune: wrote %s\n", c.options.nodeName.c_str(), out.path().c_str());
}

}  // namespace

int tuneFromEvents(const ReplayCommand& c, const NodeDefinition& def, const EventLog& events,
                   const FusionCoreOptions& engineOptions, const FilterParameters& start,
                   AtomicOutput& out) {
  const std::string& name = c.options.nodeName;
  const EngineMaker makeEngine = [&](const FilterParameters& p) {
    return def.makeEngine(p, engineOptions);
  };
  const auto begin = std::chrono::steady_clock::now();
  const TuningResult r = tuneNoise(events, makeEngine, start, c.freeEntries, c.tuning);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  printTuneReport(name, r, events.size(), wall, start, c.freeEntries);
  const std::string refusal = identificationRefusal(r);
  if (!refusal.empty()) {
    throw ReplayError("--tune: " + refusal + (out.enabled() ? "; nothing written" : ""));
  }
  std::unique_ptr<FusionEngine> tuned = makeEngine(r.tuned);
  auto ignore = [](const EstimateRef&) {};
  events.replay(*tuned, ignore);
  printNis(name + " (tuned)", *tuned, def.description.inputs);
  if (out.enabled()) writeTuned(c, r, out);
  return EXIT_SUCCESS;
}

}  // namespace sf_filter::app
