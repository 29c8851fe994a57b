// A knee tuning on real swings (study/tuning_run.h): P1 and the damping-table knee.
#include "study/tuning_run.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <filesystem>
#include <fstream>

#include "../cli/release_only.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

std::filesystem::path tempDir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("swingsim_tuning_run_test-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// P1's swing with the damping table scaled by `scale` (to 6 decimals) at `lowering`, built
// without the tuning code: the model file's text with a knee_effects map appended.
SwingResult truthSwing(double lowering, double scale) {
  const std::string path = kRoot + "/models/damping-table-default.yaml";
  const KneeModel model =
      parseKneeModel(slurp(path) + "knee_effects:\n  model_scale: " + std::to_string(scale) + "\n", path);
  SwingOptions options;
  options.trackImpactEnergy = true;  // simulate's options, as the tuning's swings
  return simulateSwing(makeSwingSetup(loadParticipant(kRoot + "/participants/p1.yaml"), model, lowering), options);
}

std::string writeStudy(const std::filesystem::path& dir, const std::string& targets) {
  const std::string path = (dir / "study.yaml").string();
  std::ofstream(path) << "kind: knee-tuning\nparticipant: " << kRoot << "/participants/p1.yaml\nknee_model: " << kRoot
                      << "/models/damping-table-default.yaml\nknobs:\n  - key: lowering_m\n    range: [0, 0.06]\n"
                      << "  - key: knee_effects.model_scale\n    range: [0.5, 8]\n    log_scale: true\ntargets:\n"
                      << targets;
  return path;
}

TEST(TuningRun, RecoversTheLoweringAndDampingThatMadeTheTargets) {
  const double lowering = 0.035, scale = 2.2;  // away from the defaults (0 m, scale 1)
  const SwingResult truth = truthSwing(lowering, scale);
  const auto dir = tempDir("recover");
  const std::string study = writeStudy(dir, "  swing_time_s: {value: " + std::to_string(truth.swingTime) +
                                                "}\n  peak_knee_flexion_deg: {value: " +
                                                std::to_string(truth.peakKneeFlexion->flexion * kRadToDeg) + "}\n");
  SweepRunControl control;
  const TuningRun run = runTuningStudy(loadTuningStudy(study), 0, control);
  ASSERT_TRUE(run.result.feasible);
  ASSERT_TRUE(run.result.identifiable) << run.result.identifiability;
  // std::to_string keeps 6 decimals: targets to 1e-6 s and 1e-6 deg, far inside what moves
  // the knobs by these tolerances (1 mm, 2 % of the scale).
  EXPECT_NEAR(run.result.best.knobs[0], lowering, 0.001);
  EXPECT_NEAR(run.result.best.knobs[1], scale, 0.02 * scale);
}

TEST(TuningRun, OnTwoKnobsItAgreesWithAFineGridSearch) {
  SWINGSIM_RELEASE_ONLY();  // 41 x 41 swings
  const auto dir = tempDir("grid");
  const std::string path = (dir / "study.yaml").string();
  std::ofstream(path) << "kind: knee-tuning\nparticipant: " << kRoot << "/participants/p1.yaml\nknee_model: " << kRoot
                      << "/models/damping-table-default.yaml\nknobs:\n  - key: lowering_m\n    range: [0, 0.06]\n"
                      << "  - key: knee_effects.model_scale\n    range: [1, 3]\ntargets:\n"
                      << "  swing_time_s: {value: 0.46}\n  peak_knee_flexion_deg: {value: 62}\n";
  const TuningStudy study = loadTuningStudy(path);
  SweepRunControl control;
  const TuningRun run = runTuningStudy(study, 0, control);
  // The grid's swings are built without the tuning code (truthSwing) and scored by the same cost.
  const int n = 40;
  const double loweringStep = 0.06 / n, scaleStep = 2.0 / n;
  double gridCost = 1e300, gridLowering = 0, gridScale = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      TuningPoint p;
      p.knobs = {i * loweringStep, 1 + j * scaleStep};
      scoreTuningPoint(p, truthSwing(p.knobs[0], p.knobs[1]), study.targets);
      if (p.ran && p.cost < gridCost) gridCost = p.cost, gridLowering = p.knobs[0], gridScale = p.knobs[1];
    }
  EXPECT_NEAR(run.result.best.knobs[0], gridLowering, loweringStep);
  EXPECT_NEAR(run.result.best.knobs[1], gridScale, scaleStep);
  EXPECT_LE(run.result.best.cost, gridCost);
}

TEST(TuningRun, TheReportedSwingIsTheOneTheTunedFilesGive) {
  SWINGSIM_RELEASE_ONLY();
  SweepRunControl control;
  const TuningRun run = runTuningStudy(loadTuningStudy(kRoot + "/studies/tune-p1-damping.yaml"), 0, control);
  const auto dir = tempDir("rerun");
  writeTuningOutputs(run, dir.string(), std::nullopt, "test");
  for (const auto& name : kTuningOutputFiles) EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  // simulate's own steps: load the written knee file, build the setup, energy bookkeeping on.
  const KneeModel tuned = loadKneeModel((dir / "tuned-knee.yaml").string());
  SwingOptions options;
  options.trackImpactEnergy = true;
  const SwingResult again = simulateSwing(
      makeSwingSetup(loadParticipant(kRoot + "/participants/p1.yaml"), tuned, run.lowering, run.added), options);
  EXPECT_EQ(again.swingTime, run.result.best.swingTime);
  EXPECT_EQ(again.peakKneeFlexion->flexion, run.result.best.peakKneeFlexion);
  EXPECT_EQ(*again.minToeClearance, run.result.best.minToeClearance);
  // The study asks for the chance of meeting the limits: its nominal draw is this swing.
  ASSERT_TRUE(run.chance.ran);
  EXPECT_EQ(run.chance.options.samples, 200);
  EXPECT_NEAR(run.chance.nominalSwingTime, run.result.best.swingTime, 1e-12);
  EXPECT_EQ(run.chance.misses.at(0), 0);  // the swing time is a soft target
  EXPECT_GE(run.chance.met + run.chance.failed + run.chance.misses.at(1) + run.chance.misses.at(2), 200);
  std::printf("%s\n", run.chance.verdict.c_str());
}

TEST(TuningRun, StoppedAfterAFewSwingsItIsInterruptedWithABestPoint) {
  SweepRunControl control;
  control.stopAfterSwings = 3;
  TuningStudy study = loadTuningStudy(kRoot + "/studies/tune-p1-damping.yaml");
  const TuningRun run = runTuningStudy(study, 1, control);
  EXPECT_TRUE(run.result.interrupted);
  EXPECT_TRUE(run.result.best.ran);
  EXPECT_LE(run.result.startSet.size(), 4u);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// The shipped tunes at the knobs' resolution: where the tune meets every hard limit, every
// rounding neighbour of the result meets them too, each knob's value is on its grid and inside
// its tolerance band; P2, whose tune meets no limit, says it cannot and its knee file says so.
TEST(TuningRun, TheShippedTunesHoldAtEveryRoundingNeighbourOrSayTheyCannot) {
  SWINGSIM_RELEASE_ONLY();  // five tunes, about 30 s on 2 cores
  for (const std::string name : {"tune-p1-damping", "tune-microprocessor-p1", "tune-microprocessor-p3",
                                 "tune-microprocessor-p4", "tune-microprocessor-p2"}) {
    SweepRunControl control;
    const TuningRun run = runTuningStudy(loadTuningStudy(kRoot + "/studies/" + name + ".yaml"), 0, control);
    const ResolutionCheck& res = run.result.resolution;
    ASSERT_TRUE(res.ran) << name;
    if (name == "tune-microprocessor-p2") {
      EXPECT_FALSE(run.result.feasible) << name;
      EXPECT_FALSE(res.holds) << name;
      EXPECT_EQ(res.verdict.rfind("cannot", 0), 0u) << res.verdict;
      EXPECT_NE(describeTunedKneeMisses(run.result).find("MISSES the hard limit"), std::string::npos);
      continue;
    }
    EXPECT_TRUE(run.result.feasible) << name;
    ASSERT_TRUE(res.holds) << name << ": " << res.verdict;
    EXPECT_GE(res.corners.size(), 2u) << name;
    for (const TuningPoint& corner : res.corners) EXPECT_TRUE(corner.feasible()) << name;
    EXPECT_EQ(describeTunedKneeMisses(run.result), "") << name;
    ASSERT_EQ(res.bands.size(), run.result.knobs.size()) << name;
    for (std::size_t k = 0; k < run.result.knobs.size(); ++k) {
      const TuningKnob& knob = run.result.knobs[k];
      const double value = run.result.best.knobs[k];
      EXPECT_NEAR(value / knob.resolution, std::round(value / knob.resolution), 1e-9) << name << " " << knob.key;
      EXPECT_LE(res.bands[k].low, value) << name << " " << knob.key;
      EXPECT_GE(res.bands[k].high, value) << name << " " << knob.key;
    }
  }
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// A measured-thigh drive can be tuned: P1's prosthesis driven by the left thigh of OpenSim's
// Gait10dof18musc walk (swing 1), whose record ends while the knee rests in the zone, inside
// the settle dwell. The swing end is then the knee's entry into the zone, and the report says so.
TEST(TuningRun, AMeasuredThighDriveWhoseRecordEndsInsideTheSettleDwellIsTuned) {
  const auto dir = tempDir("measured");
  const std::string participant = (dir / "p1-measured.yaml").string();
  std::ofstream(participant)
      << "name: P1-measured-thigh\nheight_m: 1.83\nbody_mass_kg: 70\nsegments:\n"
      << "  thigh: {length_m: 0.410, mass_kg: 3.350, com_from_distal_m: 0.284, inertia_kgm2: 0.0264}\n"
      << "  shank: {length_m: 0.515, mass_kg: 0.785, com_from_distal_m: 0.260, inertia_kgm2: 0.0161}\n"
      << "  foot:  {length_m: 0.240, mass_kg: 1.030, com_from_distal_m: 0.140, inertia_kgm2: 0.0059}\n"
      << "knee_friction_Nm: 10\nknee_model: " << kRoot << "/models/damping-table-default.yaml\n"
      << "swing_end: {thigh_target_flexion_deg: 10, zone_of_stability_deg: 6, time_limit_s: 1.5, settle_dwell_s: "
         "0.15}\n"
      << "toe_clearance: {gait: walking}\ndrive: thigh_kinematics\n"
      << "thigh_kinematics: {file: " << kRoot
      << "/tests/data/opensim-gait10dof/subject01_walk_IK.mot, hip: hip_flexion_l, "
      << "knee: knee_angle_l, knee_sign: -1, swing: 1}\n";
  const std::string study = (dir / "study.yaml").string();
  std::ofstream(study)
      << "kind: knee-tuning\nparticipant: " << participant
      << "\nknobs:\n  - key: knee_effects.model_scale\n    range: [0.5, 4]\n    log_scale: true\n"
      << "targets:\n  swing_time_s: {value: 0.55}\n  peak_knee_flexion_deg: {min: 50, max: 75, hard: true}\n";
  SweepRunControl control;
  const TuningRun run = runTuningStudy(loadTuningStudy(study), 0, control);
  ASSERT_TRUE(run.result.best.ran) << run.result.best.failure;
  EXPECT_TRUE(run.result.feasible);
  EXPECT_TRUE(run.result.best.dwellCutByRecord);
  EXPECT_TRUE(std::isfinite(run.result.best.swingTime));
  const std::string summary = formatTuningSummary(makeTuningReportInputs(run, "tuned-knee.yaml"));
  EXPECT_NE(summary.find("the measured record ends inside the settle dwell"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("nan"), std::string::npos) << summary;
}

}  // namespace
}  // namespace swingsim
