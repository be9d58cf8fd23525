// Command line of sf_wang_table2. Every option takes one value; a bad one is an error that
// names the option and says what it expects.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <sf_filter/core/alignment/alignment_policy.hpp>

#include "methods.hpp"
#include "parameters.hpp"

namespace wang_table2 {

struct Options {
  int runs = 100;
  std::uint64_t seed = 1;
  Parameters parameters;
  bool help = false;
};

inline const char* usage() {
  return "usage: sf_wang_table2 [options]\n"
         "Monte Carlo reproduction of Wang et al.'s Table II (doc/wang_table2.md).\n"
         "  --runs N            Monte Carlo runs, at least 2 (default 100)\n"
         "  --seed N            seed of the first run; run r uses seed + r (default 1)\n"
         "  --duration S        simulated seconds per run (default 30)\n"
         "  --warmup S          seconds at the start of a run left out of the figures "
         "(default 2)\n"
         "  --omega S           the filling's omega (default 0.001)\n"
         "  --history N         stored vision samples N of the filling and N_m of the hold "
         "(default 5)\n"
         "  --encoder-noise Q   density of the encoder rate's white noise [m^2/s] "
         "(default 0.017)\n"
         "  --speed S           std of the robot's speed [m/s] (default 1)\n"
         "  --difference D      backward difference distance d of the encoder rate "
         "(default 5)\n"
         "  --fill-r R          the filling's measurement variance R (default 0.1)\n"
         "  --help              this text\n";
}

namespace options_detail {

inline double number(const std::string& option, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(value)) {
    throw std::invalid_argument(option + " expects a number, got '" + text + "'");
  }
  return value;
}

inline long long integer(const std::string& option, const std::string& text) {
  const double value = number(option, text);
  if (value != std::floor(value) || std::abs(value) > 1e15) {
    throw std::invalid_argument(option + " expects a whole number, got '" + text + "'");
  }
  return static_cast<long long>(value);
}

}  // namespace options_detail

/// The options that take a value (usage() describes them).
constexpr const char* kOptionNames[] = {"--runs",       "--seed",    "--duration",      "--warmup",
                                        "--omega",      "--history", "--encoder-noise", "--speed",
                                        "--difference", "--fill-r"};

/// Parses the arguments after the program name. Throws std::invalid_argument naming the
/// offending option.
inline Options parseOptions(const std::vector<std::string>& args) {
  using options_detail::integer;
  using options_detail::number;
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& option = args[i];
    if (option == "--help" || option == "-h") {
      o.help = true;
      continue;
    }
    if (option.rfind("--", 0) != 0) {
      throw std::invalid_argument("unexpected argument '" + option + "'");
    }
    if (std::find(std::begin(kOptionNames), std::end(kOptionNames), option) ==
        std::end(kOptionNames)) {
      throw std::invalid_argument("unknown option '" + option + "'");
    }
    const std::string& value = i + 1 < args.size() ? args[++i] : std::string();
    if (value.empty()) throw std::invalid_argument(option + " needs a value");
    if (option == "--runs") {
      const long long runs = integer(option, value);
      if (runs < 2 || runs > 1000000) {
        throw std::invalid_argument("--runs must be between 2 and 1000000, got " + value);
      }
      o.runs = static_cast<int>(runs);
    } else if (option == "--seed") {
      const long long seed = integer(option, value);
      if (seed < 0) throw std::invalid_argument("--seed must not be negative, got " + value);
      o.seed = static_cast<std::uint64_t>(seed);
    } else if (option == "--duration") {
      o.parameters.duration = number(option, value);
    } else if (option == "--warmup") {
      o.parameters.warmup = number(option, value);
    } else if (option == "--omega") {
      o.parameters.omega = number(option, value);
    } else if (option == "--history") {
      const long long n = integer(option, value);
      if (n < 1 || n > sf_filter::SampleHistory::kCapacity) {
        throw std::invalid_argument("--history must be between 1 and " +
                                    std::to_string(sf_filter::SampleHistory::kCapacity) + ", got " +
                                    value);
      }
      o.parameters.holdSamples = o.parameters.fillSamples = static_cast<int>(n);
    } else if (option == "--encoder-noise") {
      o.parameters.encoderNoiseDensity = number(option, value);
    } else if (option == "--speed") {
      o.parameters.speedStd = number(option, value);
    } else if (option == "--difference") {
      const long long d = integer(option, value);
      if (d < 1 || d > 1000) {
        throw std::invalid_argument("--difference must be between 1 and 1000, got " + value);
      }
      o.parameters.differenceSteps = static_cast<int>(d);
    } else if (option == "--fill-r") {
      o.parameters.fillR = number(option, value);
      if (!(o.parameters.fillR > 0.0)) {
        throw std::invalid_argument("--fill-r must be positive, got " + value);
      }
    }
  }
  std::string problem = parametersProblem(o.parameters);
  if (problem.empty()) {
    for (Method m : kMethods) {
      problem = sf_filter::alignmentPolicyProblem(policyOf(m, o.parameters));
      if (!problem.empty()) break;
    }
  }
  if (!problem.empty()) throw std::invalid_argument(problem);
  return o;
}

}  // namespace wang_table2
