// Unit tests of JumpHold (jump_hold.hpp) with the fusion core, driven as FusionNode drives
// them: every message is one clock reading (advance, then the value), the timer another. The
// reference is the train's Kalman filter stepped by hand with the values of each period by
// the time they were sent, as the offline replay places them (issue 15: the node paused
// under load and put a pause's values into one period).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sf_filter/core/jump_hold.hpp"
#include "train_core.hpp"

namespace {

using namespace train_core;
using sf_filter::JumpHold;

constexpr double kNoStamp = std::numeric_limits<double>::quiet_NaN();

/// The node's clock handling (FusionNode): with a JumpHold (the fix) or advancing to every
/// reading.
struct Node {
  explicit Node(bool withHold) : core(makeCore()), hold(kPeriod), withHold(withHold) {}
  void read(double reading) {
    if (!withHold) {
      core.advanceTo(reading, out);
      return;
    }
    const bool held = hold.holding();
    if (!hold.admit(reading, core.clock(), core.periodsDue(reading))) return;
    if (held) {
      hold.placeKept([this](const JumpHold::Kept& v, double time) {
        if (v.control) {
          core.addControl(v.index, v.value, time);
        } else {
          core.addMeasurement(v.index, time, v.value, v.variance, kNoStamp);
        }
      });
    }
    core.advanceTo(reading, out);
  }
  void value(estimation::Index input, double reading, double v, double stamp) {
    read(reading);
    if (hold.holding() && !JumpHold::stamped(stamp)) {
      hold.keep({false, input, v, std::nullopt});
    } else {
      core.addMeasurement(input, withHold ? hold.placement(reading, stamp) : reading, v,
                          std::nullopt, stamp);
    }
  }
  void control(double reading, double u) {
    read(reading);
    if (hold.holding()) {
      hold.keep({true, 0, u, std::nullopt});
    } else {
      core.addControl(0, u);
    }
  }
  Core core;
  JumpHold hold;
  bool withHold;
  Collector out;
};

Vector<1> control(double u) { return Vector<1>::Constant(u); }

// The node reads values until 0.12 s, then gets no CPU until 0.45 s. When it runs again, roscpp
// has read /clock first: every value sent in the pause carries the reading 0.45, one
// connection after the other - the speeds (input 0: four stamped, one not), the accelerations
// (input 1, unstamped), the controls. The hold keeps the periods ending at 0.2, 0.3 and 0.4
// open; a stamped speed goes into the period of its stamp, the n unstamped values of an
// input (the n controls) to the k-th n-th of [0.12, 0.45] (accelerations at 0.23, 0.34, 0.45;
// controls at 0.285, 0.45; the single unstamped speed at 0.45), and the timer's 0.5 s ends the
// hold and estimates periods 2 to 5 with them.
TEST(JumpHold, APausedNodePlacesTheValuesSentInThePauseOverThePause) {
  for (const bool withHold : {true, false}) {
    Node node(withHold);
    node.read(0.0);
    node.value(0, 0.02, 1.0, 0.02);
    node.value(1, 0.05, 0.5, 0.05);
    node.read(0.1);  // the timer: period 1
    node.value(0, 0.12, 1.5, 0.12);
    for (const auto& [v, stamp] : {std::pair{2.0, 0.13}, {3.0, 0.23}, {4.0, 0.33}, {5.0, 0.43}}) {
      node.value(0, 0.45, v, stamp);
    }
    node.value(0, 0.45, 7.0, kNoStamp);
    for (double a : {0.6, 0.7, 0.8}) node.value(1, 0.45, a, kNoStamp);
    node.control(0.45, 1.0);
    node.control(0.45, 2.0);
    if (withHold) {
      EXPECT_TRUE(node.hold.holding());
      EXPECT_EQ(node.out.estimates.size(), 1u);  // the periods of the pause wait
    }
    node.read(0.5);  // the timer
    ASSERT_EQ(node.out.estimates.size(), 5u);
    Train reference = makeTrain();
    reference.estimate(speedAndAcceleration(1.0, 0.5));
    expectSameBelief(node.out.estimates[0], reference);
    if (!withHold) {
      // As before the fix: periods 2 to 4 were estimated at the jump with the speed 1.5 alone
      // and nothing, and the pause's values all went into period 5.
      reference.estimate(speedOnly(1.5));
      expectSameBelief(node.out.estimates[1], reference);
      reference.estimate(Measurement<2>::missing());
      reference.estimate(Measurement<2>::missing());
      reference.setControl(control(2.0));
      reference.estimate(speedAndAcceleration((2.0 + 3.0 + 4.0 + 5.0 + 7.0) / 5, 0.7));
      expectSameBelief(node.out.estimates[4], reference);
      continue;
    }
    EXPECT_FALSE(node.hold.holding());
    EXPECT_EQ(node.hold.holds(), 1u);
    reference.estimate(speedOnly((1.5 + 2.0) / 2));
    expectSameBelief(node.out.estimates[1], reference);
    reference.setControl(control(1.0));
    reference.estimate(speedAndAcceleration(3.0, 0.6));
    expectSameBelief(node.out.estimates[2], reference);
    reference.estimate(speedAndAcceleration(4.0, 0.7));
    expectSameBelief(node.out.estimates[3], reference);
    reference.setControl(control(2.0));
    reference.estimate(speedAndAcceleration((5.0 + 7.0) / 2, 0.8));
    expectSameBelief(node.out.estimates[4], reference);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(node.out.estimates[k].time, kPeriod * (k + 1), 1e-12);
  }
}

// What is not a jump, and how a hold ends besides a later reading.
TEST(JumpHold, OnlyAPauseLongerThanAPeriodIsHeldAndEveryHoldEnds) {
  JumpHold hold(kPeriod);
  // Before the schedule started nothing is due: the first reading is no jump.
  EXPECT_TRUE(hold.admit(1.7e9, 0.0, 0));
  // The timer's readings one period apart (the scheduled ends) are no jump.
  EXPECT_TRUE(hold.admit(0.2, 0.1, 1));
  EXPECT_FALSE(hold.holding());
  // A stamp outside a hold stays at its reading.
  EXPECT_EQ(hold.placement(0.25, 0.21), 0.25);
  // A jump: held, and every reading within it too.
  EXPECT_FALSE(hold.admit(0.5, 0.2, 3));
  EXPECT_FALSE(hold.admit(0.5, 0.2, 3));
  EXPECT_FALSE(hold.admit(0.3, 0.2, 1));
  // Stamps within [0.2, 0.5]; earlier ones at 0.2, later ones (a fast sensor clock) at 0.5;
  // an unset stamp (0, ROS) or none at the reading.
  EXPECT_EQ(hold.placement(0.5, 0.31), 0.31);
  EXPECT_EQ(hold.placement(0.5, 0.1), 0.2);
  EXPECT_EQ(hold.placement(0.5, 0.7), 0.5);
  EXPECT_EQ(hold.placement(0.5, 0.0), 0.5);
  EXPECT_EQ(hold.placement(0.5, kNoStamp), 0.5);
  // A reading before the hold's start (the clock ran backwards: a restarted bag) ends it, so
  // that the core sees the jump backwards.
  EXPECT_TRUE(hold.admit(0.05, 0.2, 0));
  EXPECT_FALSE(hold.holding());
  // A clock that stops after the jump: release() ends the hold at the held reading.
  EXPECT_FALSE(hold.admit(0.9, 0.5, 4));
  EXPECT_EQ(hold.release(), 0.9);
  EXPECT_FALSE(hold.holding());
  EXPECT_EQ(hold.holds(), 2u);
}

}  // namespace
