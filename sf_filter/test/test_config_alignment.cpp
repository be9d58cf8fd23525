// Tests of the per-input options generated from INPUT_ALIGNMENT, INPUT_GATE, ALIGN_BY_STAMP and
// MAX_MEASUREMENT_LAG (sf_filter/config/detail/input_alignment.hpp) for test_config_alignment.h.
#include "test_config_alignment.h"
#include <sf_filter/config/configuration.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace {

using sf_filter::AlignmentPolicy;
using sf_filter::HoldPrimitive;

static_assert(sf_config::kHasInputAlignment && sf_config::kHasInputGate &&
                  sf_config::kHasAlignByStamp,
              "the header defines all three");
static_assert(sf_config::kInputAlignment[3].kind == sf_filter::AlignmentKind::Sampled,
              "the policies are compile-time constants");

TEST(ConfigAlignment, PoliciesPerInputWithAverageForTheUnlisted) {
  EXPECT_EQ(sf_config::kInputAlignment[0], AlignmentPolicy::fill(0.001, 5, 0.05));
  EXPECT_EQ(sf_config::kInputAlignment[1], AlignmentPolicy::hold(HoldPrimitive::Bezier, 2));
  EXPECT_EQ(sf_config::kInputAlignment[2], AlignmentPolicy::last());
  EXPECT_EQ(sf_config::kInputAlignment[3], AlignmentPolicy::sampled());
  EXPECT_EQ(sf_config::kInputAlignment[4], AlignmentPolicy::average());
}

TEST(ConfigAlignment, GatesStampsAndLag) {
  EXPECT_DOUBLE_EQ(sf_config::kGateThresholds[0], 9.0);
  EXPECT_DOUBLE_EQ(sf_config::kGateThresholds[3], 6.63);
  for (int i : {1, 2, 4}) EXPECT_TRUE(std::isinf(sf_config::kGateThresholds[i])) << i;
  const bool byStamp[] = {true, false, false, true, false};
  const bool hasStamp[] = {true, false, false, true, true};
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(sf_config::kAlignByStamp[i], byStamp[i]) << i;
    EXPECT_EQ(sf_config::kInputHasStamp[i], hasStamp[i]) << i;
  }
  EXPECT_DOUBLE_EQ(sf_config::kMaxMeasurementLagMs, 40.0);
}

TEST(ConfigAlignment, DefaultInputOptionsCarryAllOfIt) {
  const std::vector<sf_filter::InputOptions> inputs = sf_config::defaultInputOptions();
  ASSERT_EQ(inputs.size(), 5u);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_EQ(inputs[i].alignment, sf_config::kInputAlignment[i]) << i;
    EXPECT_EQ(inputs[i].gateThreshold, sf_config::kGateThresholds[i]) << i;
    EXPECT_EQ(inputs[i].alignByStamp, sf_config::kAlignByStamp[i]) << i;
    EXPECT_TRUE(sf_filter::inputOptionsProblem(inputs[i]).empty()) << i;
  }
}

}  // namespace
