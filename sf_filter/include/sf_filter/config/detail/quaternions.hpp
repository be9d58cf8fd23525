// Generated rotation declarations (doc/configuration.md, "Rotations in 3D") from the optional
//
//   QUATERNION_STATES (i)(j)...  each index starts a unit quaternion x[i..i+3], stored w, x, y,
//                                z, with three tangent rows (a rotation vector, rad) in
//                                PROCESS_NOISE_COVARIANCE and INITIAL_ERROR_COVARIANCE
//
// into namespace sf_config:
//
//   constexpr bool kHasQuaternionStates;  constexpr int kTangentSize;
//   using StateLayout = estimation::manifold::StateLayout<...>  (with QUATERNION_STATES: an
//     So3WorldBlock per quaternion (the error about the world's axes), an So2Block per
//     ANGLE_STATES entry, VectorBlock<1> otherwise)
//   storedCovariance(tangent): a d x d covariance in the node's n x n form (LayoutEmbedding)
//
// EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER then run on the layout (their traits
// headers). Checked at compile time, each reported once and naming the macro: the sequence
// form, each quaternion inside the state and overlapping no other quaternion and no
// ANGLE_STATES entry; refused (#error) for the methods that cannot hold a rotation.
#pragma once

#include <array>
#include <type_traits>

#include "sf_filter/config/detail/angles.hpp"
#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/quaternion_spans.hpp"

// clang-format off

// --- preprocessing-time errors ------------------------------------------------------------------
#if defined(QUATERNION_STATES) && (SF_CFG_IS_AVERAGING || SF_CFG_IS_LINEAR)
#error QUATERNION_STATES is used by EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER only: KALMAN_FILTER's x' = A x + B u is linear and MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING average linearly, none can keep a unit quaternion; remove QUATERNION_STATES or choose EXTENDED_KALMAN_FILTER or UNSCENTED_KALMAN_FILTER
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(QUATERNION_STATES) && METHOD == PARTICLE_FILTER_SIR
#error QUATERNION_STATES is not supported by PARTICLE_FILTER_SIR yet (its particles and their mean are flat vectors); remove QUATERNION_STATES or choose EXTENDED_KALMAN_FILTER or UNSCENTED_KALMAN_FILTER
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif

// --- form -----------------------------------------------------------------------------------------
#if defined(QUATERNION_STATES) && !SF_PP_IS_VECTOR(QUATERNION_STATES)
static_assert(false, "QUATERNION_STATES: expected a sequence of state indices, each in "
              "parentheses, e.g. (3) for a quaternion x[3..6] stored w, x, y, z; found '"
              SF_PP_STR(QUATERNION_STATES) "'");
#endif

// --- entries: one struct per index, checked -------------------------------------------------------
#define SF_QUATERNION_ENTRY(r, data, k, index)                                                     \
  struct BOOST_PP_CAT(QuaternionEntry, k) {                                                        \
    SF_QUATERNION_START_MEMBERS(QUATERNION_STATES, k, index, SF_CFG_N, "inside the state",      \
                                "the quaternion is x[i..i+3]", SF_CFG_N_WHY)                       \
    static_assert(value < 0 || quaternions_detail::overlappedEntry(value, k) < 0,                  \
                  "QUATERNION_STATES entry " SF_PP_STR(k) ": the quaternion x[" SF_PP_STR(index)   \
                  "..+3] overlaps the quaternion of an earlier entry; each state variable "        \
                  "belongs to one quaternion");                                                    \
    static_assert(value < 0 || !quaternions_detail::overlapsAngleState(value),                     \
                  "QUATERNION_STATES entry " SF_PP_STR(k) ": the quaternion x[" SF_PP_STR(index)   \
                  "..+3] overlaps an ANGLE_STATES entry; a state variable is an angle or part of " \
                  "a quaternion, not both");                                                       \
  };

// clang-format on

#if defined(QUATERNION_STATES)
// Also for a malformed QUATERNION_STATES, so that its one error is the form's.
#include "sf_filter/config/detail/rotation_helpers.hpp"
#endif

#if SF_CFG_HAS_QUATERNION_STATES
#include <sf_estimation/manifold/layout_embedding.hpp>
#include <sf_estimation/manifold/so3_world_block.hpp>

namespace sf_config {
namespace quaternions_detail {

/// Where each entry's quaternion starts, in order (then detail::kNoIndex).
SF_OPTION_INDICES(1, kStarts, SF_ANGLE_INDEX, QUATERNION_STATES)

/// The first of the entries before `entry` whose quaternion shares a state with the one at
/// `start`, or -1.
constexpr int overlappedEntry(int start, int entry) {
  return detail::overlappedQuaternion(kStarts, start, entry);
}

constexpr bool overlapsAngleState(int start) {
  return detail::quaternionHitsFlag(kAngleStates, start);
}

BOOST_PP_SEQ_FOR_EACH_I(SF_QUATERNION_ENTRY, ~, QUATERNION_STATES)

constexpr bool startsQuaternion(int i) {
  for (const int start : kStarts) {
    if (start == i) return true;
  }
  return false;
}

namespace mf = estimation::manifold;

/// The layout of `Size` stored entries from `At` on, appended to Blocks: an So3WorldBlock where
/// Kinds::quaternionAt(i), an So2Block where Kinds::angleAt(i), VectorBlock<1> otherwise (the
/// state's layout here, the measurement's in quaternion_inputs.hpp).
template <class Kinds, int Size, bool Done, int At, class... Blocks>
struct LayoutFrom {
  using type = mf::StateLayout<Blocks...>;
};
template <class Kinds, int Size, int At, class... Blocks>
struct LayoutFrom<Kinds, Size, false, At, Blocks...> {
  // A quaternion past the end is reported by its entry's check; here it is left flat.
  using Block =
      std::conditional_t<Kinds::quaternionAt(At) && At + 4 <= Size, mf::So3WorldBlock,
                         std::conditional_t<Kinds::angleAt(At), mf::So2Block, mf::VectorBlock<1>>>;
  static constexpr int kNext = At + Block::StoredSize;
  using type = typename LayoutFrom<Kinds, Size, (kNext >= Size), kNext, Blocks..., Block>::type;
};

struct StateKinds {
  static constexpr bool quaternionAt(int i) { return startsQuaternion(i); }
  static constexpr bool angleAt(int i) { return kAngleStates[static_cast<std::size_t>(i)]; }
};

}  // namespace quaternions_detail

constexpr bool kHasQuaternionStates = true;
/// The state's blocks: what EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER run on.
using StateLayout =
    quaternions_detail::LayoutFrom<quaternions_detail::StateKinds, kStateSize, false, 0>::type;
constexpr int kTangentSize = StateLayout::TangentSize;

/// A tangent-space covariance (the header's Q or P0) in the n x n form of the node's
/// parameters: the quaternions' three rows on their x, y, z entries, their w rows zero.
inline Eigen::Matrix<double, kStateSize, kStateSize> storedCovariance(
    const Eigen::Matrix<double, kTangentSize, kTangentSize>& tangent) {
  return estimation::manifold::LayoutEmbedding<StateLayout>::toStored(tangent);
}

}  // namespace sf_config
#else
namespace sf_config {
constexpr bool kHasQuaternionStates = false;
constexpr int kTangentSize = kStateSize;
}  // namespace sf_config
#endif
