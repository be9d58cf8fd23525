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
#include "sf_filter/core/fusion_engine_of.hpp"
#include "sf_filter/definition/node_definition.hpp"
#include "sf_filter/generated/input_extractors.hpp"

#ifdef POSE_OUT
static_assert(BOOST_PP_SEQ_SIZE(POSE_OUT) == 3,
              "POSE_OUT: expected (x index)(y index)(heading index), 3 entries");
static_assert(BOOST_PP_SEQ_ELEM(0, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(1, POSE_OUT) < sf_config::kStateSize &&
                  BOOST_PP_SEQ_ELEM(2, POSE_OUT) < sf_config::kStateSize,
              "POSE_OUT: every state index must be < n (the state size)");
#endif

#if !SF_CFG_IS_AVERAGING && defined(SF_FILTER_SMOOTHERS_UNIT)
// sf_add_filter() compiles the third unit (fusion_node_step.cpp) only for a header in which it
// finds QUATERNION_STATES by a look at the text (cmake/sf_add_filter.cmake), and the fourth
// (fusion_node_jacobians.cpp) for one in which it finds that or EXTENDED_KALMAN_FILTER; without
// them the step and the layout EKF's observation Jacobian would be undefined references at the
// link (a planar EKF's Jacobians are then compiled here: filter_binding.hpp).
#if defined(QUATERNION_STATES) && !defined(SF_FILTER_STEP_UNIT)
#error QUATERNION_STATES: sf_add_filter() did not find it in the configuration header or in a header that one includes with double quotes, so it left out the unit of the filter step (fusion_node_step.cpp) and for an EKF that of its Jacobians (fusion_node_jacobians.cpp); name QUATERNION_STATES in the header itself (a comment will do) and re-run CMake
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
SF_CFG_SECOND_UNIT_INSTANCES(extern)
SF_CFG_THIRD_UNIT_INSTANCES(extern)
SF_CFG_JACOBIAN_UNIT_INSTANCES(extern)
#endif

namespace sf_filter {

#if !SF_CFG_IS_AVERAGING && defined(SF_FILTER_SMOOTHERS_UNIT)
// In a node built by sf_add_filter() the smoothers of the header's filter (and what its method
// puts beside them) are compiled in a unit of their own (fusion_node_smoothers.cpp); other
// units of a header (tests, tools) instantiate them where they use them.
SF_FILTER_SMOOTHER_INSTANCES(extern, FusionCore<generated::Filter>)
#endif

namespace generated {

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
                       InputState& state, double now) {
        const Message msg = deserialize<Message>(data, size);
        ReadContext context{sink, state, now, stampOf(msg)};
        std::array<GroupValues, kGroupCount> groups{};
        sf_config::forEachInput([&](auto in) {
          using In = decltype(in);
          if constexpr (In::first_same_topic == Owner::index) readInput<In>(msg, context, groups);
        });
        sendGroups<Owner::index>(msg, groups, context, std::make_index_sequence<kGroupCount>{});
      };
      appendTopicReader(readers, std::move(reader));
    }
  });
  sf_config::forEachControl([&](auto owner) {
    using Owner = decltype(owner);
    if constexpr (Owner::owns_subscription) {
      using Message = typename Owner::Message;
      TopicReader reader = topicReader<Message>(Owner::topic, true);
      reader.read = [](const std::uint8_t* data, std::uint32_t size, MessageSink& sink, InputState&,
                       double) {
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

/// "topic field" per input (its extractor's description); with INPUTS records
/// "name: topic field".
inline std::vector<std::string> inputNames() {
  std::vector<std::string> names;
  sf_config::forEachInput([&](auto in) {
    using In = decltype(in);
    names.push_back(InputOf<In>::Extractor::describe());
    if constexpr (sf_config::kHasInputRecords) {
      names.back() = std::string(sf_config::kInputNames[In::index]) + ": " + names.back();
    }
  });
  return names;
}

/// The private parameters of the extractor kinds the inputs are read by, each once.
inline std::vector<ExtractorParameter> extractorParameters() {
  std::vector<ExtractorParameter> all;
  sf_config::forEachInput([&](auto in) { InputOf<decltype(in)>::Extractor::addParameters(all); });
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
  if constexpr (sf_config::kHasPoseOut3d) {
    const auto& p = sf_config::kPoseOut3d;
    description.pose3d = Pose3dIndices{{p[0], p[1], p[2]}, p[3]};
  }
  if constexpr (sf_config::kHasTwistOut3d) description.twist3d = sf_config::kTwistOut3d;
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
    d.alignedAxis[In::index] = std::string(InputOf<In>::Extractor::kAxisName);
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
