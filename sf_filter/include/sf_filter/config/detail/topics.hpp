// Generated descriptors of the node's inputs (TOPICS_IN), controls (TOPICS_IN_CTRL) and outputs
// (TOPICS_OUT), with the checks that need C++: the message type has the field, the field is a
// number, topic names are valid, one topic has one message type, output indices are in range.
// See configuration.hpp for the API.
#pragma once

#include <limits>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/preprocessor/repetition/enum_params.hpp>
#include <boost/preprocessor/repetition/repeat.hpp>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/derived_inputs.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/support.hpp"

// clang-format off

// --- field detectors: DETECTOR<MessageT>::status (a FieldStatus) and ::get(message) -----------
#define SF_CFG_FIELD_DETECTOR(DETECTOR, FIELD)                                                     \
  template <class MessageT, class = void>                                                          \
  struct DETECTOR {                                                                                \
    static constexpr int status = ::sf_config::detail::kFieldMissing;                              \
    using type = ::sf_config::detail::UnknownMessage;                                              \
    static double get(const MessageT&) { return 0.0; }                                             \
    static type member(const MessageT&) { return {}; }                                             \
  };                                                                                               \
  template <class MessageT>                                                                        \
  struct DETECTOR<MessageT, std::void_t<decltype(std::declval<const MessageT&>().FIELD)>> {        \
    static constexpr int status =                                                                  \
        ::sf_config::detail::fieldStatusOf<decltype(std::declval<const MessageT&>().FIELD)>();     \
    using type = std::decay_t<decltype(std::declval<const MessageT&>().FIELD)>;                    \
    static double get(const MessageT& message) {                                                   \
      return ::sf_config::detail::toDouble(message.FIELD);                                         \
    }                                                                                              \
    static const type& member(const MessageT& message) { return message.FIELD; }                   \
  };

#define SF_CFG_TOPIC_NAME(entry) \
  ::sf_config::detail::unquote(SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)))
#define SF_CFG_TOPIC_NAME_OP(r, data, i, entry) BOOST_PP_COMMA_IF(i) SF_CFG_TOPIC_NAME(entry)

// Message prefix naming an entry, e.g. "TOPICS_IN entry 0 (topic 'acceleration')".
#define SF_CFG_ENTRY_PREFIX(LIST, i, entry)                                                        \
  LIST " entry " SF_PP_STR(i) " (topic '" SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) "')"

// DERIVED is a constant expression, true when the field is a member a value is derived from
// (DERIVED_INPUTS): it must exist but need not be a number.
#define SF_CFG_FIELD_CHECKS(LIST, i, entry, DETECTOR, WHAT, FIELD, DERIVED)                        \
  static_assert(::sf_config::detail::isUnknownMessage<Message>() ||                                \
                    DETECTOR<Message>::status != ::sf_config::detail::kFieldMissing,               \
                SF_CFG_ENTRY_PREFIX(LIST, i, entry) ": message type '"                             \
                SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) "' has no " WHAT " '" SF_PP_STR(FIELD)      \
                "' (check the spelling against the message definition, e.g. with rosmsg show)");   \
  static_assert(::sf_config::detail::isUnknownMessage<Message>() || (DERIVED) ||                   \
                    DETECTOR<Message>::status != ::sf_config::detail::kFieldNotNumeric,            \
                SF_CFG_ENTRY_PREFIX(LIST, i, entry) ": " WHAT " '" SF_PP_STR(FIELD)                \
                "' of message type '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))                       \
                "' is not a number (not convertible to double); select a numeric member, "         \
                "e.g. vector.x instead of vector, or derive a number from it with DERIVED_INPUTS");

#define SF_CFG_TOPIC_NAME_CHECK(LIST, i, entry, NAME)                                              \
  static_assert(::sf_config::detail::isValidTopicName(NAME),                                       \
                SF_CFG_ENTRY_PREFIX(LIST, i, entry) ": not a valid ROS topic name (letters, "      \
                "digits, '_' and '/', starting with a letter, '/' or '~'); write names that "      \
                "are not C++ tokens as a string literal, e.g. (\"my_topic\")");

// What an input and a control descriptor both hold: the message type, the entry's index, the
// topic, and the type and field as written.
#define SF_CFG_DESCRIPTOR_MEMBERS(i, entry)                                                        \
  using Message = BOOST_PP_SEQ_ELEM(1, entry);                                                     \
  static constexpr int index = i;                                                                  \
  static constexpr std::string_view topic = SF_CFG_TOPIC_NAME(entry);                              \
  static constexpr std::string_view message_type = SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry));         \
  static constexpr std::string_view field = SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry));

// --- TOPICS_IN ----------------------------------------------------------------------------------
#define SF_CFG_INPUT(r, data, i, entry)                                                            \
  namespace detail {                                                                               \
  SF_CFG_FIELD_DETECTOR(BOOST_PP_CAT(InputValueField, i), BOOST_PP_SEQ_ELEM(2, entry))             \
  BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 4), SF_CFG_FIELD_DETECTOR,                 \
               SF_PP_NOTHING)(BOOST_PP_CAT(InputVarianceField, i),                                 \
                              BOOST_PP_SEQ_ELEM(BOOST_PP_DEC(BOOST_PP_SEQ_SIZE(entry)), entry))    \
  }                                                                                                \
  struct BOOST_PP_CAT(Input, i) : ::sf_config::detail::DescriptorBase {                            \
    SF_CFG_DESCRIPTOR_MEMBERS(i, entry)                                                            \
    static constexpr bool has_variance = BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 4);              \
    static constexpr std::string_view variance_field =                                             \
        BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 4), SF_PP_STR, "" SF_PP_NOTHING)(    \
            BOOST_PP_SEQ_ELEM(BOOST_PP_DEC(BOOST_PP_SEQ_SIZE(entry)), entry));                     \
    static constexpr int first_same_topic = ::sf_config::detail::firstIndexOf(kInputTopics, i);    \
    static constexpr bool owns_subscription = first_same_topic == index;                           \
    static double value(const Message& message) {                                                  \
      return detail::BOOST_PP_CAT(InputValueField, i)<Message>::get(message);                      \
    }                                                                                              \
    /* the field itself (UnknownMessage if missing): what DERIVED_INPUTS derive a value from */  \
    using Field = typename detail::BOOST_PP_CAT(InputValueField, i)<Message>::type;                \
    static decltype(auto) member(const Message& message) {                                         \
      return detail::BOOST_PP_CAT(InputValueField, i)<Message>::member(message);                   \
    }                                                                                              \
    static double variance(const Message& message) {                                               \
      BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 4), SF_CFG_INPUT_VARIANCE_GET,         \
                   SF_CFG_INPUT_VARIANCE_NONE)(i)                                                  \
    }                                                                                              \
    SF_CFG_TOPIC_NAME_CHECK("TOPICS_IN", i, entry, topic)                                          \
    SF_CFG_FIELD_CHECKS("TOPICS_IN", i, entry, detail::BOOST_PP_CAT(InputValueField, i),           \
                        "field", BOOST_PP_SEQ_ELEM(2, entry),                                      \
                        ::sf_config::derived_detail::fieldMayBeMember(i))                             \
    BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 4), SF_CFG_FIELD_CHECKS,                 \
                 SF_PP_NOTHING)("TOPICS_IN", i, entry,                                            \
                                detail::BOOST_PP_CAT(InputVarianceField, i),                      \
                                "variance field",                                                  \
                                BOOST_PP_SEQ_ELEM(BOOST_PP_DEC(BOOST_PP_SEQ_SIZE(entry)), entry),  \
                                false)                                                             \
  };
#define SF_CFG_INPUT_VARIANCE_GET(i)                                                               \
  return detail::BOOST_PP_CAT(InputVarianceField, i)<Message>::get(message);
#define SF_CFG_INPUT_VARIANCE_NONE(i)                                                              \
  static_cast<void>(message);                                                                      \
  return std::numeric_limits<double>::quiet_NaN();

#define SF_CFG_SAME_TOPIC_SAME_TYPE(r, LIST, i, entry)                                             \
  static_assert(::sf_config::detail::isUnknownMessage<BOOST_PP_CAT(LIST, i)::Message>() ||         \
                    ::sf_config::detail::isUnknownMessage<std::tuple_element_t<                    \
                        BOOST_PP_CAT(LIST, i)::first_same_topic,                                 \
                        BOOST_PP_CAT(LIST, s)>::Message>() ||                                    \
                    std::is_same<BOOST_PP_CAT(LIST, i)::Message,                                   \
                             std::tuple_element_t<BOOST_PP_CAT(LIST, i)::first_same_topic,         \
                                                  BOOST_PP_CAT(LIST, s)>::Message>::value,         \
                SF_CFG_ENTRY_PREFIX(BOOST_PP_CAT(SF_CFG_LIST_NAME_, LIST), i, entry)               \
                ": the topic is listed in an earlier entry with a different message type; "        \
                "one topic has one message type");
#define SF_CFG_LIST_NAME_Input "TOPICS_IN"
#define SF_CFG_LIST_NAME_Control "TOPICS_IN_CTRL"


// --- TOPICS_IN_CTRL -----------------------------------------------------------------------------
#define SF_CFG_CONTROL(r, data, i, entry)                                                          \
  namespace detail {                                                                               \
  SF_CFG_FIELD_DETECTOR(BOOST_PP_CAT(ControlValueField, i), BOOST_PP_SEQ_ELEM(2, entry))           \
  }                                                                                                \
  struct BOOST_PP_CAT(Control, i) : ::sf_config::detail::DescriptorBase {                          \
    SF_CFG_DESCRIPTOR_MEMBERS(i, entry)                                                            \
    static constexpr int first_same_topic =                                                        \
        ::sf_config::detail::firstIndexOf(kControlTopics, i);                                      \
    static constexpr bool owns_subscription = first_same_topic == index;                           \
    static double value(const Message& message) {                                                  \
      return detail::BOOST_PP_CAT(ControlValueField, i)<Message>::get(message);                    \
    }                                                                                              \
    SF_CFG_TOPIC_NAME_CHECK("TOPICS_IN_CTRL", i, entry, topic)                                     \
    SF_CFG_FIELD_CHECKS("TOPICS_IN_CTRL", i, entry, detail::BOOST_PP_CAT(ControlValueField, i),    \
                        "field", BOOST_PP_SEQ_ELEM(2, entry), false)                               \
  };

// --- TOPICS_OUT ---------------------------------------------------------------------------------
#define SF_CFG_OUTPUT(r, data, i, entry)                                                           \
  struct BOOST_PP_CAT(Output, i) : ::sf_config::detail::OutputDescriptorBase {                     \
    static constexpr auto configured_state_index = BOOST_PP_SEQ_ELEM(1, entry);                    \
    static constexpr int index = i;                                                                \
    static constexpr std::string_view topic = SF_CFG_TOPIC_NAME(entry);                            \
    static constexpr int state_index = static_cast<int>(configured_state_index);                   \
    SF_CFG_TOPIC_NAME_CHECK("TOPICS_OUT", i, entry, topic)                                         \
    static_assert(::sf_config::detail::firstIndexOf(kOutputTopics, i) == i,                        \
                  SF_CFG_ENTRY_PREFIX("TOPICS_OUT", i, entry)                                      \
                  ": the topic is already used by an earlier TOPICS_OUT entry");                   \
    static_assert(std::is_integral<decltype(configured_state_index)>::value &&                     \
                      configured_state_index >= 0 && configured_state_index < kStateSize,          \
                  SF_CFG_ENTRY_PREFIX("TOPICS_OUT", i, entry) ": state index '"                    \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) "' is out of range, expected an "         \
                  "integer from 0 to " SF_PP_STR(BOOST_PP_DEC(SF_CFG_N)) " (" SF_CFG_N_WHY ")");   \
  };

// clang-format on

namespace sf_config {

// ----------------------------------------------------------------------------- measurement inputs
/// Topic names of the TOPICS_IN entries, in order (quotes of string-literal names removed).
inline constexpr std::string_view kInputTopics[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_TOPIC_NAME_OP, ~, TOPICS_IN)};

BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_INPUT, ~, TOPICS_IN)

/// The input descriptors Input0 .. Input<m-1> as a type list.
using Inputs = std::tuple<BOOST_PP_ENUM_PARAMS(SF_CFG_M, Input)>;

BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_SAME_TOPIC_SAME_TYPE, Input, TOPICS_IN)

namespace detail {
/// The message type of input I; UnknownMessage (no checks) when I is out of range, so that an
/// index mistake is reported once, by the check of the index.
template <int I, bool InRange = (I >= 0 && I < kMeasurementSize)>
struct InputMessageOf {
  using type = UnknownMessage;
};
template <int I>
struct InputMessageOf<I, true> {
  using type = typename std::tuple_element_t<I, Inputs>::Message;
};
}  // namespace detail

// --------------------------------------------------------------------------------- control inputs
#if SF_CFG_L > 0
/// Topic names of the TOPICS_IN_CTRL entries, in order.
inline constexpr std::string_view kControlTopics[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_TOPIC_NAME_OP, ~, TOPICS_IN_CTRL)};

BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_CONTROL, ~, TOPICS_IN_CTRL)

/// The control descriptors Control0 .. Control<l-1> as a type list.
using Controls = std::tuple<BOOST_PP_ENUM_PARAMS(SF_CFG_L, Control)>;

BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_SAME_TOPIC_SAME_TYPE, Control, TOPICS_IN_CTRL)
#else
using Controls = std::tuple<>;
#endif

// ---------------------------------------------------------------------------------------- outputs
/// Topic names of the TOPICS_OUT entries, in order.
inline constexpr std::string_view kOutputTopics[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_TOPIC_NAME_OP, ~, TOPICS_OUT)};

BOOST_PP_SEQ_FOR_EACH_I(SF_CFG_OUTPUT, ~, TOPICS_OUT)

/// Number of TOPICS_OUT entries.
constexpr int kOutputCount = BOOST_PP_SEQ_SIZE(TOPICS_OUT);

/// The output descriptors Output0 .. Output<k-1> as a type list.
using Outputs = std::tuple<BOOST_PP_ENUM_PARAMS(BOOST_PP_SEQ_SIZE(TOPICS_OUT), Output)>;

namespace detail {
/// Calls visitor(D{}) for each descriptor type D of the tuple, in order.
template <class Descriptors, class Visitor, std::size_t... I>
void visitEach([[maybe_unused]] Visitor& visitor, std::index_sequence<I...>) {
  (visitor(std::tuple_element_t<I, Descriptors>{}), ...);
}
template <class Descriptors, class Visitor>
void visitEach(Visitor& visitor) {
  visitEach<Descriptors>(visitor, std::make_index_sequence<std::tuple_size_v<Descriptors>>{});
}
}  // namespace detail

/// Calls visitor(Input0{}), visitor(Input1{}), ... in TOPICS_IN order.
template <class Visitor>
void forEachInput(Visitor&& visitor) {
  detail::visitEach<Inputs>(visitor);
}
/// Calls visitor(Control0{}), ... in TOPICS_IN_CTRL order (never without controls).
template <class Visitor>
void forEachControl(Visitor&& visitor) {
  detail::visitEach<Controls>(visitor);
}
/// Calls visitor(Output0{}), visitor(Output1{}), ... in TOPICS_OUT order.
template <class Visitor>
void forEachOutput(Visitor&& visitor) {
  detail::visitEach<Outputs>(visitor);
}

}  // namespace sf_config
