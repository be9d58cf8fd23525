// The 3D pose of the published nav_msgs/Odometry (doc/configuration.md, "Outputs"):
//
//   POSE_OUT_3D   (x index)(y index)(z index)(q index): the position in the odom frame [m] and
//                 the orientation, q the w of a QUATERNION_STATES entry; or (q index) alone
//                 for an orientation-only output (position zero, variance 1e6)
//   TWIST_OUT_3D  (vx)(vy)(vz)(wx)(wy)(wz) indices: the linear [m/s] and angular [rad/s]
//                 velocity in the robot's frame (the Odometry's child frame); requires
//                 POSE_OUT_3D
//
// Generates, in namespace sf_config:
//   constexpr bool kHasPoseOut3d, kHasTwistOut3d;
//   inline constexpr std::array<int, 4> kPoseOut3d;   // {x, y, z, q}, position -1 if absent
//   inline constexpr std::array<int, 6> kTwistOut3d;  // -1 each without
//
// The node publishes the Odometry with the 6x6 pose covariance (the orientation block about the
// odom frame's axes, the quaternion's error) and twist covariance, its pose as the tf
// odom -> base_link, and the Euler angles on fused/euler (io/pose_3d_messages.hpp). Checked at
// compile time, naming the macro: not with POSE_OUT or TWIST_OUT (#error), QUATERNION_STATES
// declared (#error), the number of entries, integer state indices 0 <= i < n, q a
// QUATERNION_STATES entry.
#pragma once

#include <array>
#include <type_traits>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off
#if defined(POSE_OUT_3D) && defined(POSE_OUT)
#error POSE_OUT_3D and POSE_OUT: a node publishes one odometry; keep POSE_OUT_3D for a state with a QUATERNION_STATES orientation, POSE_OUT (x index)(y index)(heading index) for a planar one
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(POSE_OUT_3D) && defined(TWIST_OUT)
#error TWIST_OUT is the planar twist (v, omega) of POSE_OUT; with POSE_OUT_3D declare TWIST_OUT_3D (vx)(vy)(vz)(wx)(wy)(wz)
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(TWIST_OUT_3D) && !defined(POSE_OUT_3D)
#error TWIST_OUT_3D requires POSE_OUT_3D: the twist is published in the nav_msgs/Odometry that POSE_OUT_3D (x index)(y index)(z index)(q index) enables
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(POSE_OUT_3D) && !defined(QUATERNION_STATES)
#error POSE_OUT_3D requires QUATERNION_STATES: its orientation is a unit quaternion of the state (QUATERNION_STATES (i)); a planar pose is POSE_OUT (x index)(y index)(heading index)
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif

#define SF_POSE_OUT_3D_OK 0
#if defined(POSE_OUT_3D) && SF_PP_IS_VECTOR(POSE_OUT_3D)
#if BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(POSE_OUT_3D), 4) || BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(POSE_OUT_3D), 1)
#undef SF_POSE_OUT_3D_OK
#define SF_POSE_OUT_3D_OK 1
#endif
#endif
#if defined(POSE_OUT_3D) && !SF_POSE_OUT_3D_OK
static_assert(false, "POSE_OUT_3D: expected four state indices, (x index)(y index)(z index)"
              "(q index), e.g. (0)(1)(2)(3) for a position x[0..2] and a quaternion x[3..6], or "
              "(q index) alone for the orientation only; found '" SF_PP_STR(POSE_OUT_3D) "'");
#endif

#define SF_TWIST_OUT_3D_OK 0
#if defined(TWIST_OUT_3D) && SF_PP_IS_VECTOR(TWIST_OUT_3D)
#if BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(TWIST_OUT_3D), 6)
#undef SF_TWIST_OUT_3D_OK
#define SF_TWIST_OUT_3D_OK 1
#endif
#endif
#if defined(TWIST_OUT_3D) && !SF_TWIST_OUT_3D_OK
static_assert(false, "TWIST_OUT_3D: expected six state indices, (vx)(vy)(vz)(wx)(wy)(wz), the "
              "linear and angular velocity in the robot's frame; found '" SF_PP_STR(TWIST_OUT_3D)
              "'");
#endif

// Entry k of MACRO: an integer state index 0 <= i < n.
#define SF_OUT_3D_INDEX_CHECK(r, MACRO, k, index)                                                  \
  static_assert(std::is_integral<decltype(index)>::value && (index) >= 0 && (index) < SF_CFG_N,    \
                MACRO ": entry " SF_PP_STR(k) " '" SF_PP_STR(index) "' is not a state " \
                "index, expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(SF_CFG_N))          \
                " (" SF_CFG_N_WHY ")");
// clang-format on

namespace sf_config {

#if SF_POSE_OUT_3D_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_OUT_3D_INDEX_CHECK, "POSE_OUT_3D", POSE_OUT_3D)
#define SF_POSE_OUT_3D_AT(k) static_cast<int>(BOOST_PP_SEQ_ELEM(k, POSE_OUT_3D))
#if BOOST_PP_SEQ_SIZE(POSE_OUT_3D) == 4
inline constexpr std::array<int, 4> kPoseOut3d = {SF_POSE_OUT_3D_AT(0), SF_POSE_OUT_3D_AT(1),
                                                  SF_POSE_OUT_3D_AT(2), SF_POSE_OUT_3D_AT(3)};
#else
inline constexpr std::array<int, 4> kPoseOut3d = {-1, -1, -1, SF_POSE_OUT_3D_AT(0)};
#endif
#if SF_CFG_HAS_QUATERNION_STATES
// Only for a valid state index: a bad one is reported once, by its entry's check.
static_assert(!std::is_integral<decltype(BOOST_PP_SEQ_ELEM(
                      BOOST_PP_DEC(BOOST_PP_SEQ_SIZE(POSE_OUT_3D)), POSE_OUT_3D))>::value ||
                  kPoseOut3d[3] < 0 || kPoseOut3d[3] >= kStateSize ||
                  quaternions_detail::startsQuaternion(kPoseOut3d[3]),
              "POSE_OUT_3D: the q index is not an entry of QUATERNION_STATES (" SF_PP_STR(
                  QUATERNION_STATES) "): the orientation is the w of a declared quaternion");
#endif
constexpr bool kHasPoseOut3d = true;
#else
constexpr bool kHasPoseOut3d = false;
inline constexpr std::array<int, 4> kPoseOut3d = {-1, -1, -1, -1};
#endif

#if SF_TWIST_OUT_3D_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_OUT_3D_INDEX_CHECK, "TWIST_OUT_3D", TWIST_OUT_3D)
#define SF_TWIST_OUT_3D_AT(k) static_cast<int>(BOOST_PP_SEQ_ELEM(k, TWIST_OUT_3D))
constexpr bool kHasTwistOut3d = true;
inline constexpr std::array<int, 6> kTwistOut3d = {SF_TWIST_OUT_3D_AT(0), SF_TWIST_OUT_3D_AT(1),
                                                   SF_TWIST_OUT_3D_AT(2), SF_TWIST_OUT_3D_AT(3),
                                                   SF_TWIST_OUT_3D_AT(4), SF_TWIST_OUT_3D_AT(5)};
#else
constexpr bool kHasTwistOut3d = false;
inline constexpr std::array<int, 6> kTwistOut3d = {-1, -1, -1, -1, -1, -1};
#endif

}  // namespace sf_config
