// The lookup every per-input (and per-state) option macro shares: ANGLE_STATES, ANGLE_INPUTS,
// INPUT_ALIGNMENT, INPUT_GATE, ALIGN_BY_STAMP, INPUT_TIMEOUT, INPUT_RANGE,
// FRAME_ALIGNED_INPUTS, INPUT_COVARIANCE list entries that each name an index; an index is
// configured by the first entry naming it (a later one is reported as listed twice), and its
// descriptor is that entry's, or the option's "not listed" type.
#pragma once

#include <cstddef>
#include <tuple>

namespace sf_config {
namespace detail {

/// Position of the first of `listed` (the index each entry names, in order) equal to `index`,
/// -1 if no entry names it.
template <std::size_t K>
constexpr int entryNaming(const int (&listed)[K], int index) {
  for (std::size_t k = 0; k < K; ++k) {
    if (listed[k] == index) return static_cast<int>(k);
  }
  return -1;
}

/// The descriptor at `Position` of `Entries` (a std::tuple of an option's entry descriptors),
/// `Unlisted` for position -1.
template <class Entries, int Position, class Unlisted>
struct DescriptorAt {
  using type = std::tuple_element_t<Position, Entries>;
};
template <class Entries, class Unlisted>
struct DescriptorAt<Entries, -1, Unlisted> {
  using type = Unlisted;
};

}  // namespace detail
}  // namespace sf_config
