// The lookup every per-input (and per-state) option macro shares: ANGLE_STATES, ANGLE_INPUTS,
// INPUT_ALIGNMENT, INPUT_GATE, ALIGN_BY_STAMP, INPUT_TIMEOUT, INPUT_RANGE,
// FRAME_ALIGNED_INPUTS, INPUT_COVARIANCE list entries that each name an index; an index is
// configured by the first entry naming it (a later one is reported as listed twice), and its
// descriptor is that entry's, or the option's "not listed" type.
//
// The shape they all share is written once here: an option macro's entries become entry
// structs (each with its checked `input_index` and its `value`), listed by SF_OPTION_ENTRIES,
// and SF_OPTION_VALUES turns them into one value per index.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <tuple>

#include <boost/preprocessor/cat.hpp>
#include <boost/preprocessor/control/if.hpp>
#include <boost/preprocessor/punctuation/comma_if.hpp>
#include <boost/preprocessor/seq/for_each_i.hpp>

// clang-format off
// The entry structs of an option, `ENTRY(r, DATA, k, entry)` for each entry of SEQ when OK (the
// macro is well formed), nothing otherwise (its mistake was reported by its form check).
#define SF_OPTION_ENTRIES(OK, ENTRY, DATA, SEQ) BOOST_PP_IF(OK, BOOST_PP_SEQ_FOR_EACH_I, SF_OPTION_NONE)(ENTRY, DATA, SEQ)
// `inline constexpr int NAME[]`: the index each entry names (INDEX_OF(entry)) when OK, then
// kNoIndex (so that the array is never empty); detail::entryNaming looks an index up in it.
#define SF_OPTION_INDICES(OK, NAME, INDEX_OF, SEQ)                                                 \
  inline constexpr int NAME[] = {BOOST_PP_IF(OK, SF_OPTION_INDEX_LIST, SF_OPTION_NONE)(INDEX_OF, SEQ) ::sf_config::detail::kNoIndex};
#define SF_OPTION_INDEX_LIST(INDEX_OF, SEQ) BOOST_PP_SEQ_FOR_EACH_I(SF_OPTION_INDEX_ITEM, INDEX_OF, SEQ)
#define SF_OPTION_INDEX_ITEM(r, INDEX_OF, k, entry) INDEX_OF(entry),
// std::tuple<PREFIX0, PREFIX1, ...> of an option's entry descriptors; std::tuple<> unless OK.
#define SF_OPTION_TUPLE(OK, PREFIX, SEQ) std::tuple<BOOST_PP_IF(OK, SF_OPTION_NAME_LIST, SF_OPTION_NONE)(PREFIX, SEQ)>
#define SF_OPTION_NAME_LIST(PREFIX, SEQ) BOOST_PP_SEQ_FOR_EACH_I(SF_OPTION_NAME_ITEM, PREFIX, SEQ)
#define SF_OPTION_NAME_ITEM(r, PREFIX, k, entry) BOOST_PP_COMMA_IF(k) BOOST_PP_CAT(PREFIX, k)
// The descriptor PREFIX<POSITION> of an option's entries, UNLISTED for position -1.
#define SF_OPTION_DESCRIPTOR(OK, PREFIX, SEQ, POSITION, UNLISTED) \
  ::sf_config::detail::DescriptorOf<SF_OPTION_TUPLE(OK, PREFIX, SEQ), POSITION, UNLISTED>
// The per-index array of an option of SIZE indices: UNLISTED where no entry (struct PREFIX<k>)
// names the index, the entry's `value` where one does.
#define SF_OPTION_VALUES(T, SIZE, UNLISTED, OK, PREFIX, SEQ)                                       \
  ::sf_config::detail::valuesByIndex<T, SIZE BOOST_PP_IF(OK, SF_OPTION_TYPES, SF_OPTION_NONE)(PREFIX, SEQ)>(UNLISTED)
#define SF_OPTION_TYPES(PREFIX, SEQ) BOOST_PP_SEQ_FOR_EACH_I(SF_OPTION_TYPE, PREFIX, SEQ)
#define SF_OPTION_TYPE(r, PREFIX, k, entry) , BOOST_PP_CAT(PREFIX, k)
#define SF_OPTION_NONE(...)
// clang-format on

namespace sf_config {
namespace detail {

/// The end of every option's index list (no input has this index).
inline constexpr int kNoIndex = std::numeric_limits<int>::min();

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
template <class Entries, int Position, class Unlisted>
using DescriptorOf = typename DescriptorAt<Entries, Position, Unlisted>::type;

/// One value per index: `unlisted`, then each entry's `value` at its `input_index` (an entry
/// whose index was refused, out of range, contributes nothing: its error is already reported).
template <class T, int Size, class... Entries>
constexpr std::array<T, static_cast<std::size_t>(Size)> valuesByIndex(const T& unlisted) {
  std::array<T, static_cast<std::size_t>(Size)> values{};
  for (T& v : values) v = unlisted;
  ((Entries::input_index >= 0 && Entries::input_index < Size
        ? void(values[static_cast<std::size_t>(Entries::input_index)] = Entries::value)
        : void()),
   ...);
  return values;
}

}  // namespace detail
}  // namespace sf_config
