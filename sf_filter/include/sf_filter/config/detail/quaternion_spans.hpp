// The overlap checks of QUATERNION_STATES (quaternions.hpp) and QUATERNION_INPUTS
// (quaternion_inputs.hpp): each entry's index starts four consecutive entries, x[i..i+3] or
// TOPICS_IN i..i+3, that belong to no other quaternion and are no angle.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include <boost/preprocessor/arithmetic/sub.hpp>

#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off
// The members `configured_index` and `value` of entry k of MACRO, and the check that `index`
// is an integer starting four entries inside `size` (`where`: "inside the state"; `layout`:
// what the four entries are; `why`: where the size comes from).
#define SF_QUATERNION_START_MEMBERS(macro, k, index, size, where, layout, why)                     \
  static constexpr auto configured_index = index;                                                  \
  static constexpr int value = static_cast<int>(configured_index);                                 \
  static_assert(std::is_integral<decltype(configured_index)>::value && configured_index >= 0 &&    \
                    configured_index + 3 < (size),                                                 \
                #macro " entry " SF_PP_STR(k) ": index '" SF_PP_STR(index) "' does not start a "   \
                "quaternion " where ", expected an integer from 0 to "                             \
                SF_PP_STR(BOOST_PP_SUB(size, 4)) " (" layout "; " why ")");
// clang-format on

namespace sf_config {
namespace detail {

/// The first of the entries before `entry` (`starts`: each entry's index, in order) whose four
/// entries share one with those from `start`, or -1.
template <std::size_t K>
constexpr int overlappedQuaternion(const int (&starts)[K], int start, int entry) {
  for (int k = 0; k < entry && k < static_cast<int>(K); ++k) {
    if (starts[k] <= start + 3 && start <= starts[k] + 3) return k;
  }
  return -1;
}

/// Whether one of the four entries from `start` (those inside `flags`) is flagged.
template <std::size_t S>
constexpr bool quaternionHitsFlag(const std::array<bool, S>& flags, int start) {
  for (int i = start; i < start + 4 && i < static_cast<int>(S); ++i) {
    if (i >= 0 && flags[static_cast<std::size_t>(i)]) return true;
  }
  return false;
}

}  // namespace detail
}  // namespace sf_config
