// Fixed-lag Rauch-Tung-Striebel smoothing: after each filtered period k, the smoothed belief of
// period k - lag given everything up to k. It equals the full RTS pass (rts_smoother.hpp) over
// the periods 0..k evaluated at k - lag, without keeping the recording: a ring of the last
// lag + 1 periods holds each period's filtered belief, the one-step prediction to its
// successor and the smoother gain G of that link, all computed once, when the successor
// arrives. The backward pass of each period then only applies the lag's corrections
//
//   x_j^s = x_j + G_j (x_j+1^s - x(j+1|j)),  P_j^s = P_j + G_j (P_j+1^s - P(j+1|j)) G_j^T
//
// from k down to k - lag: O(lag) fixed-size products per period, fixed memory, no allocation
// after construction (fixed sizes). A period that was not predicted from its predecessor (a set
// belief, a rejected step) cuts the chain as it does for the full pass: nothing flows back
// across it.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/rts_smoother.hpp"
#include "sf_estimation/rts_step.hpp"
#include "sf_estimation/types.hpp"

namespace estimation {

template <class Prediction>
class FixedLagSmoother {
 public:
  static constexpr int N = Prediction::StateSize;
  static constexpr int L = Prediction::ControlSize;
  using Period = FilteredPeriod<N, L>;
  using Smoothed = SmoothedPeriod<N>;

  /// `lag` in periods (0: the filtered belief itself); `stateSize` the run-time size.
  FixedLagSmoother(Prediction prediction, const AngleMask<N>& angleStates, std::size_t lag,
                   Index stateSize)
      : prediction_(std::move(prediction)), angleStates_(angleStates), lag_(lag) {
    if (stateSize < 1) throw ParameterError("FixedLagSmoother: the state size must be >= 1");
    ring_.reserve(lag + 1);
    for (std::size_t i = 0; i <= lag; ++i) ring_.emplace_back(stateSize);
    smoothed_ = Smoothed{Vector<N>::Zero(stateSize), Matrix<N, N>::Zero(stateSize, stateSize)};
    work_ = smoothed_;
  }

  /// The fixed-lag smoother of a filter's full smoother (smootherFor(filter)).
  FixedLagSmoother(const RtsSmoother<Prediction>& smoother, std::size_t lag, Index stateSize)
      : FixedLagSmoother(smoother.prediction(), smoother.angleStates(), lag, stateSize) {}

  /// Adds the period just filtered (FilteredPeriod::of right after estimate()). Returns the
  /// smoothed belief of the period `lag` periods before it, or nullptr while fewer than
  /// lag + 1 periods were added. Throws NumericalError (then nothing was added).
  const Smoothed* add(const Period& period) {
    if (added_ > 0 && period.predicted) linkNewest(period);
    Slot& slot = ring_[added_ % ring_.size()];
    slot.period = period;
    ++added_;
    if (added_ <= lag_) return nullptr;
    backwardPass();
    return &smoothed_;
  }

  /// Forgets every period (a new run).
  void clear() { added_ = 0; }

  std::size_t lag() const { return lag_; }
  /// The filtered belief of the period the last add() smoothed (valid while add() returned a
  /// belief and until the next add()): what the smoothed one is compared with.
  const Period& laggedFiltered() const { return ring_[(added_ - 1 - lag_) % ring_.size()].period; }
  const AngleMask<N>& angleStates() const { return angleStates_; }
  /// Periods held now (at most lag + 1).
  std::size_t periodsHeld() const { return added_ < ring_.size() ? added_ : ring_.size(); }
  /// Memory of the ring: lag + 1 slots of this size.
  static constexpr std::size_t bytesPerSlot() { return sizeof(Slot); }

 private:
  /// A period and, once its successor arrived, the prediction to it and the link's gain.
  struct Slot {
    explicit Slot(Index n)
        : period{Vector<N>::Zero(n), Matrix<N, N>::Zero(n, n), Vector<L>(), false},
          prediction(n),
          gain(Matrix<N, N>::Zero(n, n)) {}
    Period period;
    OneStepPrediction<N> prediction;
    Matrix<N, N> gain;
  };

  /// Computes the prediction from the newest held period to `next` and its gain; throws
  /// before anything is changed.
  void linkNewest(const Period& next) {
    Slot& newest = ring_[(added_ - 1) % ring_.size()];
    OneStepPrediction<N> prediction(newest.period.x.size());
    Matrix<N, N> gain(newest.period.x.size(), newest.period.x.size());
    prediction_.predict(newest.period.x, newest.period.P, next.u, prediction);
    rtsGain<N>(prediction, gain);
    newest.prediction = prediction;
    newest.gain = gain;
  }

  /// Smooths from the newest period back to the one `lag` before it into smoothed_.
  void backwardPass() {
    const std::size_t size = ring_.size();
    const std::size_t newest = added_ - 1;
    smoothed_.x = ring_[newest % size].period.x;
    smoothed_.P = ring_[newest % size].period.P;
    for (std::size_t j = newest; j-- > newest - lag_;) {
      const Slot& slot = ring_[j % size];
      if (!ring_[(j + 1) % size].period.predicted) {
        smoothed_.x = slot.period.x;
        smoothed_.P = slot.period.P;
        continue;
      }
      rtsCorrect<N>(slot.period.x, slot.period.P, slot.prediction, slot.gain, smoothed_.x,
                    smoothed_.P, angleStates_, work_.x, work_.P);
      std::swap(smoothed_, work_);
    }
  }

  Prediction prediction_;
  AngleMask<N> angleStates_;
  std::size_t lag_;
  std::vector<Slot> ring_;
  std::size_t added_ = 0;
  Smoothed smoothed_;
  Smoothed work_;
};

/// The fixed-lag smoother of a filter (KF, EKF, UKF: whatever smootherFor accepts).
template <class Filter>
auto fixedLagSmootherFor(const Filter& filter, std::size_t lag) {
  auto smoother = smootherFor(filter);
  using Prediction = std::decay_t<decltype(smoother.prediction())>;
  return FixedLagSmoother<Prediction>(smoother, lag, filter.state().size());
}

}  // namespace estimation
