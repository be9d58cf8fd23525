// PeriodSmoother for one filter type: the record of a FusionCore<Filter>'s run on the
// filter's fixed-size types and its RTS smoother (KF, EKF) or unscented RTS smoother (UKF).
// Filters without a smoother (particle filter, window filters) have none (HasSmoother).
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <sf_estimation/rts_smoother.hpp>
#include <sf_estimation/unscented_rts_smoother.hpp>

#include "sf_filter/core/period_smoother.hpp"

namespace sf_filter {

/// Whether sf_estimation has a smoother for Filter (estimation::smootherFor).
template <class Filter, class = void>
struct HasSmoother : std::false_type {};
template <class Filter>
struct HasSmoother<Filter,
                   std::void_t<decltype(estimation::smootherFor(std::declval<const Filter&>()))>>
    : std::true_type {};

template <class Core>
class PeriodSmootherOf final : public PeriodSmoother {
  using Filter = std::decay_t<decltype(std::declval<const Core&>().filter())>;
  using Smoother = decltype(estimation::smootherFor(std::declval<const Filter&>()));
  static constexpr int N = Filter::StateSize;
  static constexpr int L = Filter::ControlSize;
  using Period = estimation::FilteredPeriod<N, L>;

 public:
  explicit PeriodSmootherOf(const Core& core)
      : core_(core), smoother_(estimation::smootherFor(core.filter())) {}

  void record() override {
    const auto& e = core_.lastEstimate();
    // The core's last estimate is the filter's committed belief; a rejected step (the belief
    // kept and widened by Q), a restart, or a clock reset since the last record (the filter
    // back at its initial belief) is not a time update from the recorded predecessor.
    const bool predicted =
        !record_.empty() && !e.stepFailed && !e.filterReset && core_.clockResets() == clockResets_;
    clockResets_ = core_.clockResets();
    record_.push_back(Period{e.state, e.covariance, core_.filter().control(), predicted});
    if (!predicted) ++segments_;
  }

  void smooth() override { smoother_.smooth(record_, smoothed_); }

  std::size_t periods() const override { return record_.size(); }
  std::size_t segments() const override { return segments_; }
  PeriodBelief filtered(std::size_t k) const override { return view(record_[k].x, record_[k].P); }
  PeriodBelief smoothed(std::size_t k) const override {
    return view(smoothed_[k].x, smoothed_[k].P);
  }
  std::size_t bytesPerPeriod() const override {
    return sizeof(Period) + sizeof(estimation::SmoothedPeriod<N>);
  }

 private:
  template <class X, class P>
  static PeriodBelief view(const X& x, const P& covariance) {
    const auto n = x.size();
    return {Eigen::Map<const Eigen::VectorXd>(x.data(), n),
            Eigen::Map<const Eigen::MatrixXd>(covariance.data(), n, n)};
  }

  const Core& core_;
  Smoother smoother_;
  std::vector<Period> record_;
  std::vector<estimation::SmoothedPeriod<N>> smoothed_;
  std::uint64_t clockResets_ = 0;
  std::size_t segments_ = 0;
};

}  // namespace sf_filter
