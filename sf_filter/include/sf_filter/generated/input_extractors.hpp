// Every input behind one interface: how TOPICS_IN entry In is taken out of its message, whatever
// it is (a field, a vector rotated into the base frame, a DERIVED_INPUTS quantity of an
// extractor kind, a GPS fix in the odom frame), with its variance source (a variance field, an
// INPUT_COVARIANCE entry, or none: the header's R) and the group its value is handed over in
// (alone, an INPUT_COVARIANCE_BLOCK, the fix's GPS inputs). `InputOf<In>` is the one place the
// header's per-input macros pick these; the topic reader (node_definition_of.hpp) calls every
// input the same way:
//
//   template <class In> struct <an input extractor> {
//     static constexpr bool valid;       // false: a static_assert of the configuration failed
//     template <class Message>
//     static std::optional<Sample> sample(const Message&, ReadContext&);  // nothing: no value
//     static std::string describe();     // "topic field ..." (the input's name)
//     static constexpr std::string_view kAxisName;  // FRAME_ALIGNED_INPUTS axis, "" otherwise
//     static void addParameters(std::vector<ExtractorParameter>&);  // the kind's ~parameters
//   };
//
// and every group the same way (Group<G>::send, once the message's inputs are read). The state
// of the extractors lives in the run's InputState (definition/input_state.hpp), not in the sink.
// Included by node_definition_of.hpp, inside "#if SF_CONFIG_OK".
#pragma once

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <ros/message_traits.h>

#include "sf_filter/config/frame_alignment.hpp"
#include "sf_filter/definition/input_state.hpp"
#include "sf_filter/definition/message_sink.hpp"

namespace sf_filter {
namespace generated {

using sf_config::extractors::ExtractorParameter;
using sf_config::extractors::Sample;

template <class Message>
double stampOf(const Message& msg) {
  if constexpr (ros::message_traits::HasHeader<Message>::value) {
    return msg.header.stamp.toSec();
  } else {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

/// What an input's extractor is given besides the message.
struct ReadContext {
  MessageSink& sink;
  InputState& state;
  double now;
  double stamp;  ///< the message's header stamp [s], NaN without a header
};

// ---- variance sources ------------------------------------------------------------------------

/// No variance in the message: the header's R.
struct NoVariance {
  template <class Message>
  static std::optional<double> variance(const Message&, estimation::Index, InputState&) {
    return std::nullopt;
  }
};

/// The TOPICS_IN entry's variance field.
template <class In>
struct VarianceField {
  template <class Message>
  static std::optional<double> variance(const Message& msg, estimation::Index, InputState&) {
    return In::variance(msg);
  }
};

/// The input's INPUT_COVARIANCE entry; nullopt and counted when the message's covariance is
/// unknown.
template <class In>
struct CovarianceEntry {
  using Source = sf_config::CovarianceSource<In::index>;
  template <class Message>
  static std::optional<double> variance(const Message& msg, estimation::Index input,
                                        InputState& state) {
    if constexpr (Source::valid) {
      const std::optional<double> v = Source::variance(msg);
      if (!v) state.countCovarianceFallback(input);
      return v;
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  }
};

template <class In>
using VarianceOf =
    std::conditional_t<sf_config::CovarianceSource<In::index>::given, CovarianceEntry<In>,
                       std::conditional_t<In::has_variance, VarianceField<In>, NoVariance>>;

// ---- input extractors ------------------------------------------------------------------------

/// What the extractors without a parameter or an axis share.
struct NoExtras {
  static constexpr std::string_view kAxisName = "";
  static void addParameters(std::vector<ExtractorParameter>&) {}
};

/// The TOPICS_IN entry's numeric field.
template <class In>
struct FieldInput : NoExtras {
  static constexpr bool valid = true;
  template <class Message>
  static std::optional<Sample> sample(const Message& msg, ReadContext& c) {
    return Sample{static_cast<double>(In::value(msg)),
                  VarianceOf<In>::variance(msg, In::index, c.state)};
  }
  static std::string describe() { return std::string(In::topic) + " " + std::string(In::field); }
};

/// A FRAME_ALIGNED_INPUTS entry: the component of its vector rotated into the base frame
/// (nothing when it cannot be rotated: dropped and counted by the sink).
template <class In>
struct RotatedInput {
  using Align = sf_config::FrameAlignment<In::index>;
  static constexpr bool valid = Align::valid;
  static constexpr std::string_view kAxisName = Align::axis_name;
  template <class Message>
  static std::optional<Sample> sample(const Message& msg, ReadContext& c) {
    if constexpr (valid) {
      const std::optional<double> variance = VarianceOf<In>::variance(msg, In::index, c.state);
      const std::optional<double> value =
          c.sink.rotated(In::index, msg.header.frame_id, msg.header.stamp.sec,
                         msg.header.stamp.nsec, Align::vector(msg), Align::axis);
      if (!value) return std::nullopt;
      return Sample{*value, variance};
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  }
  static std::string describe() {
    return std::string(In::topic) + " " + std::string(Align::member);
  }
  static void addParameters(std::vector<ExtractorParameter>&) {}
};

/// "topic field quantity [differential]" of a DERIVED_INPUTS entry.
template <class In>
std::string derivedName() {
  using Derivation = sf_config::Derivation<In::index>;
  std::string quantity(sf_config::extractors::quantityEntry(Derivation::quantity_index).name);
  for (char& ch : quantity) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return std::string(In::topic) + " " + std::string(In::field) + " " + quantity +
         (Derivation::differential ? " differential" : "");
}

/// A DERIVED_INPUTS quantity, by its extractor kind (config/extractors/kinds.hpp), whose object
/// the run's InputState keeps.
template <class In>
struct DerivedInput {
  using Derivation = sf_config::Derivation<In::index>;
  using Kind = typename Derivation::Kind;
  static constexpr bool valid = Derivation::valid;
  static constexpr std::string_view kAxisName = "";
  template <class Message>
  static std::optional<Sample> sample(const Message& msg, ReadContext& c) {
    if constexpr (valid) {
      const sf_config::extractors::SampleContext context{
          VarianceOf<In>::variance(msg, In::index, c.state), c.stamp,
          c.state.extractorParameters()};
      return c.state.extractor<Kind>(In::index)
          .template sample<Derivation::kind_quantity, Derivation::differential>(
              msg, In::member(msg), context);
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  }
  static std::string describe() { return derivedName<In>(); }
  static void addParameters(std::vector<ExtractorParameter>& all) {
    for (const ExtractorParameter& p : Kind::kParameters) {
      bool known = false;
      for (const ExtractorParameter& q : all) known = known || q.name == p.name;
      if (!known) all.push_back(p);
    }
  }
};

/// The fix of a sensor_msgs/NavSatFix (GPS inputs).
template <class Message>
gps::Fix fixOf(const Message& m) {
  gps::Fix f;
  f.status = static_cast<int>(m.status.status);
  f.latitude = static_cast<double>(m.latitude);
  f.longitude = static_cast<double>(m.longitude);
  f.altitude = static_cast<double>(m.altitude);
  for (std::size_t k = 0; k < f.covariance.size(); ++k) {
    f.covariance[k] = static_cast<double>(m.position_covariance[k]);
  }
  f.covarianceType = static_cast<int>(m.position_covariance_type);
  return f;
}

/// A GPS input (DERIVED_INPUTS EAST, NORTH, UP): the fix about the datum in the odom frame
/// (gps::GpsInputs, kept by the run's InputState), nothing for a fix without a valid status
/// (counted there); its variance is the fix's, unscaled (GpsGroup scales it).
template <class In>
struct GpsInput : NoExtras {
  using Gps = sf_config::GpsDerivation<In::index>;
  static constexpr bool valid = Gps::valid;
  static constexpr int axis = Gps::axis;
  template <class Message>
  static std::optional<Sample> sample(const Message& msg, ReadContext& c) {
    if constexpr (valid) {
      const std::optional<gps::GpsSample> s = c.state.gps().sample(In::index, axis, fixOf(msg));
      if (!s) return std::nullopt;
      return Sample{s->value, s->variance, s->covarianceUnknown};
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  }
  static std::string describe() { return derivedName<In>(); }
};

// ---- groups: the inputs of one message handed over together ----------------------------------

/// The samples one message gave a group's inputs, collected while it is read.
struct GroupValues {
  std::array<estimation::Index, 6> inputs{};
  std::array<Sample, 6> samples{};
  std::array<int, 6> keys{};  ///< per slot: the block's row position, or the GPS axis
  std::array<bool, 6> present{};
  int count = 0;
  void add(int slot, int key, estimation::Index input, const Sample& s) {
    const auto k = static_cast<std::size_t>(slot);
    inputs[k] = input;
    samples[k] = s;
    keys[k] = key;
    present[k] = true;
    ++count;
  }
};

/// Hands one sample to the sink alone: with its variance, or (unknown covariance, counted)
/// with the header's R.
inline void sendAlone(estimation::Index input, const Sample& s, ReadContext& c) {
  if (s.covarianceUnknown) c.state.countCovarianceFallback(input);
  c.sink.measurement(input, c.now, s.value, s.variance, c.stamp);
}

/// Position of `input` in Block's inputs.
template <class Block>
constexpr int positionIn(int input) {
  for (int k = 0; k < Block::size; ++k) {
    if (Block::inputs[k] == input) return k;
  }
  return 0;
}

/// An INPUT_COVARIANCE_BLOCK entry: its values together with the message's covariance block
/// when every value is there and the covariance known; otherwise each value alone, with its
/// variance from the block, or (unknown covariance, counted) with the header's R.
template <class Block>
struct BlockGroup {
  template <class In>
  static void add(GroupValues& v, const Sample& s) {
    const int slot = positionIn<Block>(In::index);
    v.add(slot, slot, In::index, s);
  }
  /// Sends the values if the block is read from topic Owner (the others' are not this message).
  template <int Owner, class Message>
  static void send(const Message& msg, const GroupValues& v, ReadContext& c) {
    if constexpr (Block::valid &&
                  std::tuple_element_t<Block::first, sf_config::Inputs>::first_same_topic ==
                      Owner) {
      std::array<double, 36> covariance{};
      const bool known = Block::read(msg, covariance.data());
      std::array<estimation::Index, 6> inputs{};
      std::array<double, 6> values{};
      for (int k = 0; k < Block::size; ++k) {
        const auto i = static_cast<std::size_t>(k);
        inputs[i] = Block::inputs[k];
        values[i] = v.samples[i].value;
      }
      if (known && v.count == Block::size) {
        c.sink.measurementBlock(inputs.data(), values.data(), covariance.data(), Block::size, c.now,
                                c.stamp);
        return;
      }
      for (int k = 0; k < Block::size; ++k) {
        const auto i = static_cast<std::size_t>(k);
        if (!v.present[i]) continue;
        const Sample s{
            values[i],
            known ? std::optional<double>(covariance[i * Block::size + i]) : std::nullopt, !known};
        sendAlone(inputs[i], s, c);
      }
    }
  }
};

/// The GPS inputs of one fix: with a known covariance type together with their covariances in
/// the odom frame (times GPS_COVARIANCE_SCALE) (the fusion core carries them to the filter's
/// R, correlation of x and y included); otherwise each alone, with the header's R (counted).
struct GpsGroup {
  template <class In>
  static void add(GroupValues& v, const Sample& s) {
    // In reading order; the configuration allows one input per axis.
    if (v.count < 3) v.add(v.count, GpsInput<In>::axis, In::index, s);
  }
  /// Sends the values if topic Owner has a GPS input (then its message is a fix).
  template <int Owner, class Message>
  static void send(const Message& msg, const GroupValues& v, ReadContext& c) {
    if constexpr (readsFix<Owner>(std::make_index_sequence<sf_config::kMeasurementSize>{})) {
      if (v.count > 0) sendFix(fixOf(msg), v, c);
    }
  }
  template <int Owner, std::size_t... I>
  static constexpr bool readsFix(std::index_sequence<I...>) {
    return ((std::tuple_element_t<I, sf_config::Inputs>::first_same_topic == Owner &&
             sf_config::GpsDerivation<static_cast<int>(I)>::valid) ||
            ...);
  }
  static void sendFix(const gps::Fix& fix, const GroupValues& v, ReadContext& c) {
    const std::optional<std::array<double, 9>> odom = c.state.gps().odomCovariance(fix);
    bool finite = true;
    for (int k = 0; k < v.count; ++k) {
      finite = finite && std::isfinite(v.samples[static_cast<std::size_t>(k)].value);
    }
    // A NaN value (no altitude for UP, no position) is dropped by the core alone; a block would
    // drop the others with it.
    if (odom && finite && v.count > 1) {
      sendBlock(*odom, v, c);
      return;
    }
    for (int k = 0; k < v.count; ++k) {
      const auto i = static_cast<std::size_t>(k);
      Sample s = v.samples[i];
      if (s.variance) s.variance = *s.variance * sf_config::kGpsCovarianceScale;
      sendAlone(v.inputs[i], s, c);  // without a variance the header's R is the white part
    }
  }
  static void sendBlock(const std::array<double, 9>& odom, const GroupValues& v, ReadContext& c) {
    std::array<double, 3> values{};
    std::array<double, 9> block{};
    const auto n = static_cast<std::size_t>(v.count);
    for (std::size_t i = 0; i < n; ++i) {
      values[i] = v.samples[i].value;
      for (std::size_t j = 0; j < n; ++j) {
        block[i * n + j] = odom[static_cast<std::size_t>(v.keys[i] * 3 + v.keys[j])] *
                           sf_config::kGpsCovarianceScale;
      }
    }
    c.sink.measurementBlock(v.inputs.data(), values.data(), block.data(), v.count, c.now, c.stamp);
  }
};

inline constexpr int kBlockCount = static_cast<int>(std::tuple_size_v<sf_config::CovarianceBlocks>);
/// The groups of a message: the INPUT_COVARIANCE_BLOCK entries, then the fix's GPS inputs.
inline constexpr int kGpsGroup = kBlockCount;
inline constexpr int kGroupCount = kBlockCount + 1;
/// An input handed over alone.
inline constexpr int kAlone = -1;

template <int G>
struct GroupAt {
  using type = BlockGroup<std::tuple_element_t<G, sf_config::CovarianceBlocks>>;
};
template <>
struct GroupAt<kGpsGroup> {
  using type = GpsGroup;
};
template <int G>
using Group = typename GroupAt<G>::type;

// ---- the one choice per input ----------------------------------------------------------------

/// Input In's extractor (`Extractor`), and the group its value is handed over in.
template <class In>
struct InputOf {
  static constexpr int index = In::index;
  using Derivation = sf_config::Derivation<index>;
  static constexpr bool aligned = sf_config::FrameAlignment<index>::aligned;
  static constexpr bool gps = sf_config::GpsDerivation<index>::gps;
  static constexpr int block = sf_config::blockOf(index);
  static_assert(gps || block >= 0 || !(Derivation::derived && aligned),
                "DERIVED_INPUTS and FRAME_ALIGNED_INPUTS: an input is listed in both; a derived "
                "input reads a quaternion or pose member, which is not rotated");
  static_assert(gps || block < 0 || !aligned,
                "INPUT_COVARIANCE_BLOCK and FRAME_ALIGNED_INPUTS: an input is listed in both; the "
                "message's covariance is given in the sensor's frame, which is not rotated");
  using Extractor = std::conditional_t<
      gps, GpsInput<In>,
      std::conditional_t<Derivation::derived, DerivedInput<In>,
                         std::conditional_t<aligned, RotatedInput<In>, FieldInput<In>>>>;
  static constexpr int group = gps ? kGpsGroup : block >= 0 ? block : kAlone;
};

/// Reads input In from `msg`: alone into the sink, or into its group's values (sent once the
/// message's inputs are read, sendGroups).
template <class In, class Message>
void readInput(const Message& msg, ReadContext& c, std::array<GroupValues, kGroupCount>& groups) {
  using Input = InputOf<In>;
  const std::optional<Sample> s = Input::Extractor::sample(msg, c);
  if (!s) return;
  if constexpr (Input::group == kAlone) {
    sendAlone(In::index, *s, c);
  } else {
    Group<Input::group>::template add<In>(groups[static_cast<std::size_t>(Input::group)], *s);
  }
}

/// Hands the groups' values of one message of topic Owner to the sink, in group order.
template <int Owner, class Message, std::size_t... G>
void sendGroups(const Message& msg, const std::array<GroupValues, kGroupCount>& groups,
                ReadContext& c, std::index_sequence<G...>) {
  (Group<static_cast<int>(G)>::template send<Owner>(msg, groups[G], c), ...);
}

}  // namespace generated
}  // namespace sf_filter
