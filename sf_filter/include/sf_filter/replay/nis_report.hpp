// The replay's NIS lines (doc/evaluation.md): per input and for all inputs together, the mean
// NIS of the run with its chi-square verdict (the run's periods counted as the independent
// periods they are worth by their lag-1 autocorrelation, nis_correlation.hpp), and how often the
// node's diagnostics, judging a sliding window of ~nis_window periods, would have reported the
// filter inconsistent. They follow the summary and per-input counter lines, whose format tools
// parse, and name no "estimates" so that a parser looking for the summary line does not take them
// for it.
#pragma once

#include <cstdio>
#include <ostream>
#include <string>

#include "sf_filter/core/innovation_record.hpp"

namespace sf_filter {

/// "consistent", or which side of the bounds the mean lies on and what that suggests; a mean
/// outside the bounds but within the tolerance factor of its expected value (nis_window.hpp)
/// is "consistent within the tolerance", which the node's diagnostics report as OK.
inline std::string nisVerdict(const NisSeries& series) {
  const NisBounds b = series.bounds();
  const double mean = series.mean();
  if (series.inconsistent()) {
    return std::string(mean > b.upper ? "inconsistent, above (" : "inconsistent, below (") +
           nisAdvice(mean > b.upper) + ")";
  }
  if (mean < b.lower || mean > b.upper) {
    char text[96];
    std::snprintf(text, sizeof text, "consistent within the tolerance factor %.3g (%s the bounds)",
                  series.window().tolerance(), mean > b.upper ? "above" : "below");
    return text;
  }
  return "consistent";
}

/// One line about `series`: `label` e.g. "all inputs" or "input 0 (odom twist.twist.linear.x)".
inline void printNisLine(std::ostream& out, const std::string& node, const std::string& label,
                         const NisSeries& series) {
  out << node << ": NIS " << label << ": ";
  if (series.periods() == 0) {
    out << "none (no measured period, or no prediction: averaging method or ~nis_window 0)\n";
    return;
  }
  const NisBounds b = series.bounds();
  const double expected =
      static_cast<double>(series.degreesOfFreedom()) / static_cast<double>(series.periods());
  char text[512];
  std::snprintf(text, sizeof text,
                "mean %.4g over %llu periods (expected %.4g; lag-1 autocorrelation %.3f, worth "
                "%.4g independent periods), 95 %% bounds [%.4g, %.4g]: %s; "
                "window of %zu periods inconsistent in %llu of %llu judged periods",
                series.mean(), static_cast<unsigned long long>(series.periods()), expected,
                series.autocorrelation(), series.effectivePeriods(), b.lower, b.upper,
                nisVerdict(series).c_str(), series.window().capacity(),
                static_cast<unsigned long long>(series.inconsistentPeriods()),
                static_cast<unsigned long long>(series.judgedPeriods()));
  out << text << "\n";
}

}  // namespace sf_filter
