// What the innovations of a run say about the filter's tuning: the NIS of the whole estimate
// and of each input alone, each judged period by period by the same sliding window and
// chi-square bounds as the node's diagnostics (nis_window.hpp), with totals over the run (whose
// bounds count the run's periods as independent ones by the run's own lag-1 autocorrelation,
// as the window does; nis_correlation.hpp); and
// the prediction-error cost sum_k (log det S_k + y_k^T S_k^-1 y_k), twice the innovations'
// negative log-likelihood up to a constant, which the noise identification minimises
// (tuning/noise_tuning.hpp). The offline replay prints it in its summary; the node keeps it
// too, the window of the overall series being its diagnostics' NIS window.
//
// An input's own NIS is its innovation squared over its own innovation variance,
// y_i^2 / S_ii (the marginal of the joint chi-square: 1 degree of freedom per period it was
// measured), so a mistuned R or a biased sensor shows on the input it belongs to.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sf_filter/core/nis_window.hpp"

namespace sf_filter {

/// One NIS series: the sliding window of the diagnostics, how often it was judged and found
/// inconsistent, and the totals of the run.
class NisSeries {
 public:
  /// `window`: periods of the sliding window (0: off); `maxDofPerPeriod`: the most measured
  /// entries a period can have (the inputs it covers); `tolerance`: the factor f of
  /// NisWindow (1: the chi-square band alone).
  explicit NisSeries(std::size_t window = 0, int maxDofPerPeriod = 1, double tolerance = 1.0);

  bool enabled() const { return window_.enabled(); }
  /// The NIS of one period with `dof` > 0 measured entries; once the window is full, the
  /// period is judged as the diagnostics judge it.
  void add(double nis, int dof);

  const NisWindow& window() const { return window_; }
  /// Periods added over the run, their degrees of freedom, and the mean NIS per period.
  std::uint64_t periods() const { return periods_; }
  long degreesOfFreedom() const { return dof_; }
  double mean() const { return periods_ ? sum_ / static_cast<double>(periods_) : 0.0; }
  /// The lag-1 autocorrelation of the NIS per degree of freedom over the whole run, and the
  /// independent periods the run's mean is worth by it (nis_correlation.hpp).
  double autocorrelation() const { return autocorrelation_.value(); }
  double effectivePeriods() const {
    return sf_filter::effectivePeriods(static_cast<double>(periods_), autocorrelation());
  }
  /// Two-sided bounds on mean() at level 1 - alpha, for the whole run (a window of all its
  /// periods, worth effectivePeriods()). Requires periods() > 0.
  NisBounds bounds(double alpha = 0.05) const;
  /// The run's mean judged as a window is (NisWindow::inconsistent, with the window's
  /// tolerance). Requires periods() > 0.
  bool inconsistent(double alpha = 0.05) const {
    return NisWindow::outside(mean(), bounds(alpha),
                              static_cast<double>(dof_) / static_cast<double>(periods_),
                              window_.tolerance());
  }
  /// Periods with a full window, and those of them whose window mean lay outside its bounds
  /// (the diagnostics' "filter inconsistent" WARN).
  std::uint64_t judgedPeriods() const { return judged_; }
  std::uint64_t inconsistentPeriods() const { return inconsistent_; }

  /// Restarts the window (after a filter reset); the run's totals stay.
  void restartWindow() { window_.clear(); }

 private:
  NisWindow window_;
  LagOneAutocorrelation autocorrelation_;  ///< over the run (restartWindow() keeps it)
  double sum_ = 0.0;
  long dof_ = 0;
  std::uint64_t periods_ = 0, judged_ = 0, inconsistent_ = 0;
  /// The full window's bounds, computed once per value of its effective degrees of freedom
  /// (on their grid of 1/kEffectiveDofSteps) and of D. Boost's chi-square quantiles cost tens
  /// of microseconds, and nu changes with the autocorrelation and whenever an input is
  /// missing in a period (a sensor slower than the period): every possible nu has its slot,
  /// allocated here at construction so that the node's periods stay free of allocations
  /// (above kMaxCachedBounds slots only the last value is kept). A full window's bounds are
  /// (D/K) times the band per degree of freedom of nu (chiSquareBandPerDof), which the slot keeps.
  NisBounds windowBounds();
  static constexpr std::size_t kMaxCachedBounds = 1 << 16;
  /// index nu * kEffectiveDofSteps: the band per degree of freedom; lower < 0: not computed yet
  std::vector<NisBounds> boundsByGridStep_;
  long lastGridStep_ = -1;
  NisBounds lastBounds_;
};

class InnovationRecord {
 public:
  /// `window`: the periods of the sliding window (0: nothing is recorded); `tolerance`:
  /// NisWindow's factor f.
  InnovationRecord(std::size_t window, std::size_t inputs, double tolerance = 1.0)
      : overall_(window, static_cast<int>(inputs), tolerance),
        inputs_(inputs, NisSeries(window, 1, tolerance)) {}

  bool enabled() const { return overall_.enabled(); }
  /// The period's innovation over its measured entries: NIS, its degrees of freedom, log det S.
  void addPeriod(double nis, int dof, double logDetS) {
    if (!enabled() || dof <= 0) return;
    overall_.add(nis, dof);
    cost_ += logDetS + nis;
  }
  /// Input `input`'s own NIS y_i^2 / S_ii in a period it was measured.
  void addInput(std::size_t input, double nis) { inputs_[input].add(nis, 1); }

  const NisSeries& overall() const { return overall_; }
  const NisSeries& input(std::size_t input) const { return inputs_[input]; }
  /// sum_k (log det S_k + y_k^T S_k^-1 y_k) over the periods recorded.
  double predictionErrorCost() const { return cost_; }

  void restartWindows() {
    overall_.restartWindow();
    for (NisSeries& s : inputs_) s.restartWindow();
  }

 private:
  NisSeries overall_;
  std::vector<NisSeries> inputs_;
  double cost_ = 0.0;
};

}  // namespace sf_filter
