// Compile-time part of the spatial alignment of inputs (doc/spatial_alignment.md). Reads the
// optional configuration macros
//
//   BASE_FRAME            frame the aligned vectors are rotated into, e.g. base_link (a name,
//                         or a string literal "base_link"); default of the ~base_frame parameter
//   FRAME_ALIGNED_INPUTS  ((input index)(vector member)(axis)) per aligned TOPICS_IN entry, e.g.
//                         ((0)(angular_velocity)(z)): the node rotates message.angular_velocity
//                         from message.header.frame_id into the base frame and uses its z
//                         component instead of the entry's field
//
// and generates, in namespace sf_config:
//
//   constexpr bool kHasFrameAlignment;               // FRAME_ALIGNED_INPUTS is given
//   inline constexpr std::string_view kBaseFrame;    // BASE_FRAME ("" without it)
//   template <int I> using FrameAlignment = ...;     // what to do with input I:
//     static constexpr bool aligned;                 //   false: read the field as configured
//     // only if aligned:
//     using Message; static constexpr int input_index, axis (0 x, 1 y, 2 z);
//     static constexpr std::string_view member, axis_name;
//     static std::array<double, 3> vector(const Message&);   // message.<member>.{x, y, z}
//     static constexpr bool valid;                   // false if a check below failed
//
// Checked at compile time, each reported once and naming the macro: BASE_FRAME given with
// FRAME_ALIGNED_INPUTS (#error) and a valid tf2 frame name, the entries' form, input index
// 0 <= index < m and listed once, axis one of x y z, the input's message type has a header
// (header.frame_id, header.stamp) and the member has numeric x, y and z.
//
// ROS-free like configuration.hpp (the config_errors tests compile it with stand-in messages);
// the node's tf2 side is frame_aligner.hpp. Include after the configuration header.
#pragma once

#include <array>
#include <iterator>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/preprocessor/facilities/is_empty.hpp>

#include "sf_filter/config/configuration.hpp"
#include "sf_filter/config/detail/option_entries.hpp"

// clang-format off
#if SF_CONFIG_OK

#if defined(FRAME_ALIGNED_INPUTS) && !defined(BASE_FRAME)
#error FRAME_ALIGNED_INPUTS requires BASE_FRAME: the frame the listed vectors are rotated into, e.g. #define BASE_FRAME base_link
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(BASE_FRAME) && BOOST_PP_IS_EMPTY(BASE_FRAME)
#error BASE_FRAME is defined but empty: expected a tf2 frame name, e.g. #define BASE_FRAME base_link
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(BASE_FRAME) && !defined(FRAME_ALIGNED_INPUTS)
#pragma GCC warning "BASE_FRAME is not used without FRAME_ALIGNED_INPUTS and is ignored"
#endif

#define SF_FA_FORMAT "((input index)(vector member)(axis)), e.g. ((0)(angular_velocity)(z))"

#if defined(FRAME_ALIGNED_INPUTS)
SF_PP_CHECK_LIST("FRAME_ALIGNED_INPUTS", 3, 3, SF_FA_FORMAT, FRAME_ALIGNED_INPUTS)
#endif
#define SF_FA_OK SF_PP_IS_LIST(3, 3, FRAME_ALIGNED_INPUTS)

// Message prefix naming an entry, e.g. "FRAME_ALIGNED_INPUTS entry 0 ((0)(angular_velocity)(w))".
#define SF_FA_PREFIX(k, entry) "FRAME_ALIGNED_INPUTS entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"
#define SF_FA_INDEX(entry) static_cast<int>(BOOST_PP_SEQ_ELEM(0, entry))

// One descriptor per entry: FrameAligned<k>, with a detector of message.<member>.{x, y, z}.
#define SF_FA_ENTRY(r, data, k, entry)                                                          \
  namespace alignment_detail {                                                                 \
  template <class MessageT, class = void>                                                      \
  struct BOOST_PP_CAT(VectorMember, k) {                                                       \
    static constexpr int status = ::sf_config::detail::kFieldMissing;                          \
    static std::array<double, 3> get(const MessageT&) { return {}; }                           \
  };                                                                                           \
  template <class MessageT>                                                                    \
  struct BOOST_PP_CAT(VectorMember, k)<MessageT, std::void_t<                                  \
      decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).x),                 \
      decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).y),                 \
      decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).z)>> {              \
    static constexpr int status = vectorStatusOf<                                              \
        decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).x),               \
        decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).y),               \
        decltype(std::declval<const MessageT&>().BOOST_PP_SEQ_ELEM(1, entry).z)>();            \
    static std::array<double, 3> get(const MessageT& m) {                                      \
      return {::sf_config::detail::toDouble(m.BOOST_PP_SEQ_ELEM(1, entry).x),                  \
              ::sf_config::detail::toDouble(m.BOOST_PP_SEQ_ELEM(1, entry).y),                  \
              ::sf_config::detail::toDouble(m.BOOST_PP_SEQ_ELEM(1, entry).z)};                 \
    }                                                                                          \
  };                                                                                           \
  }                                                                                            \
  struct BOOST_PP_CAT(FrameAligned, k) {                                                       \
    static constexpr bool aligned = true;                                                      \
    static constexpr int input_index = SF_FA_INDEX(entry);                                     \
    using Message = typename ::sf_config::detail::InputMessageOf<input_index>::type;                \
    static constexpr std::string_view member = SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry));         \
    static constexpr std::string_view axis_name = SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry));      \
    static constexpr int axis = alignment_detail::axisIndex(axis_name);                        \
    static std::array<double, 3> vector(const Message& message) {                              \
      return alignment_detail::BOOST_PP_CAT(VectorMember, k)<Message>::get(message);           \
    }                                                                                          \
    /* false: a static_assert below reported a mistake; the node then skips the input's code */ \
    static constexpr bool valid = input_index >= 0 && input_index < kMeasurementSize &&       \
        axis >= 0 && alignment_detail::HasStampedHeader<Message>::value &&                     \
        alignment_detail::BOOST_PP_CAT(VectorMember, k)<Message>::status ==                    \
            ::sf_config::detail::kFieldOk;                                                     \
    static_assert(std::is_integral<decltype(BOOST_PP_SEQ_ELEM(0, entry))>::value &&           \
                      input_index >= 0 && input_index < kMeasurementSize,                      \
                  SF_FA_PREFIX(k, entry) ": input index '" SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  "' is out of range, expected an integer from 0 to "                          \
                  SF_PP_STR(BOOST_PP_DEC(SF_CFG_M)) " (the TOPICS_IN entry to align; "         \
                  SF_CFG_M_WHY ")");                                                           \
    static_assert(alignment_detail::firstEntryOf(input_index) == k,                            \
                  SF_FA_PREFIX(k, entry) ": the input is already listed in an earlier entry; " \
                  "an input is aligned once");                                                 \
    static_assert(axis >= 0, SF_FA_PREFIX(k, entry) ": axis '"                                 \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)) "' is not one of x, y, z (the "       \
                  "component of the rotated vector that replaces the input's field)");        \
    static_assert(::sf_config::detail::isUnknownMessage<Message>() ||                          \
                      alignment_detail::HasStampedHeader<Message>::value,                      \
                  SF_FA_PREFIX(k, entry) ": the message type of TOPICS_IN entry "              \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) " has no header (header.frame_id and " \
                  "header.stamp): only stamped messages say which frame their vectors are in"); \
    static_assert(::sf_config::detail::isUnknownMessage<Message>() ||                          \
                      !alignment_detail::HasStampedHeader<Message>::value ||                   \
                      alignment_detail::BOOST_PP_CAT(VectorMember, k)<Message>::status ==      \
                          ::sf_config::detail::kFieldOk,                                       \
                  SF_FA_PREFIX(k, entry) ": member '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))   \
                  "' of the message type of TOPICS_IN entry " SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  " is not a vector with numeric x, y and z (e.g. angular_velocity of "        \
                  "sensor_msgs::Imu, vector of geometry_msgs::Vector3Stamped)");               \
  };
// clang-format on

namespace sf_config {

/// No alignment: the input's field is read as configured.
struct NotFrameAligned {
  static constexpr bool aligned = false;
};

namespace alignment_detail {

/// 0, 1, 2 for the axis names x, y, z; -1 otherwise.
constexpr int axisIndex(std::string_view name) {
  return name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
}

/// A tf2 frame id: not empty, no leading '/', no quotes or white space.
constexpr bool isValidFrameName(std::string_view s) {
  if (s.empty() || s.front() == '/') return false;
  for (char c : s) {
    if (c == ' ' || c == '\t' || c == '"' || c == '\'') return false;
  }
  return true;
}

template <class X, class Y, class Z>
constexpr int vectorStatusOf() {
  return std::is_convertible_v<const X&, double> && std::is_convertible_v<const Y&, double> &&
                 std::is_convertible_v<const Z&, double>
             ? detail::kFieldOk
             : detail::kFieldNotNumeric;
}

template <class MessageT, class = void>
struct HasStampedHeader : std::false_type {};
template <class MessageT>
struct HasStampedHeader<MessageT,
                        std::void_t<decltype(std::declval<const MessageT&>().header.frame_id),
                                    decltype(std::declval<const MessageT&>().header.stamp)>>
    : std::is_convertible<decltype(std::declval<const MessageT&>().header.frame_id),
                          std::string_view> {};

/// Input index of each FRAME_ALIGNED_INPUTS entry, in order.
SF_OPTION_INDICES(SF_FA_OK, kAlignedIndices, SF_FA_INDEX, FRAME_ALIGNED_INPUTS)

/// The first FRAME_ALIGNED_INPUTS entry that lists `input`, -1 if none does.
constexpr int firstEntryOf(int input) { return detail::entryNaming(kAlignedIndices, input); }

}  // namespace alignment_detail

#if defined(BASE_FRAME)
inline constexpr std::string_view kBaseFrame = detail::unquote(SF_PP_STR(BASE_FRAME));
static_assert(alignment_detail::isValidFrameName(kBaseFrame),
              "BASE_FRAME: '" SF_PP_STR(BASE_FRAME) "' is not a valid tf2 frame name (not empty, "
              "no leading '/', no spaces or quotes inside), e.g. base_link");
#else
inline constexpr std::string_view kBaseFrame = "";
#endif

constexpr bool kHasFrameAlignment = SF_FA_OK;

SF_OPTION_ENTRIES(SF_FA_OK, SF_FA_ENTRY, ~, FRAME_ALIGNED_INPUTS)

/// How input I is read: NotFrameAligned, or its FRAME_ALIGNED_INPUTS descriptor FrameAligned<k>.
template <int I>
using FrameAlignment = SF_OPTION_DESCRIPTOR(SF_FA_OK, FrameAligned, FRAME_ALIGNED_INPUTS,
                                            alignment_detail::firstEntryOf(I), NotFrameAligned);

}  // namespace sf_config

#endif  // SF_CONFIG_OK
