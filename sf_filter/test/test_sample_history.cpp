// Tests of the fixed-size sample history (the shift register of the multi-rate hold).
#include <gtest/gtest.h>

#include "sf_filter/core/alignment/sample_history.hpp"

namespace {

using sf_filter::SampleHistory;

TEST(SampleHistory, KeepsTheNewestSamplesNewestFirst) {
  SampleHistory h(3);
  EXPECT_TRUE(h.empty());
  for (int k = 1; k <= 5; ++k) h.push(0.1 * k, 10.0 * k);
  ASSERT_EQ(h.size(), 3);
  EXPECT_TRUE(h.full());
  EXPECT_DOUBLE_EQ(h[0].value, 50.0);
  EXPECT_DOUBLE_EQ(h[1].value, 40.0);
  EXPECT_DOUBLE_EQ(h[2].value, 30.0);
  EXPECT_DOUBLE_EQ(h[2].time, 0.3);
}

TEST(SampleHistory, ASampleAtTheNewestTimeReplacesItAndAnOlderOneIsIgnored) {
  SampleHistory h(4);
  h.push(1.0, 1.0);
  h.push(2.0, 2.0);
  EXPECT_TRUE(h.push(2.0, 5.0));
  EXPECT_FALSE(h.push(1.5, 9.0));
  ASSERT_EQ(h.size(), 2);
  EXPECT_DOUBLE_EQ(h[0].value, 5.0);
  EXPECT_DOUBLE_EQ(h[1].value, 1.0);
}

TEST(SampleHistory, WrapsAroundTheFullCapacity) {
  SampleHistory h(SampleHistory::kCapacity);
  for (int k = 0; k < 3 * SampleHistory::kCapacity + 1; ++k) h.push(k, k);
  ASSERT_EQ(h.size(), SampleHistory::kCapacity);
  for (int age = 0; age < h.size(); ++age) {
    EXPECT_DOUBLE_EQ(h[age].value, 3 * SampleHistory::kCapacity - age);
  }
  h.clear();
  EXPECT_TRUE(h.empty());
}

TEST(SampleHistory, ClampsTheLength) {
  EXPECT_EQ(SampleHistory(0).length(), 1);
  EXPECT_EQ(SampleHistory(100).length(), SampleHistory::kCapacity);
}

}  // namespace
