// The state a swing starts from: a measured-thigh swing starts its knee where the record does
// (the smoothing spline's value and slope at toe-off, checked against the closed form of a
// smooth knee), the participant's initial values otherwise or when asked; and a simulated
// swing's first sample is that state.
#include "leg/toe_off_state.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

/// A smooth knee, rad: 40 deg at toe-off flexing at 300 deg/s, slowing (a cubic), at 100 Hz.
double knee(double t) { return (40 + 300 * t - 400 * t * t + 200 * t * t * t) * kDegToRad; }
constexpr double kKneeRateAtToeOff = 300 * kDegToRad;  // rad/s, knee'(0)

ThighKinematics smoothRecord() {
  ThighKinematics k;
  k.path = "smooth.csv";
  for (int i = 0; i <= 40; ++i) {
    const double t = 0.01 * i;
    k.time.push_back(t);
    k.hipFlexion.push_back((-10 + 100 * t) * kDegToRad);
    k.kneeFlexion.push_back(knee(t));
  }
  return k;
}

// A quintic spline through noise-free samples of a cubic reproduces it up to GCV's small
// smoothing: within 0.01 deg and 1 deg/s (a forward difference of the first two samples would
// be off by 4 deg/s: the cubic's curvature over one frame).
constexpr double kAngleTol = 0.01 * kDegToRad;
constexpr double kRateTol = 1 * kDegToRad;

TEST(ToeOffState, TheMeasuredKneeIsTheSplinesValueAndSlopeAtToeOff) {
  const ThighKinematics k = smoothRecord();
  const MeasuredKneeStart start = calcMeasuredKneeStart(k.path, k.time, k.kneeFlexion);
  EXPECT_NEAR(start.kneeFlexion, knee(0), kAngleTol);
  EXPECT_NEAR(start.kneeFlexionRate, kKneeRateAtToeOff, kRateTol);
}

TEST(ToeOffState, AMeasuredThighSwingStartsItsKneeFromTheRecordUnlessAsked) {
  Participant p;
  p.initial.kneeFlexion = 10 * kDegToRad;  // the resting pose the issue saw a measured swing start from
  p.initial.kneeFlexionRate = 0;
  // Hip-moment drive: the participant's values, whatever the record says.
  EXPECT_EQ(calcToeOffState(p, nullptr).kneeFlexion, p.initial.kneeFlexion);
  p.drive = SwingDrive::kThighKinematics;
  p.thighKinematics = smoothRecord();
  const ThighMotion thigh(p.thighKinematics);
  const InitialConditions measured = calcToeOffState(p, &thigh);
  EXPECT_NEAR(measured.kneeFlexion, knee(0), kAngleTol);
  EXPECT_NEAR(measured.kneeFlexionRate, kKneeRateAtToeOff, kRateTol);
  EXPECT_NEAR(measured.hipFlexion, -10 * kDegToRad, kAngleTol);
  EXPECT_NEAR(measured.hipFlexionRate, 100 * kDegToRad, kRateTol);
  p.initial.kneeStart = KneeStart::kInitial;  // the old behaviour, for comparison
  EXPECT_EQ(calcToeOffState(p, &thigh).kneeFlexion, p.initial.kneeFlexion);
  EXPECT_EQ(calcToeOffState(p, &thigh).kneeFlexionRate, p.initial.kneeFlexionRate);
  p.initial.kneeStart = KneeStart::kMeasured;
  p.thighKinematics.kneeFlexion.clear();  // a record without the knee
  EXPECT_EQ(calcToeOffState(p, &thigh).kneeFlexion, p.initial.kneeFlexion);
}

TEST(ToeOffState, ASimulatedMeasuredSwingsFirstSampleIsTheRecordsKnee) {
  Participant p = loadParticipant(kRoot + "/participants/winter.yaml");
  ASSERT_EQ(p.drive, SwingDrive::kThighKinematics);
  p.initial.kneeFlexion = 10 * kDegToRad;
  p.initial.kneeFlexionRate = 0;
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  SwingOptions options;
  options.requireSwingEnd = false;
  const SwingResult measured = simulateSwing(makeSwingSetup(p, knee), options);
  const ThighKinematics& k = p.thighKinematics;
  const MeasuredKneeStart record = calcMeasuredKneeStart(k.path, k.time, k.kneeFlexion);
  EXPECT_NEAR(measured.trajectory.kneeFlexion.front(), record.kneeFlexion, 1e-9);
  EXPECT_NEAR(measured.trajectory.kneeFlexionRate.front(), record.kneeFlexionRate, 1e-9);
  EXPECT_GT(record.kneeFlexion, 30 * kDegToRad);  // Winter's knee at toe-off: 46.7 deg
  p.initial.kneeStart = KneeStart::kInitial;
  const SwingResult resting = simulateSwing(makeSwingSetup(p, knee), options);
  EXPECT_NEAR(resting.trajectory.kneeFlexion.front(), 10 * kDegToRad, 1e-9);
}

}  // namespace
}  // namespace swingsim
