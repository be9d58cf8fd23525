// SF_DIAGONAL(vector): the diagonal matrix with the entries of a vector, in the matrix syntax
// of a configuration header. Covariances are mostly diagonal, and a 7 x 7 matrix of zeros
// hides its 7 numbers:
//
//   #include <sf_filter/config/diagonal.hpp>
//   #define PROCESS_NOISE_COVARIANCE SF_DIAGONAL((0)(0)(0)(0.5)(0)(0)(0.3))
//
// expands to ((0)(0)(0)(0)(0)(0)(0)) ... ((0)(0)(0)(0)(0)(0)(0.3)), 7 rows of 7 entries.
// Entries may be any expression without a top-level comma (0.1 * T, PIONEER_RADIUS).
#pragma once

#include <boost/preprocessor/comparison/equal.hpp>
#include <boost/preprocessor/control/iif.hpp>
#include <boost/preprocessor/repetition/repeat.hpp>
#include <boost/preprocessor/seq/elem.hpp>
#include <boost/preprocessor/seq/for_each_i.hpp>
#include <boost/preprocessor/seq/size.hpp>

// clang-format off

#define SF_DIAGONAL(vector) \
  BOOST_PP_SEQ_FOR_EACH_I(SF_DIAGONAL_ROW, BOOST_PP_SEQ_SIZE(vector), vector)
// Row i: n entries, entry i the value, the others 0. The row index and the value travel as
// the two-element sequence (i)(value), so that a value may contain parentheses.
#define SF_DIAGONAL_ROW(r, n, i, value) (BOOST_PP_REPEAT(n, SF_DIAGONAL_ENTRY, (i)(value)))
#define SF_DIAGONAL_ENTRY(z, j, row) \
  BOOST_PP_IIF(BOOST_PP_EQUAL(j, BOOST_PP_SEQ_ELEM(0, row)), SF_DIAGONAL_VALUE, \
               SF_DIAGONAL_ZERO)(row)
#define SF_DIAGONAL_VALUE(row) (BOOST_PP_SEQ_ELEM(1, row))
#define SF_DIAGONAL_ZERO(row) (0)

// clang-format on
