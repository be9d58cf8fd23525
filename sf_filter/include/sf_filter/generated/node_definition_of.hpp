// The part of a fusion node that depends on its configuration header: the NodeDefinition of
// the header (names, sizes, defaults, one reader per subscribed topic, the filter in its
// fusion core). Included by the node's translation unit after the configuration header and
// configuration.hpp, inside "#if SF_CONFIG_OK". It includes no roscpp node code: the message
// headers of the configuration bring only ROS's serialization, which is all a reader needs.
#pragma once

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <boost/preprocessor/seq/elem.hpp>
#include <boost/preprocessor/seq/size.hpp>

#include "sf_filter/config/filter_binding.hpp"
#include "sf_filter/config/frame_alignment.hpp"
#include "sf_filter/core/fusion_engine_of.hpp"
#include "sf_filter/definition/node_definition.hpp"

#ifdef POSE_OUT
static_assert(BOOST_PP_SEQ_SIZE(POSE_OUT) == 3,
              "POSE_OUT: expected (x index)(y index)(heading index), 3 entries");
static_assert(BOOST_PP_SEQ_ELEM(0, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(1, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(2, POSE_OUT) < sf_config::kStateSize,
              "POSE_OUT: every state index must be < n (the state size)");
#endif

namespace sf_filter {
namespace generated {

template <class Message>
double stampOf(const Message& msg) {
  if constexpr (ros::message_traits::HasHeader<Message>::value) {
    return msg.header.stamp.toSec();
  } else {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

template <class Message>
Message deserialize(const std::uint8_t* data, std::uint32_t size) {
  Message msg;
  ros::serialization::IStream stream(const_cast<std::uint8_t*>(data), size);
  ros::serialization::deserialize(stream, msg);
  return msg;
}

template <class Message>
TopicReader topicReader(std::string_view topic, bool controls) {
  TopicReader reader;
  reader.topic = std::string(topic);
  reader.datatype = ros::message_traits::DataType<Message>::value();
  reader.md5sum = ros::message_traits::MD5Sum<Message>::value();
  reader.definition = ros::message_traits::Definition<Message>::value();
  reader.controls = controls;
  return reader;
}

/// Value of input In from `msg`: its field, or for a FRAME_ALIGNED_INPUTS entry the component
/// of its vector rotated into the base frame (nullopt: not rotatable, dropped by the sink).
template <class In, class Message>
std::optional<double> inputValue(const Message& msg, MessageSink& sink) {
  using Align = sf_config::FrameAlignment<In::index>;
  if constexpr (Align::aligned) {
    if constexpr (Align::valid) {
      return sink.rotated(In::index, msg.header.frame_id, msg.header.stamp.sec,
                          msg.header.stamp.nsec, Align::vector(msg), Align::axis);
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  } else {
    return In::value(msg);
  }
}

/// The variance input In's message carries: its INPUT_COVARIANCE entry (nullopt and counted
/// when the message's covariance is unknown), its variance field, or none.
template <class In, class Message>
std::optional<double> inputVariance(const Message& msg, MessageSink& sink) {
  using Source = sf_config::CovarianceSource<In::index>;
  if constexpr (Source::given) {
    if constexpr (Source::valid) {
      const std::optional<double> variance = Source::variance(msg);
      if (!variance) sink.countCovarianceFallback(In::index);
      return variance;
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  } else if constexpr (In::has_variance) {
    return In::variance(msg);
  } else {
    return std::nullopt;
  }
}

/// What one fix gave its topic's GPS inputs (DERIVED_INPUTS EAST, NORTH, UP), collected while
/// the message is read and handed over together (sendGps).
struct GpsValues {
  std::optional<gps::Fix> fix;  ///< the message as a fix, once a GPS input has read it
  std::array<estimation::Index, 3> inputs{};
  std::array<int, 3> axes{};
  std::array<gps::GpsSample, 3> samples{};
  int count = 0;  ///< inputs with a sample (not dropped for the fix's status)
};

/// Reads GPS input In from the fix `msg` into `values`: its position in the odom frame
/// (gps::GpsInputs), nothing for a fix without a valid status (counted there).
template <class In, class Message>
void readGpsInput(const Message& msg, MessageSink& sink, GpsValues& values) {
  using Gps = sf_config::GpsDerivation<In::index>;
  if constexpr (Gps::valid) {
    if (!values.fix) values.fix = Gps::fix(msg);
    const std::optional<gps::GpsSample> s = sink.gps().sample(In::index, Gps::axis, *values.fix);
    if (!s || values.count >= 3) return;  // the configuration allows one input per axis
    const auto k = static_cast<std::size_t>(values.count++);
    values.inputs[k] = In::index;
    values.axes[k] = Gps::axis;
    values.samples[k] = *s;
  }  // else not built: a static_assert of the configuration reported why
}

/// Hands one fix's GPS values to the sink: with a known covariance type together with their
/// covariances in the odom frame (times GPS_COVARIANCE_SCALE) (the fusion core carries them to the
/// filter's R, correlation of x and y included); otherwise each alone, with the header's R
/// (counted).
inline void sendGps(const GpsValues& v, MessageSink& sink, double now, double stamp) {
  if (v.count == 0) return;
  const std::optional<std::array<double, 9>> odom = sink.gps().odomCovariance(*v.fix);
  bool finite = true;
  for (int k = 0; k < v.count; ++k) {
    finite = finite && std::isfinite(v.samples[static_cast<std::size_t>(k)].value);
  }
  // A NaN value (no altitude for UP, no position) is dropped by the core alone; a block would
  // drop the others with it.
  if (odom && finite && v.count > 1) {
    std::array<double, 3> values{};
    std::array<double, 9> block{};
    for (int r = 0; r < v.count; ++r) {
      const auto i = static_cast<std::size_t>(r);
      values[i] = v.samples[i].value;
      for (int c = 0; c < v.count; ++c) {
        const auto j = static_cast<std::size_t>(c);
        block[i * static_cast<std::size_t>(v.count) + j] =
            (*odom)[static_cast<std::size_t>(v.axes[i] * 3 + v.axes[j])] *
            sf_config::kGpsCovarianceScale;
      }
    }
    sink.measurementBlock(v.inputs.data(), values.data(), block.data(), v.count, now, stamp);
    return;
  }
  for (int k = 0; k < v.count; ++k) {
    const gps::GpsSample& s = v.samples[static_cast<std::size_t>(k)];
    if (s.covarianceUnknown) sink.countCovarianceFallback(v.inputs[static_cast<std::size_t>(k)]);
    const std::optional<double> variance =
        s.variance ? std::optional<double>(*s.variance * sf_config::kGpsCovarianceScale)
                   : std::nullopt;  // the header's R is the white part already
    sink.measurement(v.inputs[static_cast<std::size_t>(k)], now, s.value, variance, stamp);
  }
}

/// The sample of DERIVED_INPUTS input In (not a GPS input) from `msg`, by the input's extractor
/// kind (config/extractors/kinds.hpp), whose object the sink keeps.
template <class In, class Message>
std::optional<sf_config::extractors::Sample> derivedSample(const Message& msg, MessageSink& sink,
                                                           std::optional<double> variance,
                                                           double stamp) {
  using Derivation = sf_config::Derivation<In::index>;
  using Kind = typename Derivation::Kind;
  const sf_config::extractors::SampleContext context{variance, stamp, sink.extractorParameters()};
  return sink.extractor<Kind>(In::index)
      .template sample<Derivation::kind_quantity, Derivation::differential>(msg, In::member(msg),
                                                                            context);
}

/// Reads input In (not a GPS input) from `msg` into the sink: a DERIVED_INPUTS quantity by its
/// extractor, or the field (or rotated vector).
template <class In, class Message>
void readInput(const Message& msg, MessageSink& sink, double now) {
  using Derivation = sf_config::Derivation<In::index>;
  static_assert(!(Derivation::derived && sf_config::FrameAlignment<In::index>::aligned),
                "DERIVED_INPUTS and FRAME_ALIGNED_INPUTS: an input is listed in both; a derived "
                "input reads a quaternion or pose member, which is not rotated");
  [[maybe_unused]] const std::optional<double> variance = inputVariance<In>(msg, sink);
  const double stamp = stampOf(msg);
  if constexpr (Derivation::derived) {
    if constexpr (Derivation::valid) {
      const std::optional<sf_config::extractors::Sample> s =
          derivedSample<In>(msg, sink, variance, stamp);
      if (!s) return;
      if (s->covarianceUnknown) sink.countCovarianceFallback(In::index);
      sink.measurement(In::index, now, s->value, s->variance, stamp);
    }
  } else {
    const std::optional<double> value = inputValue<In>(msg, sink);
    if (!value) return;
    sink.measurement(In::index, now, *value, variance, stamp);
  }
}

/// The values one message gave the inputs of an INPUT_COVARIANCE_BLOCK entry, collected while
/// it is read and handed over together (sendBlocks).
struct BlockValues {
  std::array<double, 6> value{};
  std::array<bool, 6> present{};
};

/// Value of block input In: its field or an ABSOLUTE derived quantity (the configuration
/// refuses DIFFERENTIAL ones and FRAME_ALIGNED_INPUTS in a block).
template <class In, class Message>
std::optional<double> blockInputValue(const Message& msg, MessageSink& sink) {
  static_assert(!sf_config::FrameAlignment<In::index>::aligned,
                "INPUT_COVARIANCE_BLOCK and FRAME_ALIGNED_INPUTS: an input is listed in both; the "
                "message's covariance is given in the sensor's frame, which is not rotated");
  using Derivation = sf_config::Derivation<In::index>;
  if constexpr (Derivation::derived) {
    if constexpr (Derivation::valid && !Derivation::differential) {
      // The block gives the variance: the sample's is not used.
      const std::optional<sf_config::extractors::Sample> s =
          derivedSample<In>(msg, sink, std::nullopt, stampOf(msg));
      return s ? std::optional<double>(s->value) : std::nullopt;
    } else {
      return std::nullopt;  // not built: a static_assert of the configuration reported why
    }
  } else {
    return In::value(msg);
  }
}

/// Position of `input` in Block's inputs.
template <class Block>
constexpr int positionIn(int input) {
  for (int k = 0; k < Block::size; ++k) {
    if (Block::inputs[k] == input) return k;
  }
  return 0;
}

/// Hands Block's values of `msg` to the sink if the block is read from topic Owner: together
/// with the message's covariance block when every value is there and the covariance known;
/// otherwise each value alone, with its variance from the block, or (unknown covariance,
/// counted) with the header's R.
template <int Owner, class Block, class Message>
void sendBlock(const Message& msg, const BlockValues& v, MessageSink& sink, double now) {
  if constexpr (Block::valid) {
    if constexpr (std::tuple_element_t<Block::first, sf_config::Inputs>::first_same_topic ==
                  Owner) {
      std::array<double, 36> covariance{};
      const bool known = Block::read(msg, covariance.data());
      std::array<estimation::Index, 6> inputs{};
      bool all = true;
      for (int k = 0; k < Block::size; ++k) {
        inputs[static_cast<std::size_t>(k)] = Block::inputs[k];
        all = all && v.present[static_cast<std::size_t>(k)];
      }
      const double stamp = stampOf(msg);
      if (known && all) {
        sink.measurementBlock(inputs.data(), v.value.data(), covariance.data(), Block::size, now,
                              stamp);
        return;
      }
      for (int k = 0; k < Block::size; ++k) {
        const auto i = static_cast<std::size_t>(k);
        if (!v.present[i]) continue;
        if (!known) sink.countCovarianceFallback(inputs[i]);
        sink.measurement(
            inputs[i], now, v.value[i],
            known ? std::optional<double>(covariance[i * Block::size + i]) : std::nullopt, stamp);
      }
    }
  }
}

template <int Owner, class Message, std::size_t... K>
void sendBlocks(const Message& msg, const std::array<BlockValues, sizeof...(K)>& blocks,
                MessageSink& sink, double now, std::index_sequence<K...>) {
  (sendBlock<Owner, std::tuple_element_t<K, sf_config::CovarianceBlocks>>(msg, blocks[K], sink,
                                                                          now),
   ...);
  static_cast<void>(msg);
  static_cast<void>(blocks);
  static_cast<void>(sink);
  static_cast<void>(now);
}

/// One reader per distinct topic of TOPICS_IN and of TOPICS_IN_CTRL; a reader takes every
/// field used from its topic.
inline std::vector<TopicReader> topicReaders() {
  std::vector<TopicReader> readers;
  sf_config::forEachInput([&](auto owner) {
    using Owner = decltype(owner);
    if constexpr (Owner::owns_subscription) {
      using Message = typename Owner::Message;
      TopicReader reader = topicReader<Message>(Owner::topic, false);
      reader.read = [](const std::uint8_t* data, std::uint32_t size, MessageSink& sink,
                       double now) {
        const Message msg = deserialize<Message>(data, size);
        constexpr std::size_t kBlocks = std::tuple_size_v<sf_config::CovarianceBlocks>;
        std::array<BlockValues, kBlocks> blocks{};
        GpsValues gpsValues;
        sf_config::forEachInput([&](auto in) {
          using In = decltype(in);
          if constexpr (In::first_same_topic == Owner::index) {
            constexpr int block = sf_config::blockOf(In::index);
            if constexpr (sf_config::GpsDerivation<In::index>::gps) {
              readGpsInput<In>(msg, sink, gpsValues);
            } else if constexpr (block >= 0) {
              using Block = std::tuple_element_t<block, sf_config::CovarianceBlocks>;
              const std::optional<double> value = blockInputValue<In>(msg, sink);
              const auto k = static_cast<std::size_t>(positionIn<Block>(In::index));
              if (value) {
                blocks[static_cast<std::size_t>(block)].value[k] = *value;
                blocks[static_cast<std::size_t>(block)].present[k] = true;
              }
            } else {
              readInput<In>(msg, sink, now);
            }
          }
        });
        sendBlocks<Owner::index>(msg, blocks, sink, now, std::make_index_sequence<kBlocks>{});
        sendGps(gpsValues, sink, now, stampOf(msg));
      };
      appendTopicReader(readers, std::move(reader));
    }
  });
  sf_config::forEachControl([&](auto owner) {
    using Owner = decltype(owner);
    if constexpr (Owner::owns_subscription) {
      using Message = typename Owner::Message;
      TopicReader reader = topicReader<Message>(Owner::topic, true);
      reader.read = [](const std::uint8_t* data, std::uint32_t size, MessageSink& sink, double) {
        const Message msg = deserialize<Message>(data, size);
        sf_config::forEachControl([&](auto in) {
          using In = decltype(in);
          if constexpr (In::first_same_topic == Owner::index)
            sink.control(In::index, In::value(msg));
        });
      };
      appendTopicReader(readers, std::move(reader));
    }
  });
  return readers;
}

inline FilterParameters toRunTime(const sf_config::Parameters& p) {
  FilterParameters r;
  r.estimation_period_ms = p.estimation_period_ms;
  r.process_noise_covariance = p.process_noise_covariance;
  r.measurement_noise_covariance = p.measurement_noise_covariance;
  r.initial_state = p.initial_state;
  r.initial_error_covariance = p.initial_error_covariance;
  copyMethodParameters(r, p);
  r.window_size = p.window_size;
  r.weighting_coefficients = p.weighting_coefficients;
  return r;
}

/// `from` into the fixed-size `to`; the sizes were checked when the parameters were read (and
/// again here, by requireParameterShape, compiled once in the core library).
template <class Fixed>
void assignChecked(Fixed& to, const Eigen::MatrixXd& from, const char* name) {
  requireParameterShape(from, to.rows(), to.cols(), name);
  to = from;
}

inline sf_config::Parameters toFixedSize(const FilterParameters& r) {
  sf_config::Parameters p = sf_config::defaultParameters(r.estimation_period_ms);
  assignChecked(p.process_noise_covariance, r.process_noise_covariance, "Q");
  assignChecked(p.measurement_noise_covariance, r.measurement_noise_covariance, "R");
  assignChecked(p.initial_state, r.initial_state, "x0");
  assignChecked(p.initial_error_covariance, r.initial_error_covariance, "P0");
  copyMethodParameters(p, r);
  p.window_size = r.window_size;
  p.weighting_coefficients = r.weighting_coefficients;
  return p;
}

/// "topic field" per input; "topic member" for a FRAME_ALIGNED_INPUTS one; with INPUTS
/// records "name: topic field".
inline std::vector<std::string> inputNames() {
  std::vector<std::string> names;
  sf_config::forEachInput([&](auto in) {
    using In = decltype(in);
    using Align = sf_config::FrameAlignment<In::index>;
    using Derivation = sf_config::Derivation<In::index>;
    if constexpr (Align::aligned) {
      names.push_back(std::string(In::topic) + " " + std::string(Align::member));
    } else if constexpr (Derivation::derived) {
      std::string quantity(sf_config::extractors::quantityEntry(Derivation::quantity_index).name);
      for (char& c : quantity) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      names.push_back(std::string(In::topic) + " " + std::string(In::field) + " " + quantity +
                      (Derivation::differential ? " differential" : ""));
    } else {
      names.push_back(std::string(In::topic) + " " + std::string(In::field));
    }
    if constexpr (sf_config::kHasInputRecords) {
      names.back() = std::string(sf_config::kInputNames[In::index]) + ": " + names.back();
    }
  });
  return names;
}

/// The private parameters of the extractor kinds the inputs are read by, each once.
inline std::vector<sf_config::extractors::ExtractorParameter> extractorParameters() {
  std::vector<sf_config::extractors::ExtractorParameter> all;
  sf_config::forEachInput([&](auto in) {
    using Derivation = sf_config::Derivation<decltype(in)::index>;
    if constexpr (Derivation::derived) {
      for (const sf_config::extractors::ExtractorParameter& p : Derivation::Kind::kParameters) {
        bool known = false;
        for (const auto& q : all) known = known || q.name == p.name;
        if (!known) all.push_back(p);
      }
    }
  });
  return all;
}

inline NodeDefinition nodeDefinition() {
  NodeDefinition d;
  NodeDescription& description = d.description;
  description.method = sf_config::kMethodName;
  description.inputs = inputNames();
  sf_config::forEachControl([&](auto in) {
    using In = decltype(in);
    description.controls.push_back(std::string(In::topic) + " " + std::string(In::field));
  });
  sf_config::forEachOutput([&](auto out) {
    using Out = decltype(out);
    description.outputs.emplace_back(std::string(Out::topic), Out::state_index);
  });
#ifdef POSE_OUT
  description.pose =
      std::array<int, 3>{BOOST_PP_SEQ_ELEM(0, POSE_OUT), BOOST_PP_SEQ_ELEM(1, POSE_OUT),
                         BOOST_PP_SEQ_ELEM(2, POSE_OUT)};
#endif
  if constexpr (sf_config::kHasTwistOut) description.twist = sf_config::kTwistOut;
  if constexpr (sf_config::kHasAccelOut) description.accel = sf_config::kAccelOut;
  d.capabilities.canPredict = estimation::HasMeasurementPrediction<Filter>::value;
  d.capabilities.hasStamp.assign(sf_config::kInputHasStamp.begin(),
                                 sf_config::kInputHasStamp.end());
  d.capabilities.names = description.inputs;
  d.capabilities.keys.assign(sf_config::kInputNames.begin(), sf_config::kInputNames.end());
  d.estimationPeriodMs = sf_config::kEstimationPeriodMs;
  d.maxMeasurementLagMs = sf_config::kMaxMeasurementLagMs;
  d.inputOptions = sf_config::defaultInputOptions();
  d.alignedAxis.resize(description.inputs.size());
  sf_config::forEachInput([&](auto in) {
    using In = decltype(in);
    using Align = sf_config::FrameAlignment<In::index>;
    if constexpr (Align::aligned) d.alignedAxis[In::index] = std::string(Align::axis_name);
  });
  d.extractorParameters = extractorParameters();
  d.frameAlignment = sf_config::kHasFrameAlignment;
  d.baseFrame = std::string(sf_config::kBaseFrame);
  d.topics = topicReaders();
  d.defaultParameters = [](double periodMs) {
    return toRunTime(sf_config::defaultParameters(periodMs));
  };
  d.makeEngine = [](const FilterParameters& parameters, const FusionCoreOptions& options) {
    FusionCoreOptions o = options;
    for (std::size_t k = 0; k < sf_config::kInitialFromInputsCount; ++k) {
      o.initialFromInputs.push_back(
          {sf_config::kInitialFromInputs[k].state, sf_config::kInitialFromInputs[k].input});
    }
    return std::unique_ptr<FusionEngine>(
        new FusionEngineOf<Filter>(makeFilter(toFixedSize(parameters)), o));
  };
  return d;
}

}  // namespace generated
}  // namespace sf_filter
