// Tests of the per-input options generated from INPUT_TIMEOUT and INPUT_RANGE
// (sf_filter/config/detail/input_faults.hpp): test_config_alignment.h's five inputs with
// timeouts on two of them and ranges on two, carried into defaultInputOptions() in seconds.
#include "test_config_alignment.h"
#define INPUT_TIMEOUT ((4)(250))((1)(1500))
#define INPUT_RANGE ((0)(-5)(5.5))((2)(0)(1e9))
#include <sf_filter/config/configuration.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace {

static_assert(sf_config::kHasInputTimeout && sf_config::kHasInputRange, "both macros defined");
static_assert(sf_config::kInputTimeoutsMs[4] == 250.0, "the timeouts are compile-time constants");

TEST(ConfigFaults, TimeoutsPerInputInMilliseconds) {
  EXPECT_DOUBLE_EQ(sf_config::kInputTimeoutsMs[1], 1500.0);
  EXPECT_DOUBLE_EQ(sf_config::kInputTimeoutsMs[4], 250.0);
  for (int i : {0, 2, 3}) EXPECT_TRUE(std::isinf(sf_config::kInputTimeoutsMs[i])) << i;
}

TEST(ConfigFaults, RangesPerInputUnboundedForTheUnlisted) {
  EXPECT_DOUBLE_EQ(sf_config::kInputRanges[0].minimum, -5.0);
  EXPECT_DOUBLE_EQ(sf_config::kInputRanges[0].maximum, 5.5);
  EXPECT_DOUBLE_EQ(sf_config::kInputRanges[2].minimum, 0.0);
  EXPECT_DOUBLE_EQ(sf_config::kInputRanges[2].maximum, 1e9);
  for (int i : {1, 3, 4}) {
    EXPECT_TRUE(std::isinf(sf_config::kInputRanges[i].minimum) &&
                sf_config::kInputRanges[i].minimum < 0)
        << i;
    EXPECT_TRUE(std::isinf(sf_config::kInputRanges[i].maximum) &&
                sf_config::kInputRanges[i].maximum > 0)
        << i;
  }
}

TEST(ConfigFaults, DefaultInputOptionsCarryThemInSeconds) {
  const std::vector<sf_filter::InputOptions> inputs = sf_config::defaultInputOptions();
  ASSERT_EQ(inputs.size(), 5u);
  EXPECT_DOUBLE_EQ(inputs[1].timeout, 1.5);
  EXPECT_DOUBLE_EQ(inputs[4].timeout, 0.25);
  EXPECT_FALSE(inputs[0].hasTimeout());
  EXPECT_TRUE(inputs[0].hasRange());
  EXPECT_FALSE(inputs[0].inRange(5.6));
  EXPECT_TRUE(inputs[0].inRange(-5.0));
  EXPECT_FALSE(inputs[3].hasRange());
  // The alignment options are still there.
  EXPECT_DOUBLE_EQ(inputs[0].gateThreshold, 9.0);
  EXPECT_TRUE(inputs[3].alignByStamp);
  for (const auto& o : inputs) EXPECT_TRUE(sf_filter::inputOptionsProblem(o).empty());
}

}  // namespace
