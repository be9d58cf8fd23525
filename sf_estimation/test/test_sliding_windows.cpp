// Tests of SlidingWindows: per-channel ring buffers of the last `capacity` values.
#include <string>

#include <gtest/gtest.h>

#include "sf_estimation/errors.hpp"
#include "sf_estimation/sliding_windows.hpp"

namespace {

using estimation::ParameterError;
using estimation::SlidingWindows;

TEST(SlidingWindows, KeepsTheLastCapacityValuesNewestFirst) {
  SlidingWindows windows(2, 3);
  EXPECT_EQ(windows.count(0), 0);
  for (double v : {1.0, 2.0, 3.0, 4.0, 5.0}) windows.push(0, v);
  windows.push(1, 7.0);
  // channel 0 pushed 1..5 into 3 slots: holds 5, 4, 3 (newest first)
  ASSERT_EQ(windows.count(0), 3);
  EXPECT_EQ(windows.value(0, 0), 5.0);
  EXPECT_EQ(windows.value(0, 1), 4.0);
  EXPECT_EQ(windows.value(0, 2), 3.0);
  // channel 1 is independent
  ASSERT_EQ(windows.count(1), 1);
  EXPECT_EQ(windows.value(1, 0), 7.0);
}

TEST(SlidingWindows, ClearEmptiesEveryChannel) {
  SlidingWindows windows(1, 2);
  windows.push(0, 1.0);
  windows.push(0, 2.0);
  windows.push(0, 3.0);
  windows.clear();
  EXPECT_EQ(windows.count(0), 0);
  windows.push(0, 9.0);
  ASSERT_EQ(windows.count(0), 1);
  EXPECT_EQ(windows.value(0, 0), 9.0);
}

TEST(SlidingWindows, RejectsAnEmptyCapacity) {
  try {
    SlidingWindows windows(1, 0);
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("capacity"), std::string::npos) << e.what();
  }
}

}  // namespace
