// Unit tests of the first readings (FusionCoreOptions::initialFromInputs,
// INITIAL_STATE_FROM_INPUTS): a state variable takes its input's first aligned value before the
// step of the first period that has one, with its covariance kept; later periods and other
// inputs do not touch it; a reset arms it again; bad indices are refused. The reference is the
// same Kalman filter whose belief is set by hand. A particle filter takes the reading's own
// variance instead (its reference: the same particle filter set by hand).
#include <gtest/gtest.h>

#include <sf_estimation/errors.hpp>
#include <sf_estimation/models/moving_train.hpp>
#include <sf_estimation/particle_filter.hpp>

#include "train_core.hpp"

namespace {

using namespace train_core;

/// The train's core with the acceleration (state 1) from input 1's first reading.
Core firstReadingCore() {
  Core::Options options;
  options.period = kPeriod;
  options.initialFromInputs.push_back({1, 1});
  return Core(makeTrain(), options);
}

/// `reference` with state `i` set to `value`, its covariance kept.
void setState(Train& reference, int i, double value) {
  Vector<2> x = reference.state();
  x(i) = value;
  reference.setBelief(x, reference.covariance());
}

TEST(FirstReadings, AStateTakesItsInputsFirstValueBeforeTheStep) {
  Core core = firstReadingCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(0, 0.05, 2.0);  // speed only: the acceleration stays at x0
  core.advanceTo(0.1, out);
  core.addMeasurement(1, 0.15, 0.8);  // the first acceleration
  core.addMeasurement(1, 0.16, 0.6);  // averaged with it: 0.7
  core.advanceTo(0.2, out);
  core.addMeasurement(1, 0.25, 0.1);  // later readings are measurements only
  core.advanceTo(0.3, out);
  Train reference = makeTrain();
  reference.estimate(speedOnly(2.0));
  expectSameBelief(out.estimates.at(0), reference);
  setState(reference, 1, 0.7);
  Measurement<2> z = accelerationOnly(0.7);
  reference.estimate(z);
  expectSameBelief(out.estimates.at(1), reference);
  reference.estimate(accelerationOnly(0.1));
  expectSameBelief(out.estimates.at(2), reference);
  // Without the option the second period starts from the predicted acceleration instead.
  Train plain = makeTrain();
  plain.estimate(speedOnly(2.0));
  plain.estimate(accelerationOnly(0.7));
  EXPECT_GT(std::abs(plain.state()(0) - out.estimates.at(1).state(0)), 1e-3);
}

TEST(FirstReadings, AResetArmsThemAgain) {
  Core core = firstReadingCore();
  Collector out;
  core.advanceTo(0.0, out);
  core.addMeasurement(1, 0.05, 0.5);
  core.advanceTo(0.1, out);
  core.reset();
  core.addMeasurement(1, 0.15, -0.4);
  core.advanceTo(0.2, out);
  Train reference = makeTrain();
  setState(reference, 1, -0.4);
  reference.estimate(accelerationOnly(-0.4));
  expectSameBelief(out.estimates.back(), reference);
}

TEST(FirstReadings, RefusesIndicesOutsideTheStateOrTheInputs) {
  Core::Options options;
  options.period = kPeriod;
  options.initialFromInputs.push_back({2, 0});  // the train has 2 state variables
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
  options.initialFromInputs = {{0, 2}};  // ... and 2 inputs
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
  options.initialFromInputs = {{0, -1}};
  EXPECT_THROW(Core(makeTrain(), options), estimation::ParameterError);
}

using TrainPf = estimation::ParticleFilterSIR<estimation::models::MovingTrain>;

TrainPf makeTrainPf() {
  estimation::ParticleFilterParameters params;
  params.particles = 4000;
  params.seed = 5;
  const Matrix<2, 2> Q = Matrix<2, 2>::Identity() * 0.01;
  return TrainPf(estimation::models::MovingTrain{}, Q, trainR(), Vector<2>(0, 0),
                 Matrix<2, 2>::Identity(), params);
}

TEST(FirstReadings, AParticleFilterStartsFromTheReadingsOwnVariance) {
  Core::Options options;
  options.period = kPeriod;
  options.initialFromInputs.push_back({1, 1});
  sf_filter::FusionCore<TrainPf> core(makeTrainPf(), options);
  std::vector<sf_filter::FusionCore<TrainPf>::Estimate> out;
  auto collect = [&](const auto& e) { out.push_back(e); };
  core.advanceTo(0.0, collect);
  core.addMeasurement(1, 0.05, 0.7);
  core.advanceTo(0.1, collect);
  ASSERT_EQ(out.size(), 1u);
  // By hand: the acceleration at the reading with R's 0.2, uncorrelated, then the step.
  TrainPf reference = makeTrainPf();
  Vector<2> x = reference.state();
  Matrix<2, 2> P = reference.covariance();
  x(1) = 0.7;
  P(0, 1) = P(1, 0) = 0.0;
  P(1, 1) = 0.2;
  reference.setBelief(x, P);
  reference.estimate(accelerationOnly(0.7));
  EXPECT_EQ(out[0].state, reference.state());
  EXPECT_EQ(out[0].covariance, reference.covariance());
  // The reading is weighed by particles that already lie around it: the weights stay even.
  EXPECT_GT(reference.effectiveSampleSize(), 0.5 * 4000);
  // Kept P0 (variance 1 against R 0.2): the first step leaves far fewer effective particles.
  TrainPf kept = makeTrainPf();
  Vector<2> y = kept.state();
  y(1) = 0.7;
  kept.setBelief(y, kept.covariance());
  kept.estimate(accelerationOnly(0.7));
  EXPECT_LT(kept.effectiveSampleSize(), reference.effectiveSampleSize() - 0.05 * 4000);
}

}  // namespace
