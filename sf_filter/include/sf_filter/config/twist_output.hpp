// The twist of the published nav_msgs/Odometry (doc/configuration.md, "Outputs"):
//
//   TWIST_OUT  (v index)(omega index): the state variables holding the forward speed [m/s]
//              and the yaw rate [rad/s] in the robot's frame (the Odometry's child frame);
//              requires POSE_OUT, which makes the node publish the Odometry
//
// Generates, in namespace sf_config:
//   constexpr bool kHasTwistOut;
//   inline constexpr std::array<int, 2> kTwistOut;   // {v index, omega index}, {-1, -1} without
//
// The node fills twist.twist.linear.x and angular.z and their covariance block from the
// state; the twist components the state does not hold (and all of them without TWIST_OUT) get
// the variance 1e6, never 0 (estimate_messages.hpp). Checked at compile time, naming the
// macro: POSE_OUT defined (#error), two entries, integer state indices 0 <= i < n.
#pragma once

#include <array>
#include <type_traits>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off
#if defined(TWIST_OUT) && !defined(POSE_OUT)
#error TWIST_OUT requires POSE_OUT: the twist is published in the nav_msgs/Odometry that POSE_OUT (x index)(y index)(heading index) enables
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif

#if defined(TWIST_OUT)
#if SF_PP_IS_VECTOR(TWIST_OUT) && BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(TWIST_OUT), 2)
#define SF_TWIST_OUT_OK 1
#else
#define SF_TWIST_OUT_OK 0
static_assert(false, "TWIST_OUT: expected two state indices, (v index)(omega index), e.g. (3)(4) "
              "for a forward speed x[3] and a yaw rate x[4]; found '" SF_PP_STR(TWIST_OUT) "'");
#endif
#else
#define SF_TWIST_OUT_OK 0
#endif

#if SF_TWIST_OUT_OK
#define SF_TWIST_OUT_CHECK(k, WHAT)                                                                \
  static_assert(std::is_integral<decltype(BOOST_PP_SEQ_ELEM(k, TWIST_OUT))>::value &&             \
                    (BOOST_PP_SEQ_ELEM(k, TWIST_OUT)) >= 0 &&                                      \
                    (BOOST_PP_SEQ_ELEM(k, TWIST_OUT)) < SF_CFG_N,                                  \
                "TWIST_OUT: " WHAT " index '" SF_PP_STR(BOOST_PP_SEQ_ELEM(k, TWIST_OUT))           \
                "' is out of range, expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(SF_CFG_N)) \
                " (" SF_CFG_N_WHY ")");
#endif
// clang-format on

namespace sf_config {

#if SF_TWIST_OUT_OK
SF_TWIST_OUT_CHECK(0, "v")
SF_TWIST_OUT_CHECK(1, "omega")
constexpr bool kHasTwistOut = true;
inline constexpr std::array<int, 2> kTwistOut = {static_cast<int>(BOOST_PP_SEQ_ELEM(0, TWIST_OUT)),
                                                 static_cast<int>(BOOST_PP_SEQ_ELEM(1, TWIST_OUT))};
#else
constexpr bool kHasTwistOut = false;
inline constexpr std::array<int, 2> kTwistOut = {-1, -1};
#endif

}  // namespace sf_config
