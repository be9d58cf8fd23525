// The newest samples of one input with their times: the shift register U_j of Armesto et al.'s
// multi-rate hold (Algorithm 1, lines 3-5) and the stored vector u of Wang et al.'s gap
// filling (eq. 5). Fixed capacity, no allocation.
#pragma once

#include <array>

namespace sf_filter {

struct TimedSample {
  double time = 0.0;  ///< [s], the sample's stamp or arrival time
  double value = 0.0;
};

class SampleHistory {
 public:
  /// Most samples any policy keeps: a hold of order 15, or gap filling with N = 16.
  static constexpr int kCapacity = 16;

  /// Keeps the newest `length` samples, 1 <= length <= kCapacity (clamped).
  explicit SampleHistory(int length = kCapacity)
      : length_(length < 1           ? 1
                : length > kCapacity ? kCapacity
                                     : length) {}

  /// Shifts in a sample, shifting out the oldest when full. A sample at the time of the newest
  /// replaces it (two values at one instant would make the primitives divide by zero); one
  /// older than the newest is ignored and false returned.
  bool push(double time, double value) {
    if (size_ > 0) {
      TimedSample& newest = slot(0);
      if (time == newest.time) {
        newest.value = value;
        return true;
      }
      if (time < newest.time) return false;
    }
    head_ = (head_ + 1) % kCapacity;
    samples_[static_cast<std::size_t>(head_)] = {time, value};
    if (size_ < length_) ++size_;
    return true;
  }

  int size() const { return size_; }
  int length() const { return length_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == length_; }

  /// The sample `age` shifts ago: 0 is the newest (u_j), size() - 1 the oldest kept.
  const TimedSample& operator[](int age) const {
    return samples_[static_cast<std::size_t>((head_ - age + kCapacity) % kCapacity)];
  }

  void clear() { size_ = 0; }

 private:
  TimedSample& slot(int age) {
    return samples_[static_cast<std::size_t>((head_ - age + kCapacity) % kCapacity)];
  }

  std::array<TimedSample, kCapacity> samples_{};
  int length_;
  int head_ = 0;
  int size_ = 0;
};

}  // namespace sf_filter
