// How many independent periods a run of time-correlated NIS values is worth.
//
// The chi-square bounds of nis_window.hpp hold when the innovations of different periods are
// independent. On a robot they are not: wheel slip, a drifting gyro bias, a wheel that is
// exact at standstill and noisy in motion make the NIS of neighbouring periods alike, and the
// mean of K such values varies far more than chi-square(D)/K says (a window of 100 periods of
// the shipped diff-drive bag, tuned by --tune, left those bounds in 44 % of its periods).
//
// Model: the NIS per degree of freedom, u_k = eps_k / m_k, is a stationary AR(1) sequence with
// lag-1 autocorrelation rho. The variance of the mean of n of its values is then that of n
// independent ones times the variance-inflation factor (1 + rho) / (1 - rho) (large n), i.e.
// the mean is worth
//
//   n_eff = n (1 - rho) / (1 + rho)
//
// independent periods (e.g. Box, Jenkins and Reinsel, "Time Series Analysis", 2.1.5; Bayley
// and Hammersley's effective sample size). The bounds keep the two-sided chi-square band of
// the same confidence, with the degrees of freedom scaled by n_eff / n (a scaled chi-square
// matched in mean and variance, Satterthwaite's approximation): nis_window.hpp.
//
// Why AR(1) with rho estimated this way (doc/tuning.md#the-nis-check-and-correlated-innovations
// has the flag rates on simulated NIS, from sf_filter/test/test_nis_window.cpp):
// - The AR(1) factor needs one number, estimated from all neighbouring pairs and updated in
//   O(1); batch means over one window (10 batches of 10) estimate the variance from 9
//   degrees of freedom, far noisier.
// - rho is the lag-1 autocorrelation of u, exponentially weighted over a horizon of ten
//   windows, not of the judged window alone: from 100 values its standard deviation is about
//   0.1 and it depends on the window's own values (a quiet stretch of a squared process has
//   both a low mean and a low autocorrelation, so exactly the low windows would get a narrow
//   band); over ten windows the band is steadier and nearly independent of the window it
//   judges. Both flag consistent correlated NIS at 2.5 to 5 % (nominal 5 %).
// - rho is clamped to [0, 1): NIS values of jointly Gaussian innovations cannot be negatively
//   correlated (cov(y_j' A y_j, y_k' B y_k) = 2 tr(A C B C') >= 0 for C = cov(y_j, y_k)), so a
//   negative estimate is sampling noise and counts as 0; n_eff is never more than n.
// - n_eff is at least kMinEffectivePeriods (or n, if smaller): past that the window is too
//   short for the correlation of its innovations, and a band from fewer independent values
//   would pass every filter. A window that needs more should be longer (~nis_window).
// Every update is O(1) and allocation-free: a few running sums.
#pragma once

#include <algorithm>
#include <cmath>

namespace sf_filter {

/// The fewest independent periods a window's mean is taken to be worth.
constexpr double kMinEffectivePeriods = 5.0;

/// n (1 - rho) / (1 + rho) for rho clamped to [0, 1), and at least min(n, kMinEffectivePeriods).
inline double effectivePeriods(double periods, double rho) {
  const double r = std::clamp(std::isfinite(rho) ? rho : 0.0, 0.0, 1.0);
  const double n = periods * (1.0 - r) / (1.0 + r);
  return std::clamp(n, std::min(periods, kMinEffectivePeriods), periods);
}

/// The lag-1 autocorrelation of a sequence, exponentially weighted over `horizon` values
/// (weights (1 - 1 / horizon)^age; 0: every value alike, the whole sequence):
///
///   rho = (<u_k u_{k-1}> - <u>^2) / (<u^2> - <u>^2)
///
/// with <.> the weighted means (the product's over the pairs of neighbours). With equal
/// weights this is the usual sample autocorrelation up to its end terms.
class LagOneAutocorrelation {
 public:
  explicit LagOneAutocorrelation(double horizon = 0.0)
      : keep_(horizon > 1.0 ? 1.0 - 1.0 / horizon : 1.0) {}

  void add(double u) {
    if (count_ > 0) {
      pairWeight_ = keep_ * pairWeight_ + 1.0;
      product_ = keep_ * product_ + u * previous_;
    }
    weight_ = keep_ * weight_ + 1.0;
    sum_ = keep_ * sum_ + u;
    square_ = keep_ * square_ + u * u;
    previous_ = u;
    ++count_;
  }

  /// The estimate; 0 (no evidence of correlation) before two values, or when the values do
  /// not vary (a constant sequence has no autocorrelation to speak of).
  double value() const {
    if (count_ < 2) return 0.0;
    const double mean = sum_ / weight_, meanSquare = square_ / weight_;
    const double variance = meanSquare - mean * mean;
    if (!(variance > 1e-12 * meanSquare)) return 0.0;
    return (product_ / pairWeight_ - mean * mean) / variance;
  }

  void clear() {
    weight_ = sum_ = square_ = pairWeight_ = product_ = previous_ = 0.0;
    count_ = 0;
  }

 private:
  double keep_;
  double weight_ = 0.0, sum_ = 0.0, square_ = 0.0, pairWeight_ = 0.0, product_ = 0.0;
  double previous_ = 0.0;
  long count_ = 0;
};

}  // namespace sf_filter
