// Filter consistency check by the normalised innovation squared (NIS, Bar-Shalom et al.,
// "Estimation with Applications to Tracking and Navigation", section 5.4.2). For a filter
// whose model, Q and R are right, the NIS of period k,
//
//   eps_k = y_k^T S_k^-1 y_k,   y_k = z_k - z^_k,   S_k = H P(k|k-1) H^T + R
//
// over the m_k measured entries is chi-square distributed with m_k degrees of freedom. If the
// innovations of different periods were independent, the sum over a window of K periods would
// be chi-square with D = sum m_k degrees of freedom, and its mean (1/K) sum eps_k would lie in
//
//   [ chi2^-1(a/2; D) / K,  chi2^-1(1 - a/2; D) / K ]
//
// with probability 1 - a (two-sided; a = 0.05 by default). On a robot they are correlated in
// time (slip, bias, standstill), and that band is far too narrow for them: the check would
// flag a well-tuned filter most of the time. So the window's K periods count as n_eff
// independent ones (nis_correlation.hpp: n_eff = K (1 - rho) / (1 + rho), rho the lag-1
// autocorrelation of the NIS), and the band is that of a scaled chi-square with the same mean
// D/K and the inflated variance, i.e. with nu = D n_eff / K degrees of freedom:
//
//   [ (D/K) chi2^-1(a/2; nu) / nu,  (D/K) chi2^-1(1 - a/2; nu) / nu ]
//
// which is the band above when rho = 0. nu is rounded to 1/8 of a degree of freedom (at most
// 0.1 % on the bounds for nu >= 10, 0.8 % at the smallest, nu = 5) so that the bounds of every
// value can be cached (innovation_record.hpp). A mean above the upper bound says the
// innovations are larger than the filter believes (Q or R too small, or a wrong model); one
// below it says the filter is too pessimistic (Q or R too large).
//
// Significant is not the same as large. On a real robot the noise is not stationary
// (standstill, turns, a camera that sees the ball or not), and a window of a few seconds
// drifts outside the band although the filter's S is right on average, while a noise off by
// a few percent is "significant" over a long enough window. So a window counts as
// inconsistent only when its mean is outside the band AND more than a tolerance factor f
// away from its expected value D/K (below D/(K f) or above f D/K): f = 2 is a factor 1.4 on
// the standard deviations, less than what tuning on a recording can claim (doc/tuning.md).
// f = 1 is the chi-square test alone.
#pragma once

#include <cstddef>
#include <vector>

#include "sf_filter/core/nis_correlation.hpp"

namespace sf_filter {

/// What a NIS mean outside its bounds tells, and what to check (doc/filter_node.md, "What OK
/// and WARN mean"). Above: the innovations exceed S, which a sensor bias, a wrong model or a
/// too small Q or R gives; the replay's per-input NIS lines show which input. Below: S is
/// larger than the innovations, the variances are pessimistic (or an input is uninformative
/// by design), which does not make the track wrong: tuning Q and R for consistency alone can
/// make the track worse (issue 37), so the track is checked against a reference first.
inline const char* nisAdvice(bool above) {
  return above ? "innovations larger than S: Q or R too small, a sensor bias or a wrong model; "
                 "a replay's per-input NIS shows which input"
               : "innovations smaller than S: the variances are pessimistic, the track can "
                 "still be right; check it against a reference before tuning Q or R";
}

struct NisBounds {
  double lower = 0.0;
  double upper = 0.0;
};

/// Steps per degree of freedom of the grid the effective degrees of freedom are rounded to.
constexpr double kEffectiveDofSteps = 8.0;

/// nu = dof * effectivePeriods / periods, rounded to the grid (at least one step).
double effectiveDegreesOfFreedom(long dof, double periods, double effectivePeriods);

/// chi2^-1(alpha/2; nu) / nu and chi2^-1(1 - alpha/2; nu) / nu: the two-sided band at level
/// 1 - alpha of a mean NIS per degree of freedom worth nu independent degrees of freedom.
NisBounds chiSquareBandPerDof(double effectiveDof, double alpha = 0.05);

/// The bounds on the mean over `periods` periods of NIS values whose sum has `dof` degrees of
/// freedom, from the band per degree of freedom: (dof / periods) times it.
inline NisBounds meanBounds(const NisBounds& bandPerDof, long dof, double periods) {
  const double expected = static_cast<double>(dof) / periods;
  return {expected * bandPerDof.lower, expected * bandPerDof.upper};
}

/// Periods, in windows, over which the NIS's autocorrelation is estimated
/// (nis_correlation.hpp: over one window alone the estimate is too noisy).
constexpr double kAutocorrelationHorizonWindows = 10.0;

class NisWindow {
 public:
  /// `periods`: the window length K (periods with at least one measured entry); 0 disables.
  /// `autocorrelationHorizon`: the periods the autocorrelation is estimated over
  /// (LagOneAutocorrelation; 0: since the start or clear()); by default
  /// kAutocorrelationHorizonWindows windows. `tolerance`: the factor f >= 1 a mean outside
  /// the band must also be away from its expected value to count (above; 1: the band alone).
  explicit NisWindow(std::size_t periods = 0, double autocorrelationHorizon = -1.0,
                     double tolerance = 1.0)
      : nis_(periods, 0.0),
        dof_(periods, 0),
        tolerance_(tolerance),
        autocorrelation_(autocorrelationHorizon >= 0.0
                             ? autocorrelationHorizon
                             : kAutocorrelationHorizonWindows * static_cast<double>(periods)) {}

  std::size_t capacity() const { return nis_.size(); }
  bool enabled() const { return capacity() > 0; }

  /// The NIS of one period with `dof` > 0 measured entries.
  void add(double nis, int dof) {
    if (!enabled() || dof <= 0) return;
    if (size_ == capacity()) {
      sum_ -= nis_[next_];
      dofSum_ -= dof_[next_];
    } else {
      ++size_;
    }
    nis_[next_] = nis;
    dof_[next_] = dof;
    sum_ += nis;
    dofSum_ += dof;
    autocorrelation_.add(nis / dof);
    next_ = (next_ + 1) % capacity();
    // Recompute now and then so that the running sum does not accumulate rounding errors.
    if (next_ == 0) {
      sum_ = 0.0;
      for (double e : nis_) sum_ += e;
    }
  }

  std::size_t size() const { return size_; }
  bool full() const { return enabled() && size_ == capacity(); }
  /// D, the degrees of freedom of the window's sum.
  long degreesOfFreedom() const { return dofSum_; }
  /// (1/K) sum eps_k over the periods in the window (0 when empty).
  double mean() const { return size_ ? sum_ / static_cast<double>(size_) : 0.0; }

  /// rho: the lag-1 autocorrelation of the NIS per degree of freedom over the last
  /// kAutocorrelationHorizonWindows windows (exponentially weighted; restarts with clear()).
  double autocorrelation() const { return autocorrelation_.value(); }
  /// n_eff: the independent periods the window's mean is worth (nis_correlation.hpp).
  double effectivePeriods() const {
    return sf_filter::effectivePeriods(static_cast<double>(size_), autocorrelation());
  }
  /// nu = D n_eff / K on its grid: the degrees of freedom of the bounds. Requires size() > 0.
  double effectiveDegreesOfFreedom() const {
    return sf_filter::effectiveDegreesOfFreedom(dofSum_, static_cast<double>(size_),
                                                effectivePeriods());
  }

  /// The two-sided bounds on mean() at level 1 - alpha. Requires size() > 0.
  /// Compiled once in the fusion-core library (src/core/nis_window.cpp): Boost.Math's
  /// chi-square quantiles cost a second of every configuration's compile time.
  NisBounds bounds(double alpha = 0.05) const;

  /// D/K: the mean NIS of a consistent filter over the window. Requires size() > 0.
  double expectedMean() const { return static_cast<double>(dofSum_) / static_cast<double>(size_); }
  /// The tolerance factor f (above).
  double tolerance() const { return tolerance_; }

  /// Whether the window is full and its mean lies outside bounds(alpha) and more than the
  /// tolerance factor away from expectedMean().
  bool inconsistent(double alpha = 0.05) const {
    return full() && outside(mean(), bounds(alpha), expectedMean(), tolerance_);
  }

  /// Whether `mean` is outside `bounds` and outside [expected / tolerance, tolerance *
  /// expected]: the rule of inconsistent(), also for a whole run's mean.
  static bool outside(double mean, const NisBounds& bounds, double expected, double tolerance) {
    return (mean < bounds.lower && mean * tolerance < expected) ||
           (mean > bounds.upper && mean > tolerance * expected);
  }

  void clear() {
    size_ = next_ = 0;
    sum_ = 0.0;
    dofSum_ = 0;
    for (double& e : nis_) e = 0.0;
    autocorrelation_.clear();
  }

 private:
  std::vector<double> nis_;
  std::vector<int> dof_;
  std::size_t size_ = 0, next_ = 0;
  double sum_ = 0.0;
  long dofSum_ = 0;
  double tolerance_ = 1.0;
  LagOneAutocorrelation autocorrelation_;
};

}  // namespace sf_filter
