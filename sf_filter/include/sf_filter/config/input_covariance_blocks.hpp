// Covariance blocks from the message (doc/configuration.md, "Covariance from the message"):
//
//   INPUT_COVARIANCE_BLOCK  ((inputs)(covariance array member)(rows)) per group of TOPICS_IN
//                           entries read from one message whose covariances, correlations
//                           included, come from one covariance array of it, e.g.
//                           (((0)(1)(2))(pose.covariance)((0)(1)(5))) for x, y and yaw of a
//                           nav_msgs::Odometry (rows 0, 1, 5 of its 6 x 6 pose covariance)
//
// Input k of a block gets row and column rows[k] of the array (a square n x n matrix, row-major,
// n = sqrt(size)): its variance on the diagonal, its covariances with the block's other inputs
// off it. The node hands the group's values of each message to the fusion core together
// (FusionCoreBase::addMeasurementBlock), which carries the covariances to the filter's R. A
// message whose array is all zero or has -1 first (ROS's "unknown") gives no covariance: every
// value of the group uses the header's R and each fallback is counted, as for INPUT_COVARIANCE.
// Generates, in namespace sf_config:
//
//   struct CovarianceBlock<k> { static constexpr int size, inputs[size], rows[size];
//     template <class Message> static bool read(const Message&, double* out); // false: unknown
//     static constexpr bool valid; };
//   using CovarianceBlocks = std::tuple<...>;  constexpr int blockOf(int input);  // -1: none
//
// Checked at compile time, each reported once and naming the macro: the entries' form, 1 to 6
// inputs, one row per input, input indices in range, each input in one block and read from the
// block's first input's topic, no variance field or INPUT_COVARIANCE entry as well, no
// DIFFERENTIAL derived input nor a GPS input, the member a square array of numbers and the rows
// below n, each listed once.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <boost/preprocessor/seq/enum.hpp>

#include "sf_filter/config/extractors/message_covariance.hpp"
#include "sf_filter/config/input_covariance.hpp"

// clang-format off
#define SF_ICB_FORMAT "((inputs)(covariance array member)(rows)), e.g. " \
  "(((0)(1)(2))(pose.covariance)((0)(1)(5)))"

#if defined(INPUT_COVARIANCE_BLOCK)
SF_PP_CHECK_LIST("INPUT_COVARIANCE_BLOCK", 3, 3, SF_ICB_FORMAT, INPUT_COVARIANCE_BLOCK)
#endif
#define SF_ICB_OK SF_PP_IS_LIST(3, 3, INPUT_COVARIANCE_BLOCK)

#define SF_ICB_PREFIX(k, entry) \
  "INPUT_COVARIANCE_BLOCK entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"
/// The inputs and rows of an entry, as a brace list; a malformed one gives {-1} (reported).
#define SF_ICB_SEQ(seq) BOOST_PP_IIF(SF_PP_IS_VECTOR(seq), SF_ICB_SEQ_I, SF_ICB_SEQ_BAD)(seq)
#define SF_ICB_SEQ_I(seq) {BOOST_PP_SEQ_ENUM(seq)}
#define SF_ICB_SEQ_BAD(seq) {-1}
#define SF_ICB_INPUTS_OP(r, data, k, entry) \
  BOOST_PP_COMMA_IF(k) ::sf_config::covariance_block_detail::Span{ \
      BOOST_PP_CAT(CovarianceBlock, k)::inputs, BOOST_PP_CAT(CovarianceBlock, k)::size}

#define SF_ICB_ENTRY(r, data, k, entry)                                                            \
  namespace covariance_block_detail {                                                              \
  SF_IC_ARRAY_MEMBER(BOOST_PP_CAT(BlockMember, k), BOOST_PP_SEQ_ELEM(1, entry))                    \
  }                                                                                                \
  struct BOOST_PP_CAT(CovarianceBlock, k) {                                                        \
    static constexpr int inputs[] = SF_ICB_SEQ(BOOST_PP_SEQ_ELEM(0, entry));                       \
    static constexpr int rows[] = SF_ICB_SEQ(BOOST_PP_SEQ_ELEM(2, entry));                         \
    static constexpr int size = static_cast<int>(std::size(inputs));                               \
    static constexpr int first = inputs[0] >= 0 && inputs[0] < kMeasurementSize ? inputs[0] : 0;  \
    using Message = typename ::sf_config::detail::InputMessageOf<first>::type;                     \
    using Member = covariance_block_detail::BOOST_PP_CAT(BlockMember, k)<Message>;                 \
    static constexpr bool unknown = ::sf_config::detail::isUnknownMessage<Message>();              \
    static constexpr long dimension = covariance_block_detail::squareRoot(Member::size);           \
    static constexpr bool inputsOk = covariance_block_detail::inputsOk(inputs, k);                 \
    static constexpr bool sizeOk =                                                                 \
        size >= 1 && size <= 6 && size == static_cast<int>(std::size(rows));                       \
    static constexpr bool rowsOk =                                                                 \
        covariance_block_detail::rowsOk(rows, Member::size < 0 ? 6 : dimension);                   \
    static constexpr bool valid = SF_PP_IS_VECTOR(BOOST_PP_SEQ_ELEM(0, entry)) &&                  \
        SF_PP_IS_VECTOR(BOOST_PP_SEQ_ELEM(2, entry)) && sizeOk && inputsOk &&                      \
        !unknown && Member::ok && dimension > 0 && rowsOk;                                         \
    template <class M>                                                                             \
    static bool read(const M& message, double* out) {                                              \
      const auto& a = covariance_block_detail::BOOST_PP_CAT(BlockMember, k)<M>::array(message);    \
      if (::sf_config::extractors::covarianceUnknown(a)) return false;                             \
      for (int row = 0; row < size; ++row) {                                                       \
        for (int col = 0; col < size; ++col) {                                                     \
          out[row * size + col] = static_cast<double>(                                             \
              a[static_cast<std::size_t>(rows[row] * dimension + rows[col])]);                     \
        }                                                                                          \
      }                                                                                            \
      return true;                                                                                 \
    }                                                                                              \
    static_assert(SF_PP_IS_VECTOR(BOOST_PP_SEQ_ELEM(0, entry)) &&                                  \
                      SF_PP_IS_VECTOR(BOOST_PP_SEQ_ELEM(2, entry)),                                \
                  SF_ICB_PREFIX(k, entry) ": the inputs and the rows are each a sequence of "      \
                  "integers, e.g. ((0)(1)(2)), expected " SF_ICB_FORMAT);                          \
    static_assert(sizeOk,                                                                          \
                  SF_ICB_PREFIX(k, entry) ": expected 1 to 6 inputs and one row of the message's " \
                  "covariance per input");                                                         \
    static_assert(inputsOk, SF_ICB_PREFIX(k, entry) ": " SF_ICB_INPUTS_RULE);                         \
    static_assert(!covariance_block_detail::hasGpsInput(inputs),                                   \
                  SF_ICB_PREFIX(k, entry) ": a GPS input (DERIVED_INPUTS EAST, NORTH, UP) takes "  \
                  "its covariances from the fix's position_covariance, turned into the odom "      \
                  "frame; remove it from the block");                                              \
    static_assert(unknown || Member::ok,                                                           \
                  SF_ICB_PREFIX(k, entry) ": member '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))      \
                  "' of the message type of the block's inputs is not an array of numbers (e.g. " \
                  "pose.covariance of nav_msgs::Odometry, orientation_covariance of "              \
                  "sensor_msgs::Imu)");                                                            \
    static_assert(unknown || !Member::ok || !sizeOk || (dimension > 0 && rowsOk),                  \
                  SF_ICB_PREFIX(k, entry) ": the array is not a square matrix or a row is not "   \
                  "an integer below its size n (rows 0 to 5 of a 6 x 6 covariance: x y z roll "    \
                  "pitch yaw; 0 to 2 of a 3 x 3 one: roll pitch yaw), or a row is listed twice");  \
  };
#define SF_ICB_INPUTS_RULE                                                                            \
  "every input must be a TOPICS_IN index (0 to m - 1) read from the same topic as the block's "    \
  "first, listed once in one block, without a variance field or INPUT_COVARIANCE entry and "       \
  "not a DIFFERENTIAL derived input (a difference has the variance of two messages)"
// clang-format on

namespace sf_config {
namespace covariance_block_detail {

/// n with n * n = size, 0 if there is none (or the size is unknown).
constexpr long squareRoot(long size) {
  for (long n = 1; n * n <= size; ++n) {
    if (n * n == size) return n;
  }
  return 0;
}

template <std::size_t K>
constexpr bool rowsOk(const int (&rows)[K], long dimension) {
  for (std::size_t a = 0; a < K; ++a) {
    if (rows[a] < 0 || rows[a] >= dimension) return false;
    for (std::size_t b = 0; b < a; ++b) {
      if (rows[a] == rows[b]) return false;
    }
  }
  return true;
}

/// The inputs of a block as seen by the other blocks' checks.
struct Span {
  const int* inputs;
  int size;
};

template <std::size_t... I>
constexpr bool hasVarianceFieldOf(int input, std::index_sequence<I...>) {
  return ((static_cast<int>(I) == input && std::tuple_element_t<I, Inputs>::has_variance) || ...);
}
template <std::size_t... I>
constexpr int firstSameTopicOf(int input, std::index_sequence<I...>) {
  int first = -1;
  ((static_cast<int>(I) == input ? (first = std::tuple_element_t<I, Inputs>::first_same_topic) : 0),
   ...);
  return first;
}
template <std::size_t... I>
constexpr bool differentialOf(int input, std::index_sequence<I...>) {
  return ((static_cast<int>(I) == input && Derivation<static_cast<int>(I)>::differential) || ...);
}

template <std::size_t K>
constexpr bool hasGpsInput(const int (&inputs)[K]) {
  for (std::size_t a = 0; a < K; ++a) {
    if (derived_detail::isDerivedGps(inputs[a])) return true;
  }
  return false;
}

/// Checks the inputs of block `block` alone (earlier blocks are checked against it by
/// blockOf's uniqueness below).
template <std::size_t K>
constexpr bool inputsOk(const int (&inputs)[K], int /*block*/) {
  constexpr auto all = std::make_index_sequence<kMeasurementSize>{};
  for (std::size_t a = 0; a < K; ++a) {
    const int i = inputs[a];
    if (i < 0 || i >= kMeasurementSize) return false;
    if (hasVarianceFieldOf(i, all) || covariance_detail::firstEntryOf(i) >= 0) return false;
    if (differentialOf(i, all)) return false;
    if (firstSameTopicOf(i, all) != firstSameTopicOf(inputs[0], all)) return false;
    for (std::size_t b = 0; b < a; ++b) {
      if (inputs[b] == i) return false;
    }
  }
  return true;
}

}  // namespace covariance_block_detail

#if SF_ICB_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_ICB_ENTRY, ~, INPUT_COVARIANCE_BLOCK)
namespace covariance_block_detail {
inline constexpr Span kBlocks[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_ICB_INPUTS_OP, ~, INPUT_COVARIANCE_BLOCK)};
}  // namespace covariance_block_detail
#endif
using CovarianceBlocks = SF_OPTION_TUPLE(SF_ICB_OK, CovarianceBlock, INPUT_COVARIANCE_BLOCK);

/// The INPUT_COVARIANCE_BLOCK entry input `input` belongs to, -1 if none.
constexpr int blockOf([[maybe_unused]] int input) {
#if SF_ICB_OK
  for (int k = 0; k < static_cast<int>(std::size(covariance_block_detail::kBlocks)); ++k) {
    const covariance_block_detail::Span& s = covariance_block_detail::kBlocks[k];
    for (int a = 0; a < s.size; ++a) {
      if (s.inputs[a] == input) return k;
    }
  }
#endif
  return -1;
}

#if SF_ICB_OK
namespace covariance_block_detail {
/// Each input is in one block only.
constexpr bool inputsInOneBlock() {
  for (int k = 0; k < static_cast<int>(std::size(kBlocks)); ++k) {
    for (int a = 0; a < kBlocks[k].size; ++a) {
      if (blockOf(kBlocks[k].inputs[a]) != k) return false;
    }
  }
  return true;
}
static_assert(inputsInOneBlock(),
              "INPUT_COVARIANCE_BLOCK: an input is listed in two entries; list it in one");
}  // namespace covariance_block_detail
#endif

}  // namespace sf_config
