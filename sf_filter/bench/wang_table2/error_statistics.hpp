// The figures of Wang et al.'s Table II and their Monte Carlo uncertainty.
//
// ErrorSeries: the estimation error e(k) = x^(k) - x(k) of one simulated run, summarised as
// Table II does: its variance (about its own mean, divided by the number of samples) and its
// root mean square. Welford's update keeps the variance exact for long series whose mean is
// far from zero.
//
// RunAverage: one figure (a variance or an rms) over independent Monte Carlo runs: the mean
// and its standard error s / sqrt(runs), s the sample standard deviation (divisor runs - 1).
//
// PairedChange: the relative change of one method's figure against another's, (b - a) / a of
// the run means, when both were measured on the same runs (common random numbers). Its
// standard error is that of the mean per-run difference divided by the mean of a; the
// uncertainty of that denominator is left out (first-order delta method), which the
// difference's own spread dominates when the change is small.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace wang_table2 {

class ErrorSeries {
 public:
  void add(double error) {
    ++count_;
    const double delta = error - mean_;
    mean_ += delta / static_cast<double>(count_);
    squaredDeviations_ += delta * (error - mean_);
    sumOfSquares_ += error * error;
  }

  std::size_t count() const { return count_; }
  double mean() const { return mean_; }
  /// Population variance (divisor count); 0 without samples.
  double variance() const {
    return count_ == 0 ? 0.0 : squaredDeviations_ / static_cast<double>(count_);
  }
  /// sqrt(mean of e^2); 0 without samples.
  double rms() const {
    return count_ == 0 ? 0.0 : std::sqrt(sumOfSquares_ / static_cast<double>(count_));
  }

 private:
  std::size_t count_ = 0;
  double mean_ = 0.0;
  double squaredDeviations_ = 0.0;
  double sumOfSquares_ = 0.0;
};

class RunAverage {
 public:
  void add(double value) { series_.add(value); }

  std::size_t runs() const { return series_.count(); }
  double mean() const { return series_.mean(); }
  /// s / sqrt(runs) with the sample standard deviation s; needs two runs at least.
  double standardError() const {
    const auto n = static_cast<double>(series_.count());
    if (series_.count() < 2) {
      throw std::logic_error("a standard error needs two runs at least");
    }
    return std::sqrt(series_.variance() * n / (n - 1.0) / n);
  }

 private:
  ErrorSeries series_;  // the same running moments, over runs instead of time
};

class PairedChange {
 public:
  /// One run's figure of the reference method (a) and of the compared method (b).
  void add(double reference, double compared) {
    reference_.add(reference);
    difference_.add(compared - reference);
  }

  std::size_t runs() const { return reference_.runs(); }
  /// (mean b - mean a) / mean a.
  double relative() const { return difference_.mean() / reference_.mean(); }
  double standardError() const { return difference_.standardError() / std::abs(reference_.mean()); }

 private:
  RunAverage reference_;
  RunAverage difference_;
};

}  // namespace wang_table2
