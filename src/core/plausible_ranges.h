#pragma once
// Plausibility ranges of every number a user or a generator supplies, checked at load: a
// finite but absurd value (a force of 1e300 N, the 9.9e37 missing-data marker of lab
// exports, a time step of 1e-200 s, a 1e6 deg knee) is refused where it was written, with
// the file, line, key and the range's reason, instead of crashing a fit or failing deep in
// the integrator. Each range is wide (well past any real swing or bench) so that it only
// catches unit mistakes, markers and corruption. docs/robustness.md lists them all.
#include <string>

namespace swingsim {

/// A closed range [lower, upper] in `unit`, with why a value outside cannot be real.
struct PlausibleRange {
  double lower, upper;
  const char* unit;    ///< as in the file ("N", "deg", "s")
  const char* reason;  ///< one clause: what real values are
};

/// "" if `value` lies in `range`, else "expected <what> in [lower, upper] unit (reason)", with a
/// hint when |value| >= 1e37 (a missing-data marker such as 9.9e37).
std::string checkPlausible(double value, const PlausibleRange& range, const std::string& what);

/// Force on a bench (N): a 150 N m stance knee moment on a 2 cm lever is 7.5 kN.
constexpr PlausibleRange kForceRange{-1e5, 1e5, "N",
                                     "a knee cylinder carries at most a few kN (150 N m on a 2 cm lever is 7.5 kN)"};
/// Smallest nonzero magnitude of any number read from a file: below lie the subnormals
/// (1e-320 is finite, but its products underflow to 0); no quantity of ours comes near it.
constexpr double kSmallestMagnitude = 1e-300;
/// The message for a nonzero number below kSmallestMagnitude.
constexpr const char* kTooSmallMessage =
    "too small: expected 0 or a magnitude of at least 1e-300 (this is below 1e-300)";
/// Sample time (s) in a record: a lab clock of months at most.
constexpr PlausibleRange kRecordTimeRange{-1e7, 1e7, "s", "a record's clock runs for months at most"};
/// Least step between samples (s): 1 MHz, past any motion capture (<= 2 kHz) or bench DAQ.
constexpr double kMinSampleStep = 1e-6;
/// Joint angle in a record (deg): beyond a full turn it is a unit or unwrapping error.
constexpr PlausibleRange kJointAngleRange{-360, 360, "deg", "a joint angle stays within a full turn"};
/// Initial knee flexion (deg): the shank cannot pass the thigh; a knee hyperextends little.
constexpr PlausibleRange kInitialKneeRange{-30, 180, "deg",
                                           "the shank cannot fold through the thigh (180 deg) and a knee "
                                           "hyperextends by a few degrees"};
/// Initial joint rate (deg/s): a swing's knee peaks near 400-500 deg/s (Winter 2009).
constexpr PlausibleRange kJointRateRange{-3000, 3000, "deg/s", "a swinging knee peaks near 500 deg/s"};
/// Joint moment in a record or profile (N m): the hip peaks near 1-2 N m/kg in gait.
constexpr PlausibleRange kJointMomentRange{-2000, 2000, "N m",
                                           "a hip moment peaks near 1-2 N m/kg, some 300 N m for a 150 kg person"};
/// Time scale of a hip moment profile: calibration searches 0.85-1.8.
constexpr PlausibleRange kTimeScaleRange{0.2, 5, "",
                                         "calibrated scales lie in 0.85-1.8; 0.2-5 spans a 5x shorter or longer swing"};
/// Scale of a generated condition's hip moment or of a hidden effect's mass or moment:
/// 0.2-5 x the participant's.
constexpr PlausibleRange kAmplitudeScaleRange{
    0.2, 5, "", "a condition or hidden effect scales the participant's value by a fraction to a few times"};
/// Duration of a hip moment phase (s): a swing lasts 0.3-0.6 s.
constexpr PlausibleRange kPhaseDurationRange{0.01, 10, "s", "a swing lasts 0.3-0.6 s"};
/// Damping of a Mauch cylinder phase (N s/m): a hydraulic cylinder dissipates (>= 0); Mauch
/// 2014's fitted phases (models/) have 500-17,700 N s/m.
constexpr PlausibleRange kCylinderDampingRange{
    0, 1e6, "N s/m", "a hydraulic cylinder dissipates, and fitted phases have 500-17,700 N s/m"};
/// Piston position of a Mauch cylinder (m), e.g. where hyperextension starts: the stroke is a
/// few centimetres (Chien et al. measured xhy = 0.005 cm).
constexpr PlausibleRange kCylinderPositionRange{-0.1, 0.1, "m", "a knee cylinder's piston travels a few centimetres"};
/// Stiffness of a Mauch cylinder phase (N/m): the fitted phases (models/) have 2,500-563,000 N/m.
constexpr PlausibleRange kCylinderStiffnessRange{-1e7, 1e7, "N/m", "fitted phases have 2,500-563,000 N/m"};
/// A swing time in a results file (s): no swing outlasts its participant's time_limit_s,
/// which a participant file takes up to 10 s; a longer (or non-positive) time was not
/// computed by a swing.
constexpr PlausibleRange kSwingTimeRange{0, 10, "s", "the largest time_limit_s a participant takes"};
/// A knee-axis lowering in a results file (m): along the shank, which a participant file
/// takes up to 1.5 m long.
constexpr PlausibleRange kLoweringRange{0, 1.5, "m", "the knee axis is lowered along a shank of at most 1.5 m"};
/// Angle noise of generated swings (deg): motion capture is good to about 1 deg.
constexpr PlausibleRange kAngleNoiseRange{0, 10, "deg", "motion capture angles are good to about 1 deg"};
/// Force noise of generated bench records (N): a load cell is good to a few N.
constexpr PlausibleRange kForceNoiseRange{0, 1000, "N", "a bench load cell is good to a few N"};

}  // namespace swingsim
