// Why the sweep diagnosis's thigh_target_flexion candidate carries no information on the
// calibration's tables (docs/diagnosis.md, "How far the intervals can be trusted"): its
// value reaches the swing exactly as the independent generator's target does, but no swing
// of those tables ends on the thigh near the files' 20 deg, where the candidate's fit starts.
// The cost is flat there, so the fit never leaves it (likelihood ratio 0), although a truth
// at 25 deg moves one row by 58 ms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "../cli/release_only.h"
#include "../cli/run_swingsim.h"
#include "../independent/sweep_table_generator.h"
#include "core/input_error.h"
#include "identify/sweep_effects.h"
#include "study/sweep_study.h"
#include "sweep/sweep_assumptions.h"
#include "sweep/sweep_uncertainty.h"
#include "sweep_calibration_cases.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

// Library against generator on one swing, s: the cross-check's tolerance of
// tests/independent/sweep_table_generator_test.cpp (twice swingsim's documented 0.1 ms).
constexpr double kAgreeS = 0.2e-3;
// A target that decides no swing leaves its time where it was, s: the thigh's crossing is
// only an event of the integration then (measured: 0 s at every row).
constexpr double kSameS = 1e-9;
// The candidate fit's central-difference step, deg: 1e-3 of its 5-35 deg range
// (SweepPlant::fitSubset's differenceStep on the range as its typical size).
constexpr double kFitStepDeg = 1e-3 * 30.0;
// Rows as the calibration's tables have them.
const std::vector<double> kLowerings = {0.0, 0.05, 0.10, 0.15, 0.20};

// The files the calibration's sweep study reads, at the truth's hip tempo (so the library's
// swings are the truth's without a calibrated time scale), as nominal sweep variants.
std::vector<SweepVariant> truthTempoVariants(std::vector<independent::SweepParticipant>& participants) {
  const fs::path dir = testing::freshTempDir("swingsim_sweep_thigh_target", "files");
  for (auto& p : participants) p.timeScale *= calibration::kSweepTruthTempo;
  const auto files = independent::writeSweepModelFiles(participants, independent::SweepModel{}, dir.string());
  std::ofstream sweep(dir / "sweep.yaml");
  sweep << "kind: knee-axis-sweep\nname: thigh-target\nparticipants: [";
  for (std::size_t i = 0; i < files.size(); ++i) sweep << (i ? ", " : "") << fs::path(files[i]).filename().string();
  sweep << "]\nintegrator: {method: dormand-prince, accuracy: 1.0e-5}\n";
  sweep.close();
  const SweepStudy study = loadSweepStudy((dir / "sweep.yaml").string());
  std::vector<SweepVariant> out;
  for (const auto& p : study.participants) out.push_back(makeNominalVariant(study, p));
  return out;
}

// The swing time (s; NaN without an end) of `nominal` at `lowering` with the candidate's
// value `targetDeg`, through the sweep plant's own path (applySweepEffects, then the swing).
double candidateSwingTime(const SweepVariant& nominal, double targetDeg, double lowering) {
  SweepModelParams params;
  params.effects = {{EffectId::kThighTargetFlexion, targetDeg}};
  const SweepVariant v = applySweepEffects(nominal, params);
  const auto knee = std::make_shared<const KneeLawSum>(makeSweepVariantKnee(v));
  try {
    return simulateSwing(makeSwingSetup(calcSweepSwingParticipant(v, params, lowering), knee, lowering), v.swing)
        .swingTime;
  } catch (const RunError&) {
    return std::nan("");
  }
}

TEST(SweepThighTarget, TheCandidatesValueReachesTheSwingAsTheGeneratorsTarget) {
  auto participants = independent::burkettParticipants();
  const auto variants = truthTempoVariants(participants);
  const auto& p4 = participants[3];
  for (double target : {20.0, 25.0}) {
    independent::SweepModel truth;
    truth.thighTargetDeg = target;
    const auto theirs = independent::simulateSweepSwing(p4, truth, {}, 0.20);
    ASSERT_TRUE(theirs.ended);
    EXPECT_NEAR(candidateSwingTime(variants[3], target, 0.20), theirs.swingTime, kAgreeS) << target << " deg";
  }
  // At 25 deg P4's thigh, peaking at 25.6 deg, reaches its target 58 ms after his knee's return.
  EXPECT_GT(candidateSwingTime(variants[3], 25.0, 0.20) - candidateSwingTime(variants[3], 20.0, 0.20), 0.050);
}

// The candidate's fit starts at the files' 20 deg (SweepPlant::addEffect: the participants'
// mean) and takes central differences kFitStepDeg either side: no row of the tables moves
// there, so the fit sees no slope and stays (likelihood ratio 0).
TEST(SweepThighTarget, TheFitsStepsAtTheFilesTargetMoveNoRow) {
  auto participants = independent::burkettParticipants();
  const auto variants = truthTempoVariants(participants);
  int rows = 0;
  for (std::size_t i = 0; i < variants.size(); ++i)
    for (double d : kLowerings) {
      const double files = candidateSwingTime(variants[i], 20.0, d);
      if (!std::isfinite(files)) continue;
      ++rows;
      for (double target : {20.0 - kFitStepDeg, 20.0 + kFitStepDeg})
        EXPECT_NEAR(candidateSwingTime(variants[i], target, d), files, kSameS) << participants[i].name << " at " << d;
    }
  // Every row of the tables (P2 ends no swing at 200 mm).
  EXPECT_EQ(rows, 19);
}

// Over the candidate's whole range, 5-35 deg in 0.25 deg steps, a row keeps the files' swing
// time or ends no swing (its thigh no longer reaches the target), except P4's at 150 and
// 200 mm, which move only from 23.5 deg up: the target is a gate on whether a swing ends,
// not a time, for these legs. Prints, per row, the lowest target that moves its time.
TEST(SweepThighTarget, OnlyP4sLowestRowsMoveAndOnlyAbove23Deg) {
  SWINGSIM_RELEASE_ONLY();  // 2300 swings, 4 s in Release
  auto participants = independent::burkettParticipants();
  const auto variants = truthTempoVariants(participants);
  std::printf("participant lowering_m files_ms first_target_moving_deg its_ms\n");
  int moved = 0;
  for (std::size_t i = 0; i < variants.size(); ++i)
    for (double d : kLowerings) {
      const double files = candidateSwingTime(variants[i], 20.0, d);
      if (!std::isfinite(files)) continue;
      double moving = std::nan(""), movedTime = std::nan("");
      for (double target = 5.0; target <= 35.0 && std::isnan(moving); target += 0.25) {
        const double t = candidateSwingTime(variants[i], target, d);
        if (!std::isfinite(t) || std::abs(t - files) <= kSameS) continue;
        moving = target;
        movedTime = t;
      }
      std::printf("%s %.2f %.1f %.2f %.1f\n", participants[i].name.c_str(), d, 1e3 * files, moving, 1e3 * movedTime);
      if (std::isnan(moving)) continue;
      ++moved;
      EXPECT_EQ(participants[i].name, "P4") << d << " m moves at " << moving << " deg";
      EXPECT_GT(moving, 23.0) << participants[i].name << " at " << d << " m";
    }
  EXPECT_EQ(moved, 2);
}

}  // namespace
}  // namespace swingsim
