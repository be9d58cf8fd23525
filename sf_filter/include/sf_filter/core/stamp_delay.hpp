// Each input's stamp-to-arrival delay (the clock reading at which the core is given a value
// minus the value's header stamp: online the ROS time roscpp received the message, in the
// replay the bag's record time) as a running distribution, so that a value dropped as later
// than the maximum measurement lag can be explained with figures and the lag that would keep
// it (doc/filter_node.md, "Late values").
//
// The estimator is a fixed-memory log-spaced histogram: 16 bins per octave from 2^-12 s
// (0.24 ms) to 2^8 s (256 s), 320 counters of 32 bits (1.3 kB per input), whatever the length
// of the run. A quantile is the geometric middle of the bin it falls in: within 2.2 % of the
// true value (the bin's half-width in log terms), exact in rank. Unlike a streaming quantile
// estimator (P-square) it answers any quantile from the same counts, which the advice needs
// (the lag that keeps 99 %), and it is deterministic: the online node and the replay, given the
// same delays, report the same figures. Delays below 0.25 ms (also negative ones: a sensor
// clock ahead of the ROS clock) count in the lowest bin, reported as 0; longer than 256 s in
// the highest. A counter about to overflow halves every counter (the quantiles keep their
// ranks).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

namespace sf_filter {

class StampDelays {
 public:
  static constexpr int kBinsPerOctave = 16;
  static constexpr int kLowestOctave = -12;  ///< 2^-12 s = 0.24 ms
  static constexpr int kHighestOctave = 8;   ///< 2^8 s = 256 s
  static constexpr int kBins = (kHighestOctave - kLowestOctave) * kBinsPerOctave;

  /// Counts one delay [s]; a NaN (no stamp) is not counted.
  void add(double delay) {
    if (std::isnan(delay)) return;
    std::uint32_t& bin = bins_[static_cast<std::size_t>(binOf(delay))];
    if (bin == std::numeric_limits<std::uint32_t>::max()) halve();
    ++bin;
    ++count_;
  }

  /// Delays counted (since the last halving, which halves this too).
  std::uint64_t count() const { return count_; }

  /// The q-quantile (0 < q <= 1) [s]: the middle of its bin, 0 in the lowest; NaN when none.
  double quantile(double q) const {
    const int b = binOfQuantile(q);
    if (b < 0) return std::numeric_limits<double>::quiet_NaN();
    if (b == 0) return 0.0;
    return std::sqrt(lowerEdge(b) * lowerEdge(b + 1));
  }

  /// A delay [s] at least as long as the fraction q of the delays counted (the upper edge of
  /// the q-quantile's bin): a lag this long keeps that fraction. NaN when none.
  double bound(double q) const {
    const int b = binOfQuantile(q);
    return b < 0 ? std::numeric_limits<double>::quiet_NaN() : lowerEdge(b + 1);
  }

 private:
  static int binOf(double delay) {
    if (!(delay > lowerEdge(1))) return 0;
    const int b = static_cast<int>(std::floor((std::log2(delay) - kLowestOctave) * kBinsPerOctave));
    return b >= kBins ? kBins - 1 : b;
  }
  /// The lower edge of bin b (b = kBins: the upper edge of the highest).
  static double lowerEdge(int b) {
    return std::exp2(kLowestOctave + static_cast<double>(b) / kBinsPerOctave);
  }
  int binOfQuantile(double q) const {
    if (count_ == 0) return -1;
    // The smallest bin whose cumulative count reaches ceil(q * count).
    const double rank = std::ceil(q * static_cast<double>(count_));
    std::uint64_t seen = 0;
    for (int b = 0; b < kBins; ++b) {
      seen += bins_[static_cast<std::size_t>(b)];
      if (static_cast<double>(seen) >= rank) return b;
    }
    return kBins - 1;
  }
  void halve() {
    count_ = 0;
    for (std::uint32_t& bin : bins_) {
      bin /= 2;
      count_ += bin;
    }
  }

  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t count_ = 0;
};

/// "median 25 ms, p95 34 ms" of `d` ("no stamped values" when it counted none).
inline std::string delayFigures(const StampDelays& d) {
  if (d.count() == 0) return "no stamped values";
  char text[96];
  std::snprintf(text, sizeof text, "median %.1f ms, p95 %.1f ms", 1e3 * d.quantile(0.5),
                1e3 * d.quantile(0.95));
  return text;
}

/// The ~max_measurement_lag [s] that keeps 99 % of the delays `d` counted, rounded up to a
/// whole millisecond (NaN when none).
inline double lagKeeping99(const StampDelays& d) {
  return std::ceil(1e3 * d.bound(0.99) - 1e-9) / 1e3;
}

}  // namespace sf_filter
