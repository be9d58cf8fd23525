// Sizes that would exhaust memory are refused with a ParameterError naming the parameter
// (found by the fuzzer: particles = INT_MAX, window-size x input-count = 2^31 x 2^31 made the
// factory allocate terabytes instead of refusing).
#include <climits>
#include <string>

#include <gtest/gtest.h>

#include "factory_test_utils.hpp"

#include "sf_estimation/errors.hpp"
#include "sf_estimation/estimator_factory.hpp"

namespace {

using estimation::EstimatorFactory;
using estimation::ParameterError;

using sftest::refusal;

TEST(ParameterLimits, ParticlesWindowAndInputCount) {
  const auto model = estimation::makeFunctionModel(
      1, 1, 0, [](const auto& x, const auto&, auto& next) { next(0) = x(0); },
      [](const auto& x, auto& z) { z(0) = x(0); });
  const Eigen::MatrixXd one = Eigen::MatrixXd::Identity(1, 1);
  estimation::ParameterMap pf = {{"model", model}, {"Q", one}, {"R", one}, {"particles", 1000000}};
  EXPECT_EQ(
      refusal("ParticleFilterSIR", {{"model", model}, {"Q", one}, {"R", one}, {"particles", 3}}),
      "accepted");
  pf["particles"] = 1000001;
  EXPECT_NE(refusal("ParticleFilterSIR", pf).find("'particles' must be from 1 to 1000000"),
            std::string::npos);
  pf["particles"] = INT_MAX;
  EXPECT_NE(refusal("ParticleFilterSIR", pf).find("'particles'"), std::string::npos);

  EXPECT_EQ(refusal("MovingAverage", {{"input-count", 1000}, {"window-size", 10000}}), "accepted");
  EXPECT_NE(refusal("MovingAverage", {{"input-count", 2}, {"window-size", INT_MAX}})
                .find("'windowSize' must be from 1 to 10000"),
            std::string::npos);
  EXPECT_NE(refusal("MovingMedian", {{"input-count", 1001}, {"window-size", 3}})
                .find("'inputCount' must be from 1 to 1000"),
            std::string::npos);
}

}  // namespace
