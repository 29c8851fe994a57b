// The missing moment (identify/missing_moment.h) on swings the independent generator makes
// (tests/independent/swing_generator.h, no code shared with src/) with effects outside the
// library: it must name where in the measured state the effect acts, and the direction.
#include "identify/missing_moment.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "../independent/swing_generator.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

// The truth's three swings (0.5 deg noise) read as a user's files, and the model the user's
// files make (the truth without its hidden effect).
MissingMoment missingOf(const independent::SwingTruth& truth, std::uint64_t seed, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim-missing-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  independent::SwingTruth files = truth;
  files.cushionDamping = files.stiffening = 0;
  independent::writeSwingModelFiles(files, dir.string());
  std::vector<SwingRecord> records;
  for (const auto& d : independent::threeDrives()) {
    const std::string path = (dir / (d.name + ".csv")).string();
    independent::writeSwingCsv(independent::generateSwing(truth, d, 0.5, seed++), path);
    records.push_back(readSwingRecord(path));
  }
  SwingBase base;
  base.participant = loadParticipant((dir / "participant.yaml").string());
  base.knee = loadKneeModel((dir / "knee.yaml").string());
  // The model's own swing along each record from its first sample, as the reference.
  std::vector<SwingPrediction> references;
  for (const auto& r : records)
    references.push_back(predictSwing(base, SwingModelParams{}, r, r.hipFlexion.front(), r.kneeFlexion.front()));
  const MissingMoment m = calcMissingMoment(base, SwingModelParams{}, records, references);
  fs::remove_all(dir);
  std::printf("  %s: %s\n", tag.c_str(), describeMissingMoment(m).c_str());
  return m;
}

TEST(MissingMoment, ACushionNearExtensionIsPlacedAndResistsExtension) {
  independent::SwingTruth truth;
  truth.cushionDamping = 1.5;  // N m s/rad below 20 deg while extending
  const MissingMoment m = missingOf(truth, 101, "cushion");
  ASSERT_FALSE(m.regions.empty());
  const MissingMomentRegion& r = m.regions.front();
  EXPECT_TRUE(r.extending);
  EXPECT_GT(r.moment, 0) << "resists extension";
  EXPECT_NEAR(r.kneeHighDeg, 20.0, 5.0);
  EXPECT_LT(r.kneeLowDeg, 13.0);  // the records end at 8 deg
  for (const auto& other : m.regions) EXPECT_LT(other.kneeLowDeg, 25.0) << other.describe();
}

TEST(MissingMoment, ADeepFlexionStiffeningIsPlacedAboveItsOnset) {
  independent::SwingTruth truth;
  truth.stiffening = 20.0;  // N m/rad beyond 55 deg
  const MissingMoment m = missingOf(truth, 111, "stiffening");
  ASSERT_FALSE(m.regions.empty());
  for (const auto& r : m.regions) {
    EXPECT_LT(r.moment, 0) << "pushes towards extension: " << r.describe();
    EXPECT_GT(r.kneeLowDeg, 50.0) << r.describe();
  }
  double lowest = 1e9;
  for (const auto& r : m.regions) lowest = std::min(lowest, r.kneeLowDeg);
  EXPECT_NEAR(lowest, 55.0, 5.0);
}

TEST(MissingMoment, ANullLeavesNoRegion) {
  for (std::uint64_t seed : {121, 131, 141}) {
    const MissingMoment m = missingOf(independent::SwingTruth{}, seed, "null-" + std::to_string(seed));
    EXPECT_TRUE(m.regions.empty()) << describeMissingMoment(m);
    EXPECT_GT(m.kneeDeg.size(), 300u);
  }
}

}  // namespace
}  // namespace swingsim
