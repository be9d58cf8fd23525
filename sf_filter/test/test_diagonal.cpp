// SF_DIAGONAL (sf_filter/config/diagonal.hpp) must expand to the diagonal matrix of its
// vector in the configuration's matrix syntax, and configuration.hpp must accept it.
#include <sf_filter/config/diagonal.hpp>

#include <vector>

#include <gtest/gtest.h>
#include <boost/preprocessor/seq/enum.hpp>
#include <boost/preprocessor/seq/for_each.hpp>

#include <sf_filter/config/detail/preprocessor.hpp>

namespace {

using Rows = std::vector<std::vector<double>>;

// A matrix sequence ((a)(b))((c)(d)) as the initializer {{a, b}, {c, d}}.
#define TEST_ROW(r, data, row) {BOOST_PP_SEQ_ENUM(row)},
#define TEST_ROWS(matrix) \
  Rows { BOOST_PP_SEQ_FOR_EACH(TEST_ROW, ~, matrix) }

TEST(Diagonal, OneByOne) {
  const Rows d = TEST_ROWS(SF_DIAGONAL((4.5)));
  EXPECT_EQ(d, Rows{{4.5}});
}

TEST(Diagonal, ThreeByThree) {
  const Rows d = TEST_ROWS(SF_DIAGONAL((1)(2)(3)));
  const Rows expected{{1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  EXPECT_EQ(d, expected);
}

TEST(Diagonal, SevenBySevenWithZerosOnTheDiagonal) {
  // The nav3ctrl Q of thesis eq. 5.20.
  const Rows q = TEST_ROWS(SF_DIAGONAL((0)(0)(0)(0.5)(0)(0)(0.3)));
  ASSERT_EQ(q.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    ASSERT_EQ(q[i].size(), 7u);
    for (std::size_t j = 0; j < 7; ++j) {
      const double expected = i != j ? 0.0 : i == 3 ? 0.5 : i == 6 ? 0.3 : 0.0;
      EXPECT_EQ(q[i][j], expected) << "entry (" << i << ", " << j << ")";
    }
  }
}

TEST(Diagonal, EntriesAreExpressions) {
  const double T = 0.1;
#define TEST_VARIANCE 2
  const Rows d = TEST_ROWS(SF_DIAGONAL((0.5 * T)(TEST_VARIANCE)((1 + 1) * 3)));
  const Rows expected{{0.05, 0, 0}, {0, 2, 0}, {0, 0, 6}};
  EXPECT_EQ(d, expected);
#undef TEST_VARIANCE
}

TEST(Diagonal, IsAMatrixForTheConfigurationChecks) {
  static_assert(SF_PP_IS_MATRIX(SF_DIAGONAL((1)(2))), "SF_DIAGONAL gives a matrix sequence");
}

}  // namespace
