// The online node's clock readings after it did not run (issue 15, nav3ctrl_params_online under
// load). On a loaded machine the node's process can get no CPU for longer than a period while
// the inputs keep coming: measured under `stress-ng --cpu 2`, 0.2 to 0.6 s of wall time,
// 0.4 to 1.1 s of bag time under `rosbag play -r 2`. roscpp then reads each connection's backlog
// in one go, and when it reads /clock first, every value sent during the pause carries the
// same receipt time, the clock after it: the node's clock jumps over the pause, estimates the
// periods in it without their values, and puts all of them into the last one (the offline
// replay spreads them over their periods).
//
// JumpHold holds such a jump: a reading more than one period after the core's clock is not
// passed to the core at once (the node reads the clock at every message, and its timer gives
// the core every period's end exactly, so only a pause, or a simulated clock coarser than the
// period, gets there). The values read while it is held were sent between the core's clock
// before the jump (the node was not reading since) and the reading: a stamped value goes into
// the period of its stamp (a value is never sent before it is stamped) within that interval;
// an unstamped value or a control is kept, and when the hold ends the k-th of the n that one
// input (one control) sent is placed at the k-th n-th of the interval - evenly in their order,
// the best guess without stamps; a single one at the reading, as before. The first later
// reading, or one before the interval (the clock ran backwards), ends the hold, and the core
// estimates the periods the jump crossed with their values (FusionCore::advanceTo). A clock
// that stops right after a jump (the end of a bag) is released by release(). ROS-free, so the
// rule is unit-tested with the core (sf_filter/test/test_jump_hold.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <sf_estimation/types.hpp>

namespace sf_filter {

class JumpHold {
 public:
  /// `period`: the core's estimation period [s]; a reading more than this after the core's
  /// clock is a jump.
  explicit JumpHold(double period) : period_(period) {}

  /// Whether the core may be advanced to `reading` now. `coreClock`: the core's last reading;
  /// `due`: periods that would be estimated at `reading`. A jump with periods due starts a
  /// hold (false); while holding, a reading within the held interval keeps it (false), a
  /// later or an earlier one ends it (true).
  bool admit(double reading, double coreClock, std::uint64_t due) {
    if (holding_) {
      if (reading >= from_ && reading <= heldAt_) return false;
      holding_ = false;
      return true;
    }
    if (due > 0 && reading - coreClock > period_ + kTolerance) {
      holding_ = true;
      ++holds_;
      from_ = coreClock;
      heldAt_ = reading;
      return false;
    }
    return true;
  }

  /// The time a value read at `reading` belongs to: while holding, a stamped value's stamp
  /// within [the core's clock before the jump, reading] (an unstamped one is kept instead);
  /// otherwise the reading. `stamp` NaN or 0 (ROS's unset stamp): none.
  double placement(double reading, double stamp) const {
    if (!holding_ || !stamped(stamp)) return reading;
    return std::min(reading, std::max(stamp, from_));
  }

  /// An unstamped value (`control` false: of input `index`, with its variance if any) or a
  /// control read while holding, in the order read.
  struct Kept {
    bool control = false;
    estimation::Index index = 0;
    double value = 0.0;
    std::optional<double> variance;
  };
  void keep(const Kept& kept) { kept_.push_back(kept); }

  /// Hands every kept value to place(const Kept&, double time), each input's and each
  /// control's values evenly over the held interval in their order, and forgets them. Called
  /// when the hold ends, before the core is advanced.
  template <class Place>
  void placeKept(Place&& place) {
    std::map<std::pair<bool, estimation::Index>, std::pair<int, int>> counts;  // n, k so far
    for (const Kept& v : kept_) ++counts[{v.control, v.index}].first;
    for (const Kept& v : kept_) {
      auto& [n, k] = counts[{v.control, v.index}];
      ++k;
      place(v, from_ + (heldAt_ - from_) * k / n);
    }
    kept_.clear();
  }

  bool holding() const { return holding_; }
  static bool stamped(double stamp) { return !std::isnan(stamp) && stamp != 0.0; }
  /// Jumps held so far.
  std::uint64_t holds() const { return holds_; }
  /// Ends the hold; returns the held reading, to which the core is to be advanced.
  double release() {
    holding_ = false;
    return heldAt_;
  }

 private:
  /// A reading one period after the last (the timer's) is no jump, whatever the rounding of
  /// their sums (PeriodSchedule's tolerance).
  static constexpr double kTolerance = 1e-6;

  double period_;
  bool holding_ = false;
  double from_ = 0.0;    ///< the core's clock before the jump
  double heldAt_ = 0.0;  ///< the reading held
  std::uint64_t holds_ = 0;
  std::vector<Kept> kept_;
};

}  // namespace sf_filter
