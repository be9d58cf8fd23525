// The estimate's acceleration, published as geometry_msgs/AccelWithCovarianceStamped on
// accel/filtered like robot_localization's (doc/filter_node.md, "Outputs"):
//
//   ACCEL_OUT  (a index): the state variable holding the forward acceleration [m/s^2] in the
//              robot's frame (the child frame, ~child_frame_id)
//
// Generates, in namespace sf_config:
//   constexpr bool kHasAccelOut;
//   inline constexpr int kAccelOut;   // a index, -1 without
//
// The node fills accel.linear.x and its variance from the state; every other component gets
// the variance 1e6, never 0 (estimate_messages.hpp, makeAccel). Published, like the odometry,
// from the first estimate that used a measured value on. Checked at compile time, naming the
// macro: one entry, an integer state index 0 <= i < n.
#pragma once

#include <type_traits>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off
#if defined(ACCEL_OUT)
#if SF_PP_IS_VECTOR(ACCEL_OUT) && BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(ACCEL_OUT), 1)
#define SF_ACCEL_OUT_OK 1
static_assert(std::is_integral<decltype(BOOST_PP_SEQ_ELEM(0, ACCEL_OUT))>::value &&
                  (BOOST_PP_SEQ_ELEM(0, ACCEL_OUT)) >= 0 &&
                  (BOOST_PP_SEQ_ELEM(0, ACCEL_OUT)) < SF_CFG_N,
              "ACCEL_OUT: a index '" SF_PP_STR(BOOST_PP_SEQ_ELEM(0, ACCEL_OUT))
              "' is out of range, expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(SF_CFG_N))
              " (" SF_CFG_N_WHY ")");
#else
#define SF_ACCEL_OUT_OK 0
static_assert(false, "ACCEL_OUT: expected one state index, (a index), e.g. (6) for a forward "
              "acceleration x[6]; found '" SF_PP_STR(ACCEL_OUT) "'");
#endif
#else
#define SF_ACCEL_OUT_OK 0
#endif
// clang-format on

namespace sf_config {

#if SF_ACCEL_OUT_OK
constexpr bool kHasAccelOut = true;
inline constexpr int kAccelOut = static_cast<int>(BOOST_PP_SEQ_ELEM(0, ACCEL_OUT));
#else
constexpr bool kHasAccelOut = false;
inline constexpr int kAccelOut = -1;
#endif

}  // namespace sf_config
