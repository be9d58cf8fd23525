// Filter consistency check by the normalised innovation squared (NIS, Bar-Shalom et al.,
// "Estimation with Applications to Tracking and Navigation", section 5.4.2). For a filter
// whose model, Q and R are right, the NIS of period k,
//
//   eps_k = y_k^T S_k^-1 y_k,   y_k = z_k - z^_k,   S_k = H P(k|k-1) H^T + R
//
// over the m_k measured entries is chi-square distributed with m_k degrees of freedom, and
// the innovations of different periods are independent. The sum over a window of K periods
// is then chi-square with D = sum m_k degrees of freedom, so its mean (1/K) sum eps_k lies in
//
//   [ chi2^-1(a/2; D) / K,  chi2^-1(1 - a/2; D) / K ]
//
// with probability 1 - a (two-sided; a = 0.05 by default). A mean above the bound says the
// innovations are larger than the filter believes (Q or R too small, or a wrong model); one
// below it says the filter is too pessimistic (Q or R too large).
#pragma once

#include <cstddef>
#include <vector>

namespace sf_filter {

struct NisBounds {
  double lower = 0.0;
  double upper = 0.0;
};

/// The two-sided bounds at level 1 - alpha on the mean over `periods` periods of NIS values
/// whose sum has `dof` degrees of freedom: the chi-square quantiles divided by `periods`.
NisBounds chiSquareMeanBounds(long dof, double periods, double alpha = 0.05);

class NisWindow {
 public:
  /// `periods`: the window length K (periods with at least one measured entry); 0 disables.
  explicit NisWindow(std::size_t periods = 0) : nis_(periods, 0.0), dof_(periods, 0) {}

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

  /// The two-sided bounds on mean() at level 1 - alpha. Requires size() > 0.
  /// Compiled once in the fusion-core library (src/core/nis_window.cpp): Boost.Math's
  /// chi-square quantiles cost a second of every configuration's compile time.
  NisBounds bounds(double alpha = 0.05) const;

  /// Whether the window is full and its mean lies outside bounds(alpha).
  bool inconsistent(double alpha = 0.05) const {
    if (!full()) return false;
    const NisBounds b = bounds(alpha);
    return mean() < b.lower || mean() > b.upper;
  }

  void clear() {
    size_ = next_ = 0;
    sum_ = 0.0;
    dofSum_ = 0;
    for (double& e : nis_) e = 0.0;
  }

 private:
  std::vector<double> nis_;
  std::vector<int> dof_;
  std::size_t size_ = 0, next_ = 0;
  double sum_ = 0.0;
  long dofSum_ = 0;
};

}  // namespace sf_filter
