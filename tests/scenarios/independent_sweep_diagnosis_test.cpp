// The sweep plant of `swingsim diagnose` on sweep tables from the independent generator
// (tests/independent/sweep_table_generator.h: its own equations, knee, stop and swing-end
// rule, sharing no code with src/), with noise at Burkett Table 3's trial-to-trial SDs and
// truths away from the files (hip time scales 6 % below the files'): a hidden
// lowering-dependent hip drive is named with its value inside its interval on held-out
// participants; a null table accepts nothing; an effect outside the library (the damping
// re-tuned at each lowering) ends "NOT explained".
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../cli/release_only.h"
#include "../independent/sweep_table_generator.h"
#include "identify/diagnosis_engine.h"
#include "study/diagnosis_study.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

// Every participant at 0-200 mm in 50 mm steps (Burkett's range), 20 trials per row: with
// Burkett's 5 (SD / sqrt(5) = 14-21 ms a row) a hip-effort exponent of -1 (-9 ms at 100 mm,
// -37 ms at 200 mm for P1) is at the detection limit of 3-4 runners (docs/diagnosis.md).
const std::vector<double> kLowerings = {0.0, 0.05, 0.10, 0.15, 0.20};
constexpr int kTrials = 20;

Diagnosis diagnoseTable(const independent::SweepEffects& fx, std::uint64_t seed, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim-indep-sweep-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const independent::SweepModel files;
  auto participants = independent::burkettParticipants();
  const auto fileNames = independent::writeSweepModelFiles(participants, files, dir.string());
  // The truth is not the files: a 6 % faster hip drive. A lab's 20 trials per lowering, each
  // with Table 3's trial-to-trial SD.
  std::vector<std::vector<double>> lowerings;
  for (auto& p : participants) {
    p.timeScale *= 0.94;
    p.trials = kTrials;
    // Only the lowerings where the truth ends a swing (a runner who cannot swing through is
    // not measured there).
    lowerings.emplace_back();
    for (double d : kLowerings)
      if (independent::simulateSweepSwing(p, files, fx, d).ended) lowerings.back().push_back(d);
  }
  independent::writeSweepCsv(independent::generateSweepTableByParticipant(participants, lowerings, files, fx, seed),
                             (dir / "measured.csv").string());
  {
    std::ofstream sweep(dir / "sweep.yaml");
    sweep << "kind: knee-axis-sweep\nname: indep\nparticipants: [";
    for (std::size_t i = 0; i < fileNames.size(); ++i)
      sweep << (i ? ", " : "") << fs::path(fileNames[i]).filename().string();
    sweep << "]\nintegrator: {method: dormand-prince, accuracy: 1.0e-5}\n";
    std::ofstream study(dir / "study.yaml");
    study << "kind: sweep-diagnosis\nname: indep-" << tag << "\nsweep: sweep.yaml\nmeasured: measured.csv\n"
          << "candidates: [hip_effort_adaptation, hip_tempo_lowering, com_rule_proportional]\n"
          << "acceptance: {max_effects: 1, whiteness_lags: 2}\n";
  }
  const DiagnosisStudy study = loadDiagnosisStudy((dir / "study.yaml").string());
  const auto plant = loadDiagnosisPlant(study, 0);
  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  if (!std::getenv("SWINGSIM_KEEP_TEST_FILES")) fs::remove_all(dir);
  std::printf("[%s] accepted:", tag.c_str());
  for (const auto& a : dg.accepted) std::printf(" %s", a.c_str());
  for (const auto& s : dg.acceptedScores)
    for (const auto& p : s.parameters)
      std::printf(" %s %.3g (%.3g .. %.3g)", p.name.c_str(), p.value, p.lower, p.upper);
  std::printf("; held-out before");
  for (double v : dg.baseline.validationRmse) std::printf(" %.1f", v);
  std::printf(" after");
  for (double v : dg.final.validationRmse) std::printf(" %.1f", v);
  std::printf(" ms; %s\n", dg.verdict.substr(0, 160).c_str());
  return dg;
}

TEST(IndependentSweepDiagnosis, NamesAHipDriveThatRisesWithLowering) {
  SWINGSIM_RELEASE_ONLY();
  independent::SweepEffects fx;
  fx.hipEffortExponent = -1.0;  // hip moment x (I_k(0) / I_k(d)): more effort on the lowered knee
  const Diagnosis dg = diagnoseTable(fx, 11, "effort");
  ASSERT_EQ(dg.accepted.size(), 1u);
  EXPECT_EQ(dg.accepted[0], "hip_effort_adaptation");
  const auto& p = dg.acceptedScores[0].parameters[0];
  EXPECT_LE(p.lower, -1.0);
  EXPECT_GE(p.upper, -1.0);
  EXPECT_LT(dg.final.pooledValidationRmse, dg.baseline.pooledValidationRmse);
  EXPECT_TRUE(dg.explained) << dg.verdict;
}

TEST(IndependentSweepDiagnosis, AcceptsNothingOnANullTable) {
  SWINGSIM_RELEASE_ONLY();
  const Diagnosis dg = diagnoseTable({}, 12, "null");
  EXPECT_TRUE(dg.accepted.empty());
}

TEST(IndependentSweepDiagnosis, AnEffectOutsideTheLibraryIsNotExplained) {
  SWINGSIM_RELEASE_ONLY();
  independent::SweepEffects fx;
  fx.dampingRetune = 0.6;  // the prosthetist stiffens the knee 60 % per 100 mm of lowering
  const Diagnosis dg = diagnoseTable(fx, 13, "retune");
  EXPECT_FALSE(dg.explained);
  EXPECT_NE(dg.verdict.find("NOT explained"), std::string::npos);
}

}  // namespace
}  // namespace swingsim
