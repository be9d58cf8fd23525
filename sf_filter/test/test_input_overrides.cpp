// Tests of the run-time overrides of the per-input options (node parameters, replay options):
// what they change and what they refuse.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sf_filter/core/input_overrides.hpp"

namespace {

using sf_filter::AlignmentPolicy;
using sf_filter::InputCapabilities;
using sf_filter::InputOptions;

InputCapabilities predictingFilter() {
  InputCapabilities can;
  can.canPredict = true;
  can.hasStamp = {true, false};
  can.names = {"vision x", "wheel data"};
  return can;
}

template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(InputOverrides, ChangeTheNamedInputOnly) {
  std::vector<InputOptions> inputs(2);
  const InputCapabilities can = predictingFilter();
  sf_filter::overrideAlignment(inputs, 1, "FILL 0.001 5 0.2", can);
  sf_filter::overrideGate(inputs, 0, 6.63, can);
  sf_filter::overrideAlignByStamp(inputs, 0, true, can);
  EXPECT_EQ(inputs[0].alignment, AlignmentPolicy::average());
  EXPECT_EQ(inputs[1].alignment, AlignmentPolicy::fill(0.001, 5, 0.2));
  EXPECT_DOUBLE_EQ(inputs[0].gateThreshold, 6.63);
  EXPECT_FALSE(inputs[1].gated());
  EXPECT_TRUE(inputs[0].alignByStamp);
  EXPECT_FALSE(inputs[1].alignByStamp);
  sf_filter::overrideGate(inputs, 0, 0.0, can);  // 0 removes the gate
  EXPECT_FALSE(inputs[0].gated());
}

TEST(InputOverrides, RefuseWhatTheInputOrMethodCannotDo) {
  std::vector<InputOptions> inputs(2);
  InputCapabilities can = predictingFilter();
  EXPECT_EQ(errorOf([&] { sf_filter::overrideAlignment(inputs, 2, "LAST", can); }),
            "input index 2 is out of range, expected 0 to 1");
  EXPECT_EQ(errorOf([&] { sf_filter::overrideAlignByStamp(inputs, 1, true, can); }),
            "input 1 (wheel data): its message type has no header.stamp to align by");
  EXPECT_NE(errorOf([&] {
              sf_filter::overrideGate(inputs, 0, -1.0, can);
            }).find("gate threshold must be a finite number > 0, or 0 for no gate"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              sf_filter::overrideAlignment(inputs, 0, "HOLD CUBIC 1", can);
            }).find("unknown hold primitive 'CUBIC'"),
            std::string::npos);
  can.canPredict = false;  // an averaging method
  EXPECT_NE(errorOf([&] {
              sf_filter::overrideGate(inputs, 0, 9.0, can);
            }).find("input 0 (vision x): a gate needs the predicted measurement"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              sf_filter::overrideAlignment(inputs, 1, "FILL 0.001 5", can);
            }).find("input 1 (wheel data): FILL needs the predicted measurement"),
            std::string::npos);
  EXPECT_NO_THROW(sf_filter::overrideGate(inputs, 0, 0.0, can));
  EXPECT_NO_THROW(sf_filter::overrideAlignment(inputs, 1, "HOLD TAYLOR 1", can));
  // Nothing refused was applied.
  EXPECT_EQ(inputs[0].alignment, AlignmentPolicy::average());
  EXPECT_FALSE(inputs[0].gated());
}

TEST(InputOverrides, InputsNamedByIndexOrRecordName) {
  InputCapabilities can = predictingFilter();
  // Thesis syntax: no record names, only indices.
  EXPECT_EQ(sf_filter::inputIndexOf("1", can), 1);
  EXPECT_EQ(errorOf([&] { sf_filter::inputIndexOf("wheel", can); }),
            "input 'wheel' is neither an input index nor an input name (this header has no "
            "INPUTS records)");
  // INPUTS records: the record name or the index, and the override acts on that input.
  can.keys = {"vision_x", "wheel"};
  EXPECT_EQ(sf_filter::inputIndexOf("wheel", can), 1);
  EXPECT_EQ(sf_filter::inputIndexOf("vision_x", can), 0);
  EXPECT_EQ(sf_filter::inputIndexOf("0", can), 0);
  EXPECT_EQ(errorOf([&] { sf_filter::inputIndexOf("Wheel", can); }),
            "input 'Wheel' is neither an input index nor one of the input names vision_x, wheel");
  EXPECT_EQ(errorOf([&] { sf_filter::inputIndexOf("1x", can); }),
            "input '1x' is neither an input index nor one of the input names vision_x, wheel");
  std::vector<InputOptions> inputs(2);
  sf_filter::overrideGate(inputs, sf_filter::inputIndexOf("wheel", can), 4.0, can);
  EXPECT_EQ(inputs[1].gateThreshold, 4.0);
  EXPECT_FALSE(inputs[0].gated());
}

TEST(InputOverrides, LagMustBeFiniteAndNotNegative) {
  EXPECT_DOUBLE_EQ(sf_filter::checkedLagMs(0.0), 0.0);
  EXPECT_DOUBLE_EQ(sf_filter::checkedLagMs(25.0), 25.0);
  EXPECT_THROW(sf_filter::checkedLagMs(-1.0), std::invalid_argument);
  EXPECT_THROW(sf_filter::checkedLagMs(NAN), std::invalid_argument);
}

TEST(InputOverrides, TimeoutsInMillisecondsWithZeroForNone) {
  std::vector<InputOptions> inputs(2);
  const InputCapabilities can = predictingFilter();
  sf_filter::overrideTimeout(inputs, 1, 250.0, can);
  EXPECT_DOUBLE_EQ(inputs[1].timeout, 0.25);
  EXPECT_FALSE(inputs[0].hasTimeout());
  sf_filter::overrideTimeout(inputs, 1, 0.0, can);
  EXPECT_FALSE(inputs[1].hasTimeout());
  EXPECT_EQ(errorOf([&] { sf_filter::overrideTimeout(inputs, 0, -5.0, can); }),
            "input 0 (vision x): timeout must be a finite number of ms > 0, or 0 for no timeout, "
            "got -5.000000");
  EXPECT_NE(errorOf([&] { sf_filter::overrideTimeout(inputs, 0, std::nan(""), can); }), "no error");
  EXPECT_EQ(errorOf([&] { sf_filter::overrideTimeout(inputs, 3, 1.0, can); }),
            "input index 3 is out of range, expected 0 to 1");
}

TEST(InputOverrides, RangesNeedMinimumBelowMaximum) {
  std::vector<InputOptions> inputs(2);
  const InputCapabilities can = predictingFilter();
  sf_filter::overrideRange(inputs, 0, -2.0, 3.0, can);
  EXPECT_TRUE(inputs[0].inRange(3.0));
  EXPECT_FALSE(inputs[0].inRange(3.5));
  EXPECT_FALSE(inputs[1].hasRange());
  EXPECT_EQ(errorOf([&] { sf_filter::overrideRange(inputs, 1, 3.0, 3.0, can); }),
            "input 1 (wheel data): plausible range needs minimum < maximum, got [3.000000, "
            "3.000000]");
  EXPECT_NE(errorOf([&] { sf_filter::overrideRange(inputs, 1, std::nan(""), 3.0, can); }),
            "no error");
  EXPECT_EQ(inputs[1].maximum, std::numeric_limits<double>::infinity());  // left as it was
}

TEST(InputOverrides, FutureStampToleranceIsNotNegative) {
  EXPECT_DOUBLE_EQ(sf_filter::checkedFutureStampMs(500.0), 500.0);
  EXPECT_EQ(errorOf([] { sf_filter::checkedFutureStampMs(-1.0); }),
            "maximum future stamp must be a number of ms >= 0, got -1.000000");
}

}  // namespace
