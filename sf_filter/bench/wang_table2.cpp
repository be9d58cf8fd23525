// sf_wang_table2: Monte Carlo reproduction of Wang et al.'s Table II ("Filling the Gap between
// Low Frequency Measurements with Their Estimates", section V) with the fusion core's own
// SAMPLED, HOLD and FILL alignment. doc/wang_table2.md describes the set-up and the results.
//
//   sf_wang_table2 [--runs N] [--seed N] [--duration S] [--omega S] [--history N] ...
//   (--help lists every option)
#include <chrono>
#include <exception>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "wang_table2/methods.hpp"
#include "wang_table2/options.hpp"
#include "wang_table2/simulation.hpp"
#include "wang_table2/table.hpp"

namespace {

using namespace wang_table2;

void printSetup(std::ostream& out, const Options& o) {
  const Parameters& s = o.parameters;
  out << "Wang et al. Table II, Monte Carlo: " << o.runs << " runs x " << s.duration
      << " s (errors from " << s.warmup << " s on, every 1 ms), seeds " << o.seed << ".."
      << o.seed + static_cast<std::uint64_t>(o.runs) - 1 << "\n"
      << "vision 32 Hz, encoders 1000 Hz, sigma_b " << s.biasStd << " m/s, T " << s.biasTimeConstant
      << " s, encoder noise " << s.encoderNoiseDensity << " m^2/s, d " << s.differenceSteps
      << ", speed std " << s.speedStd << " m/s\n"
      << "KF: SAMPLED, R " << s.kalmanR << "; hold: HOLD BEZIER " << s.holdSamples - 1 << ", R "
      << s.holdR << "; filling: FILL " << s.omega << ' ' << s.fillSamples << ", R " << s.fillR
      << "; Q diag(" << s.positionNoiseDensity << ", " << s.biasNoiseDensity << ") x 1 ms\n\n";
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parseOptions(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::invalid_argument& e) {
    std::cerr << "sf_wang_table2: " << e.what() << "\n\n" << usage();
    return 2;
  }
  if (options.help) {
    std::cout << usage();
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  MeasuredTable table;
  try {
    for (int r = 0; r < options.runs; ++r) {
      std::mt19937_64 rng(options.seed + static_cast<std::uint64_t>(r));
      const SimulatedRun run = simulateRun(options.parameters, rng);
      RunErrors errors;
      for (std::size_t m = 0; m < kRows; ++m) {
        for (std::size_t c = 0; c < kColumns; ++c) {
          errors[m][c] = runMethod(run, options.parameters, kMethods[m], kVisionStds[c]);
        }
      }
      table.addRun(errors);
    }
  } catch (const std::exception& e) {
    std::cerr << "sf_wang_table2: " << e.what() << '\n';
    return 1;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printSetup(std::cout, options);
  printTable(std::cout, table);
  std::cout << '\n'
            << options.runs << " runs in " << std::fixed << std::setprecision(1) << seconds
            << " s\n";
  return 0;
}
