// Boost.Preprocessor helpers of the configuration layer: recognizing well-formed sequences,
// emitting static_asserts that name the offending macro (with the sizes found and expected
// stringized into the message), and unrolling sequences into C++ statements.
//
// Every macro that receives a user's macro value takes it as the trailing variadic argument,
// so that a mistaken value containing top-level commas (e.g. `0, 0` or `{0, 0}`) still reaches
// a check that reports it instead of breaking the macro call itself.
#pragma once

#include <boost/preprocessor/arithmetic/dec.hpp>
#include <boost/preprocessor/arithmetic/inc.hpp>
#include <boost/preprocessor/cat.hpp>
#include <boost/preprocessor/comparison/equal.hpp>
#include <boost/preprocessor/comparison/greater_equal.hpp>
#include <boost/preprocessor/comparison/less_equal.hpp>
#include <boost/preprocessor/comparison/not_equal.hpp>
#include <boost/preprocessor/control/expr_iif.hpp>
#include <boost/preprocessor/control/iif.hpp>
#include <boost/preprocessor/logical/bitand.hpp>
#include <boost/preprocessor/logical/compl.hpp>
#include <boost/preprocessor/punctuation/comma_if.hpp>
#include <boost/preprocessor/punctuation/is_begin_parens.hpp>
#include <boost/preprocessor/repetition/repeat.hpp>
#include <boost/preprocessor/seq/elem.hpp>
#include <boost/preprocessor/seq/fold_left.hpp>
#include <boost/preprocessor/seq/for_each_i.hpp>
#include <boost/preprocessor/seq/size.hpp>
#include <boost/preprocessor/seq/variadic_seq_to_seq.hpp>
#include <boost/preprocessor/tuple/eat.hpp>
#include <boost/preprocessor/tuple/elem.hpp>
#include <boost/preprocessor/tuple/size.hpp>
#include <boost/preprocessor/variadic/size.hpp>

// clang-format off

/// String literal of the (macro-expanded) argument, commas included.
#define SF_PP_STR(...) SF_PP_STR_I(__VA_ARGS__)
#define SF_PP_STR_I(...) #__VA_ARGS__

#define SF_PP_NOTHING(...)

// ---------------------------------------------------------------------------------------------
// Recognizers (expand to the literal 0 or 1; usable in #if and BOOST_PP_IIF)
// ---------------------------------------------------------------------------------------------

/// 1 if the argument is one token sequence starting with '(' (no top-level comma).
#define SF_PP_IS_SEQ(...)                                                                          \
  BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_VARIADIC_SIZE(__VA_ARGS__), 1),                             \
               BOOST_PP_IS_BEGIN_PARENS, 0 BOOST_PP_TUPLE_EAT())(__VA_ARGS__)

/// 1 if the argument is a Boost.PP sequence (a)(b)(c) whose elements have no top-level comma.
#define SF_PP_IS_VECTOR(...)                                                                       \
  BOOST_PP_IIF(SF_PP_IS_SEQ(__VA_ARGS__), SF_PP_IS_VECTOR_I, 0 BOOST_PP_TUPLE_EAT())(__VA_ARGS__)
#define SF_PP_IS_VECTOR_I(seq)                                                                     \
  BOOST_PP_SEQ_FOLD_LEFT(SF_PP_IS_VECTOR_OP, 1, BOOST_PP_VARIADIC_SEQ_TO_SEQ(seq))
#define SF_PP_IS_VECTOR_OP(s, state, tuple)                                                        \
  BOOST_PP_BITAND(state, BOOST_PP_EQUAL(BOOST_PP_TUPLE_SIZE(tuple), 1))

/// 1 if the argument is a sequence of rows, each row a sequence: ((1)(0))((0)(1)).
#define SF_PP_IS_MATRIX(...)                                                                       \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_PP_IS_MATRIX_I, 0 BOOST_PP_TUPLE_EAT())(__VA_ARGS__)
#define SF_PP_IS_MATRIX_I(seq) BOOST_PP_SEQ_FOLD_LEFT(SF_PP_IS_MATRIX_OP, 1, seq)
#define SF_PP_IS_MATRIX_OP(s, state, row) BOOST_PP_BITAND(state, SF_PP_IS_VECTOR(row))

/// 1 if the argument is a sequence of entries, each entry a sequence of MIN..MAX elements,
/// e.g. ((acceleration)(geometry_msgs::Vector3Stamped)(vector.y)).
#define SF_PP_IS_LIST(MIN, MAX, ...)                                                               \
  BOOST_PP_EQUAL(SF_PP_LIST_FIRST_BAD(MIN, MAX, __VA_ARGS__), 256)

/// Index of the first malformed entry of a list (see SF_PP_IS_LIST); 255 if the list itself is
/// not a sequence; 256 if all entries are well formed.
#define SF_PP_LIST_FIRST_BAD(MIN, MAX, ...)                                                        \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_PP_LIST_FIRST_BAD_I, 255 SF_PP_NOTHING)(           \
      MIN, MAX, __VA_ARGS__)
#define SF_PP_LIST_FIRST_BAD_I(MIN, MAX, seq)                                                      \
  BOOST_PP_TUPLE_ELEM(4, 3,                                                                      \
                      BOOST_PP_SEQ_FOLD_LEFT(SF_PP_LIST_FIRST_BAD_OP, (0, MIN, MAX, 256), seq))
#define SF_PP_LIST_FIRST_BAD_OP(s, state, entry)                                                   \
  (BOOST_PP_INC(BOOST_PP_TUPLE_ELEM(4, 0, state)), BOOST_PP_TUPLE_ELEM(4, 1, state),               \
   BOOST_PP_TUPLE_ELEM(4, 2, state),                                                               \
   BOOST_PP_IIF(BOOST_PP_BITAND(BOOST_PP_EQUAL(BOOST_PP_TUPLE_ELEM(4, 3, state), 256),             \
                                BOOST_PP_COMPL(SF_PP_IS_ENTRY(BOOST_PP_TUPLE_ELEM(4, 1, state),    \
                                                              BOOST_PP_TUPLE_ELEM(4, 2, state),    \
                                                              entry))),                            \
                BOOST_PP_TUPLE_ELEM(4, 0, state), BOOST_PP_TUPLE_ELEM(4, 3, state)))

/// 1 if `entry` is a sequence of MIN..MAX elements.
#define SF_PP_IS_ENTRY(MIN, MAX, ...)                                                              \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_PP_IS_ENTRY_I, 0 SF_PP_NOTHING)(                 \
      MIN, MAX, __VA_ARGS__)
#define SF_PP_IS_ENTRY_I(MIN, MAX, entry)                                                          \
  BOOST_PP_BITAND(BOOST_PP_GREATER_EQUAL(BOOST_PP_SEQ_SIZE(entry), MIN),                           \
                  BOOST_PP_LESS_EQUAL(BOOST_PP_SEQ_SIZE(entry), MAX))

// ---------------------------------------------------------------------------------------------
// Checks: expand to static_assert declarations whose message starts with the macro name.
// NAME is a string literal; WHY is a string literal explaining where the expected size comes
// from (e.g. "n = 2 is the number of expressions in STATE_TRANSITION_MODEL").
// ---------------------------------------------------------------------------------------------

/// Checks that the value is a sequence of EXPECTED entries. EXAMPLE is a string literal.
#define SF_PP_CHECK_VECTOR(NAME, EXPECTED, WHY, EXAMPLE, ...)                                      \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_PP_CHECK_VECTOR_SIZE, SF_PP_VECTOR_FORM_ERROR)(    \
      NAME, EXPECTED, WHY, EXAMPLE, __VA_ARGS__)
#define SF_PP_VECTOR_FORM_ERROR(NAME, EXPECTED, WHY, EXAMPLE, ...)                                 \
  static_assert(false, NAME ": expected a sequence of " SF_PP_STR(EXPECTED)                        \
                " entries, each in parentheses, e.g. " EXAMPLE "; found '"                         \
                SF_PP_STR(__VA_ARGS__) "'");
#define SF_PP_CHECK_VECTOR_SIZE(NAME, EXPECTED, WHY, EXAMPLE, seq)                                 \
  static_assert(BOOST_PP_SEQ_SIZE(seq) == (EXPECTED),                                              \
                NAME ": expected " SF_PP_STR(EXPECTED) " entries, found "                          \
                SF_PP_STR(BOOST_PP_SEQ_SIZE(seq)) " (" WHY ")");

/// Checks that the value is a ROWS x COLS matrix written as a sequence of rows.
#define SF_PP_CHECK_MATRIX(NAME, ROWS, COLS, WHY, ...)                                             \
  BOOST_PP_IIF(SF_PP_IS_MATRIX(__VA_ARGS__), SF_PP_CHECK_MATRIX_SIZE, SF_PP_MATRIX_FORM_ERROR)(    \
      NAME, ROWS, COLS, WHY, __VA_ARGS__)
#define SF_PP_MATRIX_FORM_ERROR(NAME, ROWS, COLS, WHY, ...)                                        \
  static_assert(false, NAME ": expected a " SF_PP_STR(ROWS) " x " SF_PP_STR(COLS)                  \
                " matrix written as a sequence of rows, each row a sequence of entries, "          \
                "e.g. ((1)(0))((0)(1)); found '" SF_PP_STR(__VA_ARGS__) "'");
#define SF_PP_CHECK_MATRIX_SIZE(NAME, ROWS, COLS, WHY, m)                                          \
  static_assert(BOOST_PP_SEQ_SIZE(m) == (ROWS),                                                    \
                NAME ": expected " SF_PP_STR(ROWS) " rows, found "                                 \
                SF_PP_STR(BOOST_PP_SEQ_SIZE(m)) " (" WHY ")");                                     \
  BOOST_PP_IIF(BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(m), ROWS), SF_PP_CHECK_MATRIX_ROWS,                \
               SF_PP_NOTHING)(NAME, COLS, WHY, SF_PP_MATRIX_FIRST_BAD_ROW(COLS, m), m)
// Only the first row of the wrong length is reported (and only if the row count is right).
#define SF_PP_CHECK_MATRIX_ROWS(NAME, COLS, WHY, BAD, m)                                           \
  SF_PP_CHECK_MATRIX_ROWS_I(NAME, COLS, WHY, BAD, m)
#define SF_PP_CHECK_MATRIX_ROWS_I(NAME, COLS, WHY, BAD, m)                                         \
  BOOST_PP_IIF(BOOST_PP_EQUAL(BAD, 256), SF_PP_NOTHING, SF_PP_MATRIX_ROW_ERROR)(                   \
      NAME, COLS, WHY, BAD, m)
#define SF_PP_MATRIX_ROW_ERROR(NAME, COLS, WHY, BAD, m)                                            \
  static_assert(false, NAME ": row " SF_PP_STR(BAD) " has "                                        \
                SF_PP_STR(BOOST_PP_SEQ_SIZE(BOOST_PP_SEQ_ELEM(BAD, m))) " entries, expected "      \
                SF_PP_STR(COLS) " (" WHY ")");
/// Index of the first row whose length is not COLS, 256 if there is none.
#define SF_PP_MATRIX_FIRST_BAD_ROW(COLS, m)                                                        \
  BOOST_PP_TUPLE_ELEM(3, 2,                                                                      \
                      BOOST_PP_SEQ_FOLD_LEFT(SF_PP_MATRIX_FIRST_BAD_ROW_OP, (0, COLS, 256), m))
#define SF_PP_MATRIX_FIRST_BAD_ROW_OP(s, state, row)                                               \
  (BOOST_PP_INC(BOOST_PP_TUPLE_ELEM(3, 0, state)), BOOST_PP_TUPLE_ELEM(3, 1, state),               \
   BOOST_PP_IIF(BOOST_PP_BITAND(BOOST_PP_EQUAL(BOOST_PP_TUPLE_ELEM(3, 2, state), 256),             \
                                BOOST_PP_NOT_EQUAL(BOOST_PP_SEQ_SIZE(row),                         \
                                                   BOOST_PP_TUPLE_ELEM(3, 1, state))),             \
                BOOST_PP_TUPLE_ELEM(3, 0, state), BOOST_PP_TUPLE_ELEM(3, 2, state)))

/// Reports the first malformed entry of a list. FORMAT is a string literal such as
/// "((topic)(type)(field))". Expands to nothing if the list is well formed.
#define SF_PP_CHECK_LIST(NAME, MIN, MAX, FORMAT, ...)                                              \
  SF_PP_CHECK_LIST_I(NAME, MIN, MAX, FORMAT, SF_PP_LIST_FIRST_BAD(MIN, MAX, __VA_ARGS__),          \
                     __VA_ARGS__)
#define SF_PP_CHECK_LIST_I(NAME, MIN, MAX, FORMAT, BAD, ...)                                       \
  SF_PP_CHECK_LIST_II(NAME, MIN, MAX, FORMAT, BAD, __VA_ARGS__)
#define SF_PP_CHECK_LIST_II(NAME, MIN, MAX, FORMAT, BAD, ...)                                      \
  BOOST_PP_IIF(BOOST_PP_EQUAL(BAD, 256), SF_PP_NOTHING,                                            \
               BOOST_PP_IIF(BOOST_PP_EQUAL(BAD, 255), SF_PP_LIST_FORM_ERROR,                       \
                            SF_PP_LIST_ENTRY_ERROR))(NAME, MIN, MAX, FORMAT, BAD, __VA_ARGS__)
#define SF_PP_LIST_FORM_ERROR(NAME, MIN, MAX, FORMAT, BAD, ...)                                    \
  static_assert(false, NAME ": expected a sequence of entries, each entry written as "             \
                FORMAT "; found '" SF_PP_STR(__VA_ARGS__) "'");
#define SF_PP_LIST_ENTRY_ERROR(NAME, MIN, MAX, FORMAT, BAD, seq)                                   \
  SF_PP_LIST_ENTRY_ERROR_I(NAME, FORMAT, BAD, BOOST_PP_SEQ_ELEM(BAD, seq))
#define SF_PP_LIST_ENTRY_ERROR_I(NAME, FORMAT, BAD, ...)                                           \
  BOOST_PP_IIF(SF_PP_IS_VECTOR(__VA_ARGS__), SF_PP_LIST_ENTRY_SIZE_ERROR,                          \
               SF_PP_LIST_ENTRY_FORM_ERROR)(NAME, FORMAT, BAD, __VA_ARGS__)
#define SF_PP_LIST_ENTRY_SIZE_ERROR(NAME, FORMAT, BAD, entry)                                      \
  static_assert(false, NAME ": entry " SF_PP_STR(BAD) " has " SF_PP_STR(BOOST_PP_SEQ_SIZE(entry))  \
                " elements, expected " FORMAT "; found '" SF_PP_STR(entry) "'");
#define SF_PP_LIST_ENTRY_FORM_ERROR(NAME, FORMAT, BAD, ...)                                        \
  static_assert(false, NAME ": entry " SF_PP_STR(BAD)                                            \
                " is not a sequence of parenthesized elements, expected " FORMAT                 \
                " (note the double parentheses around each entry); found '"                        \
                SF_PP_STR(__VA_ARGS__) "'");

// ---------------------------------------------------------------------------------------------
// Code generation (only used on values that passed the recognizers above)
// ---------------------------------------------------------------------------------------------

/// VAR(0) = (e0); VAR(1) = (e1); ...
#define SF_PP_ASSIGN_VECTOR(VAR, seq) BOOST_PP_SEQ_FOR_EACH_I(SF_PP_ASSIGN_VECTOR_OP, VAR, seq)
#define SF_PP_ASSIGN_VECTOR_OP(r, VAR, i, e) VAR(i) = (e);

/// VAR(i, j) = (e_ij); for every entry of a matrix given as a sequence of rows.
#define SF_PP_ASSIGN_MATRIX(VAR, m)                                                                \
  BOOST_PP_REPEAT(BOOST_PP_SEQ_SIZE(m), SF_PP_ASSIGN_MATRIX_ROW, (VAR, m))
#define SF_PP_ASSIGN_MATRIX_ROW(z, i, data)                                                        \
  BOOST_PP_SEQ_FOR_EACH_I(SF_PP_ASSIGN_MATRIX_OP, (BOOST_PP_TUPLE_ELEM(2, 0, data), i),            \
                          BOOST_PP_SEQ_ELEM(i, BOOST_PP_TUPLE_ELEM(2, 1, data)))
#define SF_PP_ASSIGN_MATRIX_OP(r, data, j, e)                                                      \
  BOOST_PP_TUPLE_ELEM(2, 0, data)(BOOST_PP_TUPLE_ELEM(2, 1, data), j) = (e);

// ---------------------------------------------------------------------------------------------
// Math functions of the expressions
// ---------------------------------------------------------------------------------------------

/// Brings the math functions into scope so that an expression like sin(x[0]) finds std::sin
/// for double and Eigen's overload (by argument-dependent lookup) for AutoDiffScalar.
#define SF_CFG_MATH_USINGS                                                                         \
  using std::sin; using std::cos; using std::tan; using std::asin; using std::acos;                \
  using std::atan; using std::atan2; using std::sinh; using std::cosh; using std::tanh;            \
  using std::sqrt; using std::pow; using std::exp; using std::log; using std::abs;

// clang-format on
