// The table of unpublished assumptions (docs/uncertainty.md): every entry's apply function
// changes what it claims, its range holds the files' value, and the draws stay inside it.
#include "sweep/sweep_assumptions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

const SweepStudy& burkett() {
  static const SweepStudy s = loadSweepStudy(kRoot + "/studies/burkett2004.yaml");
  return s;
}

SweepVariant nominalP(std::size_t i) { return makeNominalVariant(burkett(), burkett().participants.at(i)); }

TEST(SweepAssumptions, EveryEntryIsDocumentedAndKeyedOnce) {
  std::set<std::string> keys;
  for (const auto& a : sweepAssumptions()) {
    EXPECT_TRUE(keys.insert(a.key).second) << a.key << " twice";
    EXPECT_FALSE(a.name.empty()) << a.key;
    EXPECT_FALSE(a.unit.empty()) << a.key;
    EXPECT_GT(a.source.size(), 20u) << a.key << ": a range needs its source";
    EXPECT_EQ(a.discrete, a.choices.size() == 2) << a.key;
  }
  // The assumptions docs/uncertainty.md lists are all there.
  for (const char* key : {"com_rule", "hip_time_scale", "hip_extension_ratio", "hip_flexion_duration",
                          "hip_extension_duration", "hip_effort_adaptation", "thigh_target_flexion", "knee_friction",
                          "settle_dwell", "stop_stiffness", "stop_restitution", "integrator_accuracy"})
    EXPECT_EQ(keys.count(key), 1u) << key;
}

// For every participant and assumption: the nominal is what the files say (read of the
// untouched variant) and lies in [low, high]; applying low, a middle value and high reads
// back that value; and nothing else the sweep reads changes.
TEST(SweepAssumptions, ApplyChangesWhatItClaimsWithinTheRange) {
  for (std::size_t i = 0; i < burkett().participants.size(); ++i) {
    const SweepVariant nominal = nominalP(i);
    for (const auto& a : sweepAssumptions()) {
      const AssumptionRange r = a.calcRange(nominal);
      ASSERT_TRUE(r.applicable) << a.key;  // the Burkett participants have the sine profile
      EXPECT_EQ(r.nominal, a.read(nominal)) << a.key;
      EXPECT_LE(r.low, r.nominal) << a.key;
      EXPECT_GE(r.high, r.nominal) << a.key;
      EXPECT_LT(r.low, r.high) << a.key << ": a range of one value varies nothing";
      for (double u : {0.0, 0.5, 0.999}) {
        const double value = calcAssumptionValue(a, r, u);
        EXPECT_GE(value, r.low) << a.key;
        EXPECT_LE(value, r.high) << a.key;
        SweepVariant v = nominal;
        a.apply(v, value);
        EXPECT_NEAR(a.read(v), value, 1e-12 * std::fabs(value)) << a.key << " u=" << u;
        // Every other assumption still reads its nominal value.
        for (const auto& other : sweepAssumptions()) {
          if (other.key == a.key) continue;
          EXPECT_EQ(other.read(v), other.read(nominal)) << a.key << " changed " << other.key;
        }
      }
    }
  }
}

// The fields themselves, for the entries a reader would check first.
TEST(SweepAssumptions, ApplyWritesTheParticipantKneeAndIntegratorFields) {
  const SweepVariant nominal = nominalP(0);
  auto find = [](const std::string& key) -> const SweepAssumption& {
    for (const auto& a : sweepAssumptions())
      if (a.key == key) return a;
    throw std::runtime_error("no assumption " + key);
  };
  SweepVariant v = nominal;
  ASSERT_EQ(v.participant.comRule, ComRule::kFixedFromProximal);
  find("com_rule").apply(v, 1.0);
  EXPECT_EQ(v.participant.comRule, ComRule::kProportional);
  find("com_rule").apply(v, 0.0);
  EXPECT_EQ(v.participant.comRule, ComRule::kFixedFromProximal);

  find("knee_friction").apply(v, 7.5);
  EXPECT_EQ(v.participant.kneeFriction, 7.5);
  find("stop_stiffness").apply(v, 3e4);
  EXPECT_EQ(v.knee.spec.stop.stiffness, 3e4);
  find("stop_restitution").apply(v, 0.35);
  EXPECT_EQ(v.knee.spec.stop.restitution, 0.35);
  find("settle_dwell").apply(v, 0.12);
  EXPECT_EQ(v.participant.swingEnd.settleDwell, 0.12);
  find("thigh_target_flexion").apply(v, 25);
  EXPECT_NEAR(v.participant.swingEnd.thighTargetFlexion, 25 * kDegToRad, 1e-15);
  find("hip_extension_ratio").apply(v, 1.0);
  EXPECT_EQ(v.participant.hipMoment.extensionAmplitude, v.participant.hipMoment.flexionAmplitude);
  find("integrator_accuracy").apply(v, 3e-6);
  EXPECT_EQ(v.swing.accuracy, 3e-6);

  // The rebuilt knee law carries the new friction and stop: at 2 deg of hyperextension,
  // extending, the stop and friction push harder than in the files' law.
  const KneeKinematics hyperextended{-2 * kDegToRad, -1.0};
  const double before = makeSweepVariantKnee(nominal).calcMoment(hyperextended, nullptr);
  SweepVariant stiffer = nominal;
  find("stop_stiffness").apply(stiffer, 2 * nominal.knee.spec.stop.stiffness);
  EXPECT_GT(makeSweepVariantKnee(stiffer).calcMoment(hyperextended, nullptr), before);
  // Coming out of the stop (flexing at 2 deg of hyperextension), the unloading spring is
  // e^2 k: a livelier stop pushes harder.
  const KneeKinematics leaving{-2 * kDegToRad, 1.0};
  SweepVariant dead = nominal, lively = nominal;
  find("stop_restitution").apply(dead, 0.3);
  find("stop_restitution").apply(lively, 0.5);
  EXPECT_GT(makeSweepVariantKnee(lively).calcMoment(leaving, nullptr),
            makeSweepVariantKnee(dead).calcMoment(leaving, nullptr));
  SweepVariant rubbing = nominal;
  find("knee_friction").apply(rubbing, nominal.participant.kneeFriction + 5);
  EXPECT_GT(makeSweepVariantKnee(rubbing).calcMoment(hyperextended, nullptr), before);
}

// The shank + foot inertia about the knee at the standard location, by hand from P1's
// Table 2 values (participants/p1.yaml; foot COM measured from the toe).
TEST(SweepAssumptions, BelowKneeInertiaAtStandardLocation) {
  const Participant& p = burkett().participants[0];
  const double shankCom = p.shank.length - p.shank.comFromDistal;
  const double footForward = p.foot.length - p.foot.comFromDistal;
  const double expected = p.shank.inertia + p.shank.mass * shankCom * shankCom + p.foot.inertia +
                          p.foot.mass * (p.shank.length * p.shank.length + footForward * footForward);
  EXPECT_NEAR(calcBelowKneeInertia(p, 0), expected, 1e-12);
}

// Hale 1990 adaptation: exponent 0 replays the files' moment; exponent 1 scales both
// amplitudes by the inertia ratio, which falls as the knee (and the foot with it) moves up
// the shank.
TEST(SweepAssumptions, HipEffortAdaptationScalesByTheInertiaRatio) {
  const Participant& p = burkett().participants[0];
  const Participant same = calcAdaptedParticipant(p, 0.1, 0.0);
  EXPECT_EQ(same.hipMoment.flexionAmplitude, p.hipMoment.flexionAmplitude);
  const double ratio = calcBelowKneeInertia(p, 0.1) / calcBelowKneeInertia(p, 0);
  ASSERT_LT(ratio, 1.0);
  const Participant full = calcAdaptedParticipant(p, 0.1, 1.0);
  EXPECT_NEAR(full.hipMoment.flexionAmplitude, p.hipMoment.flexionAmplitude * ratio, 1e-12);
  EXPECT_NEAR(full.hipMoment.extensionAmplitude, p.hipMoment.extensionAmplitude * ratio, 1e-12);
  const Participant half = calcAdaptedParticipant(p, 0.1, 0.5);
  EXPECT_NEAR(half.hipMoment.flexionAmplitude, p.hipMoment.flexionAmplitude * std::sqrt(ratio), 1e-12);
}

// A tabulated hip moment has no half-sine shape: those entries are not applicable and
// leave the variant as it was.
TEST(SweepAssumptions, ShapeEntriesDoNotApplyToATabulatedHipMoment) {
  SweepVariant v = nominalP(0);
  v.participant.hipMoment.kind = HipMomentProfile::Kind::kTable;
  v.participant.hipMoment.times = {0, 0.2, 0.4};
  v.participant.hipMoment.moments = {0, 30, 0};
  for (const auto& a : sweepAssumptions()) {
    const bool shape =
        a.key == "hip_extension_ratio" || a.key == "hip_flexion_duration" || a.key == "hip_extension_duration";
    EXPECT_EQ(a.calcRange(v).applicable, !shape) << a.key;
  }
}

// Log-uniform draws cover the range in log: u = 0.5 is the geometric mean.
TEST(SweepAssumptions, LogUniformDrawIsGeometric) {
  for (const auto& a : sweepAssumptions()) {
    if (!a.logUniform) continue;
    const AssumptionRange r = a.calcRange(nominalP(0));
    EXPECT_NEAR(calcAssumptionValue(a, r, 0.5), std::sqrt(r.low * r.high), 1e-12 * r.high) << a.key;
  }
}

}  // namespace
}  // namespace swingsim
