// Tests of the alignment policy's text form (runtime parameters, --align) and validation.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sf_filter/core/alignment/alignment_policy.hpp"
#include "sf_filter/core/input_options.hpp"

namespace {

using sf_filter::AlignmentKind;
using sf_filter::AlignmentPolicy;
using sf_filter::HoldPrimitive;
using sf_filter::parseAlignmentPolicy;

TEST(AlignmentPolicy, ParsesEveryPolicy) {
  EXPECT_EQ(parseAlignmentPolicy("AVERAGE"), AlignmentPolicy::average());
  EXPECT_EQ(parseAlignmentPolicy("  LAST "), AlignmentPolicy::last());
  EXPECT_EQ(parseAlignmentPolicy("SAMPLED"), AlignmentPolicy::sampled());
  EXPECT_EQ(parseAlignmentPolicy("HOLD TAYLOR 2"), AlignmentPolicy::hold(HoldPrimitive::Taylor, 2));
  EXPECT_EQ(parseAlignmentPolicy("HOLD BEZIER 3 0.5"),
            AlignmentPolicy::hold(HoldPrimitive::Bezier, 3, 0.5));
  EXPECT_EQ(parseAlignmentPolicy("FILL 0.001 5"), AlignmentPolicy::fill(0.001, 5));
  EXPECT_EQ(parseAlignmentPolicy("FILL 1e-3 5 0.1"), AlignmentPolicy::fill(0.001, 5, 0.1));
  const AlignmentPolicy p = parseAlignmentPolicy("HOLD LAGRANGE 1");
  EXPECT_EQ(p.kind, AlignmentKind::Hold);
  EXPECT_EQ(p.primitive, HoldPrimitive::Lagrange);
  EXPECT_EQ(p.order, 1);
  EXPECT_FALSE(p.variance.has_value());
}

TEST(AlignmentPolicy, TextFormRoundTrips) {
  for (const char* text : {"AVERAGE", "LAST", "SAMPLED", "HOLD LAGRANGE 0", "HOLD TAYLOR 2 0.25",
                           "FILL 0.001 5", "FILL 0.002 3 0.1"}) {
    EXPECT_EQ(toString(parseAlignmentPolicy(text)), text);
  }
}

/// The message of the std::invalid_argument thrown for `text`.
std::string errorOf(const std::string& text) {
  try {
    parseAlignmentPolicy(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(AlignmentPolicy, RefusesMalformedTextNamingTheProblem) {
  EXPECT_NE(errorOf("").find("empty"), std::string::npos);
  EXPECT_NE(errorOf("MEAN").find("unknown alignment policy 'MEAN'"), std::string::npos);
  EXPECT_NE(errorOf("last").find("unknown alignment policy"), std::string::npos);
  EXPECT_NE(errorOf("LAST 1").find("LAST takes 0 arguments"), std::string::npos);
  EXPECT_NE(errorOf("HOLD 2").find("HOLD takes 2 or 3 arguments"), std::string::npos);
  EXPECT_NE(errorOf("HOLD SPLINE 2").find("unknown hold primitive 'SPLINE'"), std::string::npos);
  EXPECT_NE(errorOf("HOLD TAYLOR two").find("order 'two' is not a number"), std::string::npos);
  EXPECT_NE(errorOf("HOLD TAYLOR 1.5").find("order '1.5' is not an integer"), std::string::npos);
  EXPECT_NE(errorOf("HOLD TAYLOR 16").find("HOLD order 16 is out of range, expected 0 to 15"),
            std::string::npos);
  EXPECT_NE(errorOf("FILL 0 5").find("FILL omega must be a positive number"), std::string::npos);
  EXPECT_NE(errorOf("FILL 0.001 0").find("FILL N (stored samples) 0 is out of range"),
            std::string::npos);
  EXPECT_NE(errorOf("FILL 0.001 5 -1").find("FILL variance must be positive"), std::string::npos);
  EXPECT_NE(errorOf("FILL 0.001x 5").find("omega '0.001x' is not a number"), std::string::npos);
}

TEST(AlignmentPolicy, PropertiesOfEachKind) {
  EXPECT_FALSE(AlignmentPolicy::average().substitutes());
  EXPECT_FALSE(AlignmentPolicy::sampled().substitutes());
  EXPECT_TRUE(AlignmentPolicy::hold(HoldPrimitive::Bezier, 2).substitutes());
  EXPECT_EQ(AlignmentPolicy::hold(HoldPrimitive::Bezier, 2).historyLength(), 3);
  EXPECT_FALSE(AlignmentPolicy::hold(HoldPrimitive::Bezier, 2).needsPrediction());
  EXPECT_TRUE(AlignmentPolicy::fill(0.001, 5).needsPrediction());
  EXPECT_EQ(AlignmentPolicy::fill(0.001, 5).historyLength(), 5);
  EXPECT_EQ(AlignmentPolicy::last().historyLength(), 0);
}

TEST(InputOptions, RefusesANonPositiveGate) {
  sf_filter::InputOptions o;
  EXPECT_TRUE(sf_filter::inputOptionsProblem(o).empty());
  o.gateThreshold = 0.0;
  EXPECT_NE(sf_filter::inputOptionsProblem(o).find("gate threshold must be positive"),
            std::string::npos);
  o.gateThreshold = 9.0;
  o.alignment = AlignmentPolicy::hold(HoldPrimitive::Taylor, -1);
  EXPECT_NE(sf_filter::inputOptionsProblem(o).find("HOLD order -1"), std::string::npos);
}

}  // namespace
