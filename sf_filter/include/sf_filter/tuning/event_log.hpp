// What a bag gives the fusion core, kept in memory: the clock reading of every message and the
// values (alone or as a message's covariance block) and controls its topic readers took out of
// it (after tf rotation and derived inputs), in the order the bag replay handed them to the core.
// Replaying the log into a fresh core (replayEvents) repeats the bag replay's estimates exactly,
// without reading or deserialising the bag again: the noise identification (noise_tuning.hpp)
// replays it hundreds of times.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sf_filter/core/fusion_engine.hpp"
#include "sf_filter/core/replay_clock.hpp"

namespace sf_filter {

class EventLog {
 public:
  void clock(double now) { events_.push_back({Kind::Clock, false, 0, now, 0.0, 0.0, 0.0}); }
  void measurement(Index input, double now, double value, std::optional<double> variance,
                   double stamp) {
    events_.push_back({Kind::Measurement, variance.has_value(), input, now, value,
                       variance.value_or(0.0), stamp});
  }
  /// The values of one message with their covariance block (MessageSink::measurementBlock:
  /// INPUT_COVARIANCE_BLOCK, a GPS fix); `count` at most FusionCoreBase::kMaxBlockSize.
  void measurementBlock(const Index* inputs, const double* values, const double* covariance,
                        int count, double now, double stamp) {
    Block b;
    b.count = count;
    for (int r = 0; r < count && r < kMaxBlock; ++r) {
      b.inputs[static_cast<std::size_t>(r)] = inputs[r];
      b.values[static_cast<std::size_t>(r)] = values[r];
      for (int c = 0; c < count && c < kMaxBlock; ++c) {
        b.covariance[static_cast<std::size_t>(r * count + c)] = covariance[r * count + c];
      }
    }
    events_.push_back(
        {Kind::Block, false, static_cast<Index>(blocks_.size()), now, 0.0, 0.0, stamp});
    blocks_.push_back(b);
  }
  void control(Index control, double value) {
    events_.push_back({Kind::Control, false, control, 0.0, value, 0.0, 0.0});
  }
  std::size_t size() const { return events_.size(); }

  /// The index of the first clock reading at or after `fraction` of the span of the log's
  /// clock readings (size() without one): where a log is split into a first and a later part.
  std::size_t splitIndex(double fraction) const {
    double first = 0.0, last = 0.0;
    bool any = false;
    for (const Event& e : events_) {
      if (e.kind != Kind::Clock) continue;
      if (!any) first = e.now;
      last = e.now;
      any = true;
    }
    const double at = first + fraction * (last - first);
    for (std::size_t i = 0; any && i < events_.size(); ++i) {
      if (events_[i].kind == Kind::Clock && events_[i].now >= at) return i;
    }
    return events_.size();
  }

  /// The log of the events before `end` (a recording cut there).
  EventLog head(std::size_t end) const {
    EventLog part;
    part.events_.assign(events_.begin(),
                        events_.begin() + static_cast<std::ptrdiff_t>(std::min(end, size())));
    part.blocks_ = blocks_;  // a Block event refers to its place here
    return part;
  }

  /// Feeds the log into `core` as the bag replay fed the bag, through the same ReplayClock;
  /// the estimates go to `write` (an EstimateRef callable).
  template <class Write>
  void replay(FusionEngine& core, Write& write) const {
    ReplayClock clock;
    replay(core, write, clock, 0, events_.size());
  }

  /// Events [begin, end) of the log through `clock`: a replay in parts (the held-out part of
  /// the noise identification's guard) gives the estimates of a replay in one.
  template <class Write>
  void replay(FusionEngine& core, Write& write, ReplayClock& clock, std::size_t begin,
              std::size_t end) const {
    for (std::size_t i = begin; i < end && i < events_.size(); ++i) {
      const Event& e = events_[i];
      switch (e.kind) {
        case Kind::Clock:
          clock.advance(core, e.now, write);
          break;
        case Kind::Measurement:
          core.addMeasurement(e.index, e.now, e.value,
                              e.hasVariance ? std::optional<double>(e.variance) : std::nullopt,
                              e.stamp);
          break;
        case Kind::Block: {
          const Block& b = blocks_[static_cast<std::size_t>(e.index)];
          core.addMeasurementBlock(b.inputs.data(), b.values.data(), b.covariance.data(), b.count,
                                   e.now, e.stamp);
          break;
        }
        case Kind::Control:
          core.addControl(e.index, e.value);
          break;
      }
    }
  }

 private:
  enum class Kind : std::uint8_t { Clock, Measurement, Block, Control };
  struct Event {
    Kind kind;
    bool hasVariance;  ///< the message carried a variance (passed on as it came)
    Index index;       ///< the input, the control, or for a Block its place in blocks_
    double now, value, variance, stamp;
  };
  static constexpr int kMaxBlock = 6;  ///< FusionCoreBase::kMaxBlockSize
  /// One message's block (the generated readers never hand over more than kMaxBlock values).
  struct Block {
    int count = 0;
    std::array<Index, kMaxBlock> inputs{};
    std::array<double, kMaxBlock> values{};
    std::array<double, kMaxBlock * kMaxBlock> covariance{};
  };
  std::vector<Event> events_;
  std::vector<Block> blocks_;
};

}  // namespace sf_filter
