// The settle rule (SwingLog, swing/swing_log.h) on hand-made event sequences: the swing
// ends at the last entry into the zone that is followed by the settle dwell inside it.
#include <gtest/gtest.h>

#include "swing/swing_log.h"

namespace swingsim {
namespace {

constexpr double kDwell = 0.1;  // s
constexpr double kZone = 0.1;   // rad
constexpr double kPeak = 1.0;   // rad, above the zone

TEST(SwingEvents, EndIsTheEntryConfirmedByTheDwell) {
  SwingLog log(kDwell);
  log.onThighAtTarget(0.10);
  log.onKneePeak(0.20, kPeak, kZone);
  log.onKneeZone(0.30, true);
  ASSERT_TRUE(log.candidate);
  log.confirmUntil(0.30 + 0.5 * kDwell);
  EXPECT_FALSE(log.ended);
  log.confirmUntil(0.30 + kDwell);
  ASSERT_TRUE(log.ended);
  EXPECT_DOUBLE_EQ(log.endTime, 0.30);
  EXPECT_EQ(log.events.back().name, "swing_end");
}

TEST(SwingEvents, ABounceMovesTheEndToTheNextEntry) {
  SwingLog log(kDwell);
  log.onThighAtTarget(0.10);
  log.onKneePeak(0.20, kPeak, kZone);
  log.onKneeZone(0.30, true);
  log.onKneeZone(0.35, false);  // out again before the dwell has passed
  EXPECT_FALSE(log.candidate);
  log.onKneePeak(0.37, 0.2, kZone);  // the bounce's top
  log.onKneeZone(0.40, true);
  log.confirmUntil(0.40 + kDwell);
  ASSERT_TRUE(log.ended);
  EXPECT_DOUBLE_EQ(log.endTime, 0.40);
  EXPECT_EQ(log.bounces, 1);
  EXPECT_EQ(log.bounceHeight, 0.2);
  ASSERT_TRUE(log.peak);
  EXPECT_DOUBLE_EQ(log.peak->flexion, kPeak);
  EXPECT_DOUBLE_EQ(log.peak->time, 0.20);
}

TEST(SwingEvents, NoPeakAboveTheZoneLeavesThePeakAbsent) {
  SwingLog log(kDwell);
  log.onThighAtTarget(0.10);
  log.onKneePeak(0.20, 0.5 * kZone, kZone);  // a wiggle inside the zone is not a peak
  EXPECT_FALSE(log.peak);
  EXPECT_FALSE(log.bounceHeight);
}

TEST(SwingEvents, NoBouncePeakLeavesTheBounceHeightAbsent) {
  SwingLog log(kDwell);
  log.onThighAtTarget(0.10);
  log.onKneePeak(0.20, kPeak, kZone);
  log.onKneeZone(0.30, true);
  log.onKneeZone(0.35, false);  // out of the zone, and the run stops before the knee peaks
  EXPECT_EQ(log.bounces, 1);
  EXPECT_FALSE(log.bounceHeight);
  ASSERT_TRUE(log.peak);
  EXPECT_DOUBLE_EQ(log.peak->flexion, kPeak);
}

TEST(SwingEvents, AReboundOutAndBackWithinOneStepKeepsItsHeight) {
  // One step of 10 ms whose ends are both just inside the zone (knee 0.099 rad), rising at its
  // start and falling at its end (1 rad/s each way, no acceleration): the Hermite interpolant
  // peaks at 0.099 + 0.01 / 4 = 0.1015 rad at mid-step, above the zone's 0.1 rad.
  SwingLog log(kDwell);
  log.onThighAtTarget(0.05);
  log.onKneePeak(0.10, kPeak, kZone);
  log.onKneeZone(0.20, true);
  SwingEndRule rule;
  rule.zoneOfStability = kZone;
  rule.thighTargetFlexion = -1;  // the thigh already at its target, above it throughout
  // Inside the settle dwell after the entry at 0.20 s.
  const StepEnd a{0.25, 0.5, 0.099, 0, 1.0, 0, 0, 0, 0, {}};
  const StepEnd b{0.26, 0.5, 0.099, 0, -1.0, 0, 0, 0, 0, {}};
  handleStepEvents(a, b, rule, log);
  EXPECT_EQ(log.bounces, 1);
  ASSERT_TRUE(log.bounceHeight);
  EXPECT_NEAR(*log.bounceHeight, 0.1015, 1e-9);
}

TEST(SwingEvents, KneeInTheZoneBeforeTheThighWaitsForTheThigh) {
  SwingLog log(kDwell);
  log.onKneePeak(0.20, kPeak, kZone);
  log.onKneeZone(0.30, true);
  log.confirmUntil(0.30 + 2 * kDwell);
  EXPECT_FALSE(log.ended);  // no end without the thigh at its target
  log.onThighAtTarget(0.50);
  log.confirmUntil(0.50 + kDwell);
  ASSERT_TRUE(log.ended);
  EXPECT_DOUBLE_EQ(log.endTime, 0.50);
}

}  // namespace
}  // namespace swingsim
