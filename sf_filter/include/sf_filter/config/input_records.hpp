// INPUTS: one record per measurement input, carrying that input's own options, translated into
// the thesis's index-addressed macros (TOPICS_IN, OBSERVATION_MODEL, MEASUREMENT_NOISE_COVARIANCE,
// INPUT_GATE, ...) before anything else reads them, so the generated tables are exactly those of
// the equivalent thesis-syntax header (doc/configuration.md, "One record per input").
//
//   #define INPUTS
//     ((odom_speed)(odom)(nav_msgs::Odometry)(twist.twist.linear.x)
//        (observe, x[3])(variance, 2.5e-5)(by_stamp)(timeout, 500))
//     ((gyro_z)(imu/data)(sensor_msgs::Imu)(angular_velocity.z)
//        (observe, x[4] + x[5])(variance, 1.25e-5)(frame_aligned, angular_velocity, z))
//
// A record is (name)(topic)(type)(field) followed by options, each (option, arguments...):
//   option            arguments            generates (record i)
//   observe           expression           OBSERVATION_MODEL entry i
//   observation_row   (h0)(h1)...(h<n-1>)  OBSERVATION_MATRIX row i (KALMAN_FILTER)
//   jacobian_row      (d0)(d1)...          OBSERVATION_JACOBIAN row i
//   variance          R_ii                 MEASUREMENT_NOISE_COVARIANCE: diagonal entry i
//   variance_field    member               TOPICS_IN entry i's variance field
//   alignment         POLICY, ...          INPUT_ALIGNMENT ((i)(POLICY)...)
//   gate              threshold            INPUT_GATE ((i)(threshold))
//   timeout           ms                   INPUT_TIMEOUT ((i)(ms))
//   range             minimum, maximum     INPUT_RANGE ((i)(minimum)(maximum))
//   by_stamp          -                    ALIGN_BY_STAMP (i)
//   angle             -                    ANGLE_INPUTS (i)
//   frame_aligned     member, axis         FRAME_ALIGNED_INPUTS ((i)(member)(axis))
//   derived           quantity, mode       DERIVED_INPUTS ((i)(quantity)(mode))
//   covariance        member, entry        INPUT_COVARIANCE ((i)(member)(entry))
//   covariance_block  block, member, row   INPUT_COVARIANCE_BLOCK entry of the records with
//                                          this block number (0 to 3), in record order:
//                                          ((i j ...)(member)(row_i row_j ...))
// Record i is input i (the order of INPUTS is the measurement order). The name is the input's
// name in diagnostics, logs and the ~input_* parameters (a C++ identifier, unique).
//
// Checked here (static_assert, message starting with "INPUTS"): the record's form, unknown
// options, an option's argument count, an option given twice, a name used twice or not an
// identifier, and observe / observation_row / jacobian_row / variance on some records but not
// on others, or missing where METHOD requires them, a covariance_block's block number outside
// 0 to 3 or its member other than the block's first record's. A header defining INPUTS and one
// of the macros it generates fails with an #error naming both (INPUT_COVARIANCE_BLOCK only when
// a record gives covariance_block: without, the index-addressed blocks still apply). Mistakes
// in an option's value (a negative gate, an unknown policy) are reported by the checks of the
// generated macro, e.g. "INPUT_GATE entry 1", counting the entries of that macro from 0.
#pragma once

#if defined(INPUTS)

#include <boost/preprocessor/arithmetic/add.hpp>
#include <boost/preprocessor/control/expr_iif.hpp>
#include <boost/preprocessor/control/if.hpp>
#include <boost/preprocessor/facilities/is_empty.hpp>
#include <boost/preprocessor/logical/bitor.hpp>
#include <boost/preprocessor/logical/not.hpp>
#include <boost/preprocessor/punctuation/remove_parens.hpp>
#include <boost/preprocessor/repetition/repeat.hpp>
#include <boost/preprocessor/seq/seq.hpp>
#include <boost/preprocessor/seq/fold_left.hpp>
#include <boost/preprocessor/seq/for_each.hpp>
#include <boost/preprocessor/seq/rest_n.hpp>
#include <boost/preprocessor/seq/for_each_i.hpp>
#include <boost/preprocessor/tuple/pop_front.hpp>
#include <boost/preprocessor/tuple/to_seq.hpp>

#include "sf_filter/config/detail/input_record_checks.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/diagonal.hpp"
#include "sf_filter/config/methods.hpp"

// clang-format off

// ---------------------------------------------------------------------------------------------
// One syntax or the other
// ---------------------------------------------------------------------------------------------
#if defined(TOPICS_IN)
#error INPUTS and TOPICS_IN are both defined: a header gives its inputs either as INPUTS records (name, topic, type, field and options on one entry) or in the index-addressed macros, not both
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif defined(OBSERVATION_MODEL) || defined(OBSERVATION_MATRIX) || defined(OBSERVATION_JACOBIAN)
#error INPUTS cannot be combined with OBSERVATION_MODEL, OBSERVATION_MATRIX or OBSERVATION_JACOBIAN: give each input observation on its record, (observe, expression) or (observation_row, (h0)(h1)...)
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif defined(MEASUREMENT_NOISE_COVARIANCE)
#error INPUTS cannot be combined with MEASUREMENT_NOISE_COVARIANCE: give each input variance on its record, (variance, R_ii)
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif defined(INPUT_ALIGNMENT) || defined(INPUT_GATE) || defined(INPUT_TIMEOUT) || defined(INPUT_RANGE) || defined(ALIGN_BY_STAMP)
#error INPUTS cannot be combined with INPUT_ALIGNMENT, INPUT_GATE, INPUT_TIMEOUT, INPUT_RANGE or ALIGN_BY_STAMP: give them on the records, (alignment, ...) (gate, threshold) (timeout, ms) (range, minimum, maximum) (by_stamp)
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif defined(ANGLE_INPUTS) || defined(FRAME_ALIGNED_INPUTS) || defined(DERIVED_INPUTS) || defined(INPUT_COVARIANCE)
#error INPUTS cannot be combined with ANGLE_INPUTS, FRAME_ALIGNED_INPUTS, DERIVED_INPUTS or INPUT_COVARIANCE: give them on the records, (angle) (frame_aligned, member, axis) (derived, quantity, mode) (covariance, member, entry)
#define SF_CFG_FATAL
#define SF_CFG_STOP
#else

// ---------------------------------------------------------------------------------------------
// Options: SF_INPUTS_OPTION_<name> is (id, minimum size, maximum size, "form") of the option's
// tuple, the name included.
// ---------------------------------------------------------------------------------------------
#define SF_INPUTS_OPTION_observe (1, 2, 2, "(observe, expression)")
#define SF_INPUTS_OPTION_observation_row (2, 2, 2, "(observation_row, (h0)(h1)...)")
#define SF_INPUTS_OPTION_jacobian_row (3, 2, 2, "(jacobian_row, (d0)(d1)...)")
#define SF_INPUTS_OPTION_variance (4, 2, 2, "(variance, R_ii)")
#define SF_INPUTS_OPTION_variance_field (5, 2, 2, "(variance_field, member)")
#define SF_INPUTS_OPTION_alignment (6, 2, 6, "(alignment, POLICY[, arguments])")
#define SF_INPUTS_OPTION_gate (7, 2, 2, "(gate, threshold)")
#define SF_INPUTS_OPTION_timeout (8, 2, 2, "(timeout, ms)")
#define SF_INPUTS_OPTION_range (9, 3, 3, "(range, minimum, maximum)")
#define SF_INPUTS_OPTION_by_stamp (10, 1, 1, "(by_stamp)")
#define SF_INPUTS_OPTION_angle (11, 1, 1, "(angle)")
#define SF_INPUTS_OPTION_frame_aligned (12, 3, 3, "(frame_aligned, member, axis)")
#define SF_INPUTS_OPTION_derived (13, 3, 3, "(derived, quantity, mode)")
#define SF_INPUTS_OPTION_covariance (14, 3, 3, "(covariance, member, entry)")
#define SF_INPUTS_OPTION_covariance_block (15, 4, 4, "(covariance_block, block, member, row)")
#define SF_INPUTS_OPTION_SF_INPUTS_END (16, 1, 1, "")  // marks the end of a record
#define SF_INPUTS_OPTION_NAMES                                                                     \
  "observe, observation_row, jacobian_row, variance, variance_field, alignment, gate, timeout, "   \
  "range, by_stamp, angle, frame_aligned, derived, covariance, covariance_block"
#define SF_INPUTS_OBSERVE 1
#define SF_INPUTS_OBSERVATION_ROW 2
#define SF_INPUTS_JACOBIAN_ROW 3
#define SF_INPUTS_VARIANCE 4
#define SF_INPUTS_VARIANCE_FIELD 5
#define SF_INPUTS_ALIGNMENT 6
#define SF_INPUTS_GATE 7
#define SF_INPUTS_TIMEOUT 8
#define SF_INPUTS_RANGE 9
#define SF_INPUTS_BY_STAMP 10
#define SF_INPUTS_ANGLE 11
#define SF_INPUTS_FRAME_ALIGNED 12
#define SF_INPUTS_DERIVED 13
#define SF_INPUTS_COVARIANCE 14
#define SF_INPUTS_COVARIANCE_BLOCK 15

/// The option table entry of an option tuple (kw, ...), or (0, 0, 99, "") if kw is unknown.
#define SF_INPUTS_ENTRY(option)                                                                    \
  BOOST_PP_IIF(BOOST_PP_IS_BEGIN_PARENS(BOOST_PP_TUPLE_ELEM(0, option)), SF_INPUTS_ENTRY_UNKNOWN,  \
               SF_INPUTS_ENTRY_I)(BOOST_PP_TUPLE_ELEM(0, option))
#define SF_INPUTS_ENTRY_I(kw)                                                                      \
  BOOST_PP_IIF(BOOST_PP_IS_BEGIN_PARENS(BOOST_PP_CAT(SF_INPUTS_OPTION_, kw)), SF_INPUTS_ENTRY_KNOWN, \
               SF_INPUTS_ENTRY_UNKNOWN)(kw)
#define SF_INPUTS_ENTRY_KNOWN(kw) BOOST_PP_CAT(SF_INPUTS_OPTION_, kw)
#define SF_INPUTS_ENTRY_UNKNOWN(kw) (0, 0, 99, "")
#define SF_INPUTS_ID(option) BOOST_PP_TUPLE_ELEM(0, SF_INPUTS_ENTRY(option))

// ---------------------------------------------------------------------------------------------
// Records: a record is a variadic sequence; R below is it as a plain sequence of tuples,
// ((name))((topic))((type))((field))((option, ...))...
// ---------------------------------------------------------------------------------------------
#define SF_INPUTS_R(record) BOOST_PP_VARIADIC_SEQ_TO_SEQ(record)

/// 1 if the value is a sequence of records, each a sequence of at least 4 elements.
#define SF_INPUTS_ARE_RECORDS(...)                                                                 \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_INPUTS_ARE_RECORDS_I, 0 SF_PP_NOTHING)(__VA_ARGS__)
#define SF_INPUTS_ARE_RECORDS_I(seq) BOOST_PP_SEQ_FOLD_LEFT(SF_INPUTS_ARE_RECORDS_OP, 1, seq)
#define SF_INPUTS_ARE_RECORDS_OP(s, state, record)                                                 \
  BOOST_PP_BITAND(state, BOOST_PP_IIF(BOOST_PP_IS_BEGIN_PARENS(record), SF_INPUTS_LONG_ENOUGH,     \
                                      0 SF_PP_NOTHING)(record))
#define SF_INPUTS_LONG_ENOUGH(record)                                                              \
  BOOST_PP_GREATER_EQUAL(BOOST_PP_SEQ_SIZE(SF_INPUTS_R(record)), 4)
#define SF_INPUTS_POSITIONAL(k, R) BOOST_PP_TUPLE_ELEM(0, BOOST_PP_SEQ_ELEM(k, R))
#define SF_INPUTS_NAME(R) SF_INPUTS_POSITIONAL(0, R)

/// R's options followed by the end marker ((SF_INPUTS_END)) (never empty).
#define SF_INPUTS_OPTIONS(R) BOOST_PP_SEQ_REST_N(4, R((SF_INPUTS_END)))

/// (found, option tuple) of the option with id ID in R; (0, ~) if R has none.
#define SF_INPUTS_FIND(ID, R)                                                                      \
  BOOST_PP_TUPLE_POP_FRONT(BOOST_PP_SEQ_FOLD_LEFT(SF_INPUTS_FIND_OP, (ID, 0, ~), SF_INPUTS_OPTIONS(R)))
// state (ID, found, option). An option with the wrong number of arguments is not found (it is
// reported by SF_INPUTS_CHECK_OPTION, and the generated macros stay well formed).
#define SF_INPUTS_FIND_OP(s, state, option)                                                        \
  BOOST_PP_IIF(BOOST_PP_BITAND(BOOST_PP_COMPL(BOOST_PP_TUPLE_ELEM(3, 1, state)),                   \
                               SF_INPUTS_IS(BOOST_PP_TUPLE_ELEM(3, 0, state), option)),            \
               (BOOST_PP_TUPLE_ELEM(3, 0, state), 1, option), state)
#define SF_INPUTS_IS(ID, option)                                                                   \
  BOOST_PP_IIF(BOOST_PP_EQUAL(SF_INPUTS_ID(option), ID), SF_INPUTS_ARITY_OK, 0 SF_PP_NOTHING)(     \
      option, SF_INPUTS_ENTRY(option))
#define SF_INPUTS_ARITY_OK(option, entry)                                                          \
  BOOST_PP_BITAND(BOOST_PP_GREATER_EQUAL(BOOST_PP_TUPLE_SIZE(option), BOOST_PP_TUPLE_ELEM(4, 1, entry)), \
                  BOOST_PP_LESS_EQUAL(BOOST_PP_TUPLE_SIZE(option), BOOST_PP_TUPLE_ELEM(4, 2, entry)))

#define SF_INPUTS_HAS(ID, R) BOOST_PP_TUPLE_ELEM(2, 0, SF_INPUTS_FIND(ID, R))
/// The option's arguments as a sequence: (a)(b) of (kw, a, b).
#define SF_INPUTS_ARGS(ID, R)                                                                      \
  BOOST_PP_TUPLE_TO_SEQ(BOOST_PP_TUPLE_POP_FRONT(BOOST_PP_TUPLE_ELEM(2, 1, SF_INPUTS_FIND(ID, R))))
#define SF_INPUTS_ARG0(ID, R) BOOST_PP_SEQ_ELEM(0, SF_INPUTS_ARGS(ID, R))

// ---------------------------------------------------------------------------------------------
// Emitters: one pass over the records each.
// ---------------------------------------------------------------------------------------------
/// 1 if some record has option ID.
#define SF_INPUTS_ANY(ID) BOOST_PP_COMPL(BOOST_PP_IS_EMPTY(SF_INPUTS_INDICES(ID)))
#define SF_INPUTS_INDICES(ID) BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_INDEX_OP, ID, INPUTS)
#define SF_INPUTS_INDEX_OP(r, ID, i, record)                                                       \
  BOOST_PP_EXPR_IIF(SF_INPUTS_HAS(ID, SF_INPUTS_R(record)), (i))

/// ((i)(arguments...)) of every record with option ID: the entries of an index-addressed list.
#define SF_INPUTS_LIST(ID) BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_LIST_OP, ID, INPUTS)
#define SF_INPUTS_LIST_OP(r, ID, i, record) SF_INPUTS_LIST_OP_I(ID, i, SF_INPUTS_R(record))
#define SF_INPUTS_LIST_OP_I(ID, i, R)                                                              \
  BOOST_PP_IIF(SF_INPUTS_HAS(ID, R), SF_INPUTS_LIST_ENTRY, SF_PP_NOTHING)(ID, i, R)
#define SF_INPUTS_LIST_ENTRY(ID, i, R) ((i) SF_INPUTS_ARGS(ID, R))

/// (argument) of option ID per record, (placeholder) for a record without it (reported by
/// SF_INPUTS_CHECK_EVERY): a vector with one entry per input.
#define SF_INPUTS_VECTOR(ID, placeholder)                                                          \
  BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_VECTOR_OP, (ID, placeholder), INPUTS)
#define SF_INPUTS_VECTOR_OP(r, data, i, record)                                                    \
  SF_INPUTS_VECTOR_OP_I(BOOST_PP_TUPLE_ELEM(2, 0, data), BOOST_PP_TUPLE_ELEM(2, 1, data),          \
                        SF_INPUTS_R(record))
#define SF_INPUTS_VECTOR_OP_I(ID, placeholder, R)                                                  \
  (BOOST_PP_IIF(SF_INPUTS_HAS(ID, R), SF_INPUTS_ARG0, placeholder SF_PP_NOTHING)(ID, R))

#define SF_INPUTS_TOPICS_IN_OP(r, data, i, record) SF_INPUTS_TOPICS_IN_ENTRY(SF_INPUTS_R(record))
#define SF_INPUTS_TOPICS_IN_ENTRY(R)                                                               \
  ((SF_INPUTS_POSITIONAL(1, R))(SF_INPUTS_POSITIONAL(2, R))(SF_INPUTS_POSITIONAL(3, R))            \
   BOOST_PP_IIF(SF_INPUTS_HAS(SF_INPUTS_VARIANCE_FIELD, R), SF_INPUTS_VARIANCE_FIELD_OF,           \
                SF_PP_NOTHING)(R))
#define SF_INPUTS_VARIANCE_FIELD_OF(R) (SF_INPUTS_ARG0(SF_INPUTS_VARIANCE_FIELD, R))

/// The covariance blocks: records with (covariance_block, k, member, row), k from 0 to
/// SF_INPUTS_MAX_BLOCKS - 1, form INPUT_COVARIANCE_BLOCK's entry for k (if any record has k).
#define SF_INPUTS_MAX_BLOCKS 4
#define SF_INPUTS_BLOCKS BOOST_PP_REPEAT(SF_INPUTS_MAX_BLOCKS, SF_INPUTS_BLOCK_ENTRY, ~)
#define SF_INPUTS_BLOCK_ENTRY(z, k, data)                                                          \
  BOOST_PP_IIF(BOOST_PP_IS_EMPTY(SF_INPUTS_BLOCK_SEQ(k, 0)), SF_PP_NOTHING,                        \
               SF_INPUTS_BLOCK_ENTRY_I)(k)
#define SF_INPUTS_BLOCK_ENTRY_I(k)                                                                 \
  ((SF_INPUTS_BLOCK_SEQ(k, 0))(SF_INPUTS_BLOCK_MEMBER(k))(SF_INPUTS_BLOCK_SEQ(k, 2)))
#define SF_INPUTS_BLOCK_MEMBER(k) BOOST_PP_SEQ_HEAD(SF_INPUTS_BLOCK_SEQ(k, 1))
/// Per record of block k: (i) (what 0), (member) (what 1) or (row) (what 2).
#define SF_INPUTS_BLOCK_SEQ(k, what) BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_BLOCK_OP, (k, what), INPUTS)
#define SF_INPUTS_BLOCK_OP(r, data, i, record)                                                     \
  SF_INPUTS_BLOCK_OP_I(BOOST_PP_TUPLE_ELEM(2, 0, data), BOOST_PP_TUPLE_ELEM(2, 1, data), i,        \
                       SF_INPUTS_R(record))
#define SF_INPUTS_BLOCK_OP_I(k, what, i, R)                                                        \
  BOOST_PP_IIF(SF_INPUTS_IN_BLOCK(k, R), SF_INPUTS_BLOCK_ITEM, SF_PP_NOTHING)(what, i, R)
#define SF_INPUTS_BLOCK_ITEM(what, i, R)                                                           \
  (BOOST_PP_IF(what, BOOST_PP_SEQ_ELEM(what, SF_INPUTS_ARGS(SF_INPUTS_COVARIANCE_BLOCK, R)), i))
/// 1 if R has (covariance_block, k, ...).
#define SF_INPUTS_IN_BLOCK(k, R)                                                                   \
  BOOST_PP_IIF(SF_INPUTS_HAS(SF_INPUTS_COVARIANCE_BLOCK, R), SF_INPUTS_BLOCK_IS,                   \
               0 SF_PP_NOTHING)(k, R)
#define SF_INPUTS_BLOCK_IS(k, R) BOOST_PP_EQUAL(SF_INPUTS_ARG0(SF_INPUTS_COVARIANCE_BLOCK, R), k)

#define SF_INPUTS_POSITIONAL_OK(R)                                                                 \
  BOOST_PP_BITAND(BOOST_PP_BITAND(SF_INPUTS_IS_ONE(0, R), SF_INPUTS_IS_ONE(1, R)),                 \
                  BOOST_PP_BITAND(SF_INPUTS_IS_ONE(2, R), SF_INPUTS_IS_ONE(3, R)))
/// 1 if every record starts with (name)(topic)(type)(field), each one element.
#define SF_INPUTS_ALL_POSITIONAL_OK BOOST_PP_SEQ_FOLD_LEFT(SF_INPUTS_ALL_POSITIONAL_OP, 1, INPUTS)
#define SF_INPUTS_ALL_POSITIONAL_OP(s, state, record)                                              \
  BOOST_PP_BITAND(state, SF_INPUTS_POSITIONAL_OK(SF_INPUTS_R(record)))
#define SF_INPUTS_CHECK_POSITIONAL(z, i, data)                                                     \
  SF_INPUTS_CHECK_POSITIONAL_I(i, SF_INPUTS_R(BOOST_PP_SEQ_ELEM(i, INPUTS)))
#define SF_INPUTS_CHECK_POSITIONAL_I(i, R)                                                         \
  static_assert(SF_INPUTS_POSITIONAL_OK(R), "INPUTS record " SF_PP_STR(i) ": expected (name)(topic)(type)(field) before the "  \
                "options; found '" SF_PP_STR(R) "'");
#define SF_INPUTS_IS_ONE(k, R) BOOST_PP_EQUAL(BOOST_PP_TUPLE_SIZE(BOOST_PP_SEQ_ELEM(k, R)), 1)

// ---------------------------------------------------------------------------------------------
// Which of the all-or-none options every record must give: those some record gives, and
// those METHOD requires (configuration.hpp's table).
// ---------------------------------------------------------------------------------------------
#if defined(METHOD) && (METHOD == EXTENDED_KALMAN_FILTER || METHOD == UNSCENTED_KALMAN_FILTER ||   \
                        METHOD == PARTICLE_FILTER_SIR)
#define SF_INPUTS_REQUIRES_OBSERVE 1
#else
#define SF_INPUTS_REQUIRES_OBSERVE 0
#endif
#if defined(METHOD) && METHOD == KALMAN_FILTER
#define SF_INPUTS_REQUIRES_OBSERVATION_ROW 1
#else
#define SF_INPUTS_REQUIRES_OBSERVATION_ROW 0
#endif
#if defined(METHOD) && (METHOD == KALMAN_FILTER || SF_INPUTS_REQUIRES_OBSERVE)
#define SF_INPUTS_REQUIRES_VARIANCE 1
#else
#define SF_INPUTS_REQUIRES_VARIANCE 0
#endif

// ---------------------------------------------------------------------------------------------
// The thesis macros
// ---------------------------------------------------------------------------------------------
#if !SF_INPUTS_ARE_RECORDS(INPUTS)
static_assert(false, "INPUTS: expected a sequence of records, each written as "
              "((name)(topic)(type)(field)(option, arguments)...), e.g. "
              "((gyro_z)(imu)(sensor_msgs::Imu)(angular_velocity.z)(observe, x[2])(variance, 1e-4)); "
              "found '" SF_PP_STR(INPUTS) "'");
#define SF_CFG_FATAL
#elif !SF_INPUTS_ALL_POSITIONAL_OK
BOOST_PP_REPEAT(BOOST_PP_SEQ_SIZE(INPUTS), SF_INPUTS_CHECK_POSITIONAL, ~)
#define SF_CFG_FATAL
#else
#define TOPICS_IN BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_TOPICS_IN_OP, ~, INPUTS)
// SF_INPUTS_EVERY_<option>: 1 if every record must give the option.
#if SF_INPUTS_REQUIRES_OBSERVE || SF_INPUTS_ANY(SF_INPUTS_OBSERVE)
#define SF_INPUTS_EVERY_OBSERVE 1
#define OBSERVATION_MODEL SF_INPUTS_VECTOR(SF_INPUTS_OBSERVE, 0)
#else
#define SF_INPUTS_EVERY_OBSERVE 0
#endif
#if SF_INPUTS_REQUIRES_OBSERVATION_ROW || SF_INPUTS_ANY(SF_INPUTS_OBSERVATION_ROW)
#define SF_INPUTS_EVERY_OBSERVATION_ROW 1
#define OBSERVATION_MATRIX SF_INPUTS_VECTOR(SF_INPUTS_OBSERVATION_ROW, (0))
#else
#define SF_INPUTS_EVERY_OBSERVATION_ROW 0
#endif
#if SF_INPUTS_ANY(SF_INPUTS_JACOBIAN_ROW)
#define SF_INPUTS_EVERY_JACOBIAN_ROW 1
#define OBSERVATION_JACOBIAN SF_INPUTS_VECTOR(SF_INPUTS_JACOBIAN_ROW, (0))
#else
#define SF_INPUTS_EVERY_JACOBIAN_ROW 0
#endif
#if SF_INPUTS_REQUIRES_VARIANCE || SF_INPUTS_ANY(SF_INPUTS_VARIANCE)
#define SF_INPUTS_EVERY_VARIANCE 1
#define MEASUREMENT_NOISE_COVARIANCE SF_DIAGONAL(SF_INPUTS_VECTOR(SF_INPUTS_VARIANCE, 1))
#else
#define SF_INPUTS_EVERY_VARIANCE 0
#endif
#if SF_INPUTS_ANY(SF_INPUTS_ALIGNMENT)
#define INPUT_ALIGNMENT SF_INPUTS_LIST(SF_INPUTS_ALIGNMENT)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_GATE)
#define INPUT_GATE SF_INPUTS_LIST(SF_INPUTS_GATE)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_TIMEOUT)
#define INPUT_TIMEOUT SF_INPUTS_LIST(SF_INPUTS_TIMEOUT)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_RANGE)
#define INPUT_RANGE SF_INPUTS_LIST(SF_INPUTS_RANGE)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_BY_STAMP)
#define ALIGN_BY_STAMP SF_INPUTS_INDICES(SF_INPUTS_BY_STAMP)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_ANGLE)
#define ANGLE_INPUTS SF_INPUTS_INDICES(SF_INPUTS_ANGLE)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_FRAME_ALIGNED)
#define FRAME_ALIGNED_INPUTS SF_INPUTS_LIST(SF_INPUTS_FRAME_ALIGNED)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_DERIVED)
#define DERIVED_INPUTS SF_INPUTS_LIST(SF_INPUTS_DERIVED)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_COVARIANCE)
#define INPUT_COVARIANCE SF_INPUTS_LIST(SF_INPUTS_COVARIANCE)
#endif
#if SF_INPUTS_ANY(SF_INPUTS_COVARIANCE_BLOCK) && defined(INPUT_COVARIANCE_BLOCK)
#error INPUTS records give (covariance_block, block, member, row) and INPUT_COVARIANCE_BLOCK is defined too: give the blocks on the records or in INPUT_COVARIANCE_BLOCK, not both
#define SF_CFG_FATAL
#define SF_CFG_STOP
#elif SF_INPUTS_ANY(SF_INPUTS_COVARIANCE_BLOCK) && !BOOST_PP_IS_EMPTY(SF_INPUTS_BLOCKS)
#define INPUT_COVARIANCE_BLOCK SF_INPUTS_BLOCKS  // (none if every block number is out of range)
#endif

/// The record names as string literals, in input order (detail/input_names.hpp).
#define SF_INPUTS_NAMES BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_NAMES_OP, ~, INPUTS)
#define SF_INPUTS_NAMES_OP(r, data, i, record)                                                     \
  BOOST_PP_COMMA_IF(i) SF_PP_STR(SF_INPUTS_NAME(SF_INPUTS_R(record)))

// ---------------------------------------------------------------------------------------------
// Checks of the records (one static_assert per mistake, naming INPUTS and the record)
// ---------------------------------------------------------------------------------------------
// REPEAT over the records, so that the options' FOR_EACH inside is not nested in another.
#define SF_INPUTS_CHECK_RECORD(z, i, data)                                                         \
  SF_INPUTS_CHECK_R(i, SF_INPUTS_R(BOOST_PP_SEQ_ELEM(i, INPUTS)))
#define SF_INPUTS_CHECK_R(i, R) SF_INPUTS_CHECK_OPTIONS_I(i, R, SF_INPUTS_IDS(R))
#define SF_INPUTS_CHECK_OPTIONS_I(i, R, ids)                                                       \
  static_assert(::sf_config::input_records::isIdentifier(SF_PP_STR(SF_INPUTS_NAME(R))),            \
                "INPUTS record " SF_PP_STR(i) ": the name '" SF_PP_STR(SF_INPUTS_NAME(R))          \
                "' is not an identifier (letters, digits, _; not starting with a digit)");        \
  static_assert(::sf_config::input_records::countBefore(kSfInputsNames, i,                         \
                                                        SF_PP_STR(SF_INPUTS_NAME(R))) == 0,        \
                "INPUTS record " SF_PP_STR(i) ": the name '" SF_PP_STR(SF_INPUTS_NAME(R))          \
                "' is already used by an earlier record");                                         \
  BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_CHECK_OPTION, (i, R, ids), SF_INPUTS_OPTIONS(R))               \
  SF_INPUTS_CHECK_EVERY(i, R, ids, SF_INPUTS_OBSERVE, SF_INPUTS_EVERY_OBSERVE,                     \
                        "(observe, expression)")                                                   \
  SF_INPUTS_CHECK_EVERY(i, R, ids, SF_INPUTS_OBSERVATION_ROW, SF_INPUTS_EVERY_OBSERVATION_ROW,     \
                        "(observation_row, (h0)(h1)...)")                                          \
  SF_INPUTS_CHECK_EVERY(i, R, ids, SF_INPUTS_JACOBIAN_ROW, SF_INPUTS_EVERY_JACOBIAN_ROW,           \
                        "(jacobian_row, (d0)(d1)...)")                                             \
  SF_INPUTS_CHECK_EVERY(i, R, ids, SF_INPUTS_VARIANCE, SF_INPUTS_EVERY_VARIANCE, "(variance, R_ii)") \
  BOOST_PP_IIF(SF_INPUTS_HAS(SF_INPUTS_COVARIANCE_BLOCK, R), SF_INPUTS_CHECK_BLOCK,                \
               SF_PP_NOTHING)(i, R, SF_INPUTS_ARGS(SF_INPUTS_COVARIANCE_BLOCK, R))


/// The option ids of R, (std::initializer_list<int>{id, ...}) (the end marker included).
#define SF_INPUTS_IDS(R)                                                                           \
  (std::initializer_list<int>{BOOST_PP_SEQ_FOR_EACH_I(SF_INPUTS_IDS_OP, ~, SF_INPUTS_OPTIONS(R))})
#define SF_INPUTS_IDS_OP(r, data, k, option) BOOST_PP_COMMA_IF(k) SF_INPUTS_ID(option)

#define SF_INPUTS_CHECK_OPTION(r, data, k, option)                                                 \
  SF_INPUTS_CHECK_OPTION_I(BOOST_PP_TUPLE_ELEM(3, 0, data), BOOST_PP_TUPLE_ELEM(3, 1, data),       \
                           BOOST_PP_TUPLE_ELEM(3, 2, data), k, option)
#define SF_INPUTS_CHECK_OPTION_I(i, R, ids, k, option)                                             \
  SF_INPUTS_CHECK_OPTION_II(i, R, ids, k, option, SF_INPUTS_ENTRY(option))
#define SF_INPUTS_CHECK_OPTION_II(i, R, ids, k, option, entry)                                     \
  static_assert(BOOST_PP_TUPLE_ELEM(4, 0, entry) != 0,                                             \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R))                    \
                "): unknown option '" SF_PP_STR(option) "'; the options are "                     \
                SF_INPUTS_OPTION_NAMES);                                                           \
  static_assert(BOOST_PP_TUPLE_ELEM(4, 0, entry) == 0 ||                                           \
                    (BOOST_PP_TUPLE_SIZE(option) >= BOOST_PP_TUPLE_ELEM(4, 1, entry) &&            \
                     BOOST_PP_TUPLE_SIZE(option) <= BOOST_PP_TUPLE_ELEM(4, 2, entry)),             \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R))                    \
                "): option '" SF_PP_STR(option) "' has the wrong number of arguments, expected "   \
                BOOST_PP_TUPLE_ELEM(4, 3, entry));                                                 \
  static_assert(BOOST_PP_TUPLE_ELEM(4, 0, entry) == 0 ||                                           \
                    ::sf_config::input_records::countBefore(ids, k, BOOST_PP_TUPLE_ELEM(4, 0, entry)) == 0, \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R))                    \
                "): option '" SF_PP_STR(option) "' is given a second time");

/// A record's (covariance_block, k, member, row): k names one of the blocks, and the member is
/// the one of the block's first record (the block reads one covariance array).
#define SF_INPUTS_CHECK_BLOCK(i, R, args)                                                          \
  static_assert(BOOST_PP_SEQ_ELEM(0, args) >= 0 &&                                                 \
                    BOOST_PP_SEQ_ELEM(0, args) < SF_INPUTS_MAX_BLOCKS,                             \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R)) "): block '"       \
                SF_PP_STR(BOOST_PP_SEQ_ELEM(0, args)) "' of (covariance_block, block, member, "    \
                "row) is not one of 0 to 3 (records with the same block number share one "         \
                "INPUT_COVARIANCE_BLOCK entry)");                                                  \
  static_assert(std::string_view(SF_PP_STR(BOOST_PP_SEQ_ELEM(1, args))) ==                         \
                    std::string_view(SF_PP_STR(SF_INPUTS_BLOCK_MEMBER(BOOST_PP_SEQ_ELEM(0, args)))), \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R)) "): the member '"  \
                SF_PP_STR(BOOST_PP_SEQ_ELEM(1, args)) "' of its covariance_block is not the one "  \
                "of the block's first record; a block reads one covariance array");

/// A record without option ID although NEEDED (some record gives it, or METHOD requires it).
#define SF_INPUTS_CHECK_EVERY(i, R, ids, ID, NEEDED, FORM)                                         \
  static_assert(!(NEEDED) || ::sf_config::input_records::countBefore(ids, 99, ID) > 0,                                                 \
                "INPUTS record " SF_PP_STR(i) " (" SF_PP_STR(SF_INPUTS_NAME(R)) ") has no "        \
                FORM ": every record needs it (METHOD requires it, or other records give it)");

namespace sf_config::input_records {
inline constexpr std::string_view kSfInputsNames[] = {SF_INPUTS_NAMES};
BOOST_PP_REPEAT(BOOST_PP_SEQ_SIZE(INPUTS), SF_INPUTS_CHECK_RECORD, ~)
}  // namespace sf_config::input_records
#endif  // records well formed

#endif  // one syntax
#endif  // INPUTS

// clang-format on
