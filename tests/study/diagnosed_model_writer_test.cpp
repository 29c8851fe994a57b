// What `swingsim diagnose --save-model` writes loads back, carries the diagnosed values and
// runs: the cylinder's knee model, the swing's knee model and participant.
#include "study/diagnosed_model_writer.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "../cli/release_only.h"
#include "identify/cylinder_plant.h"
#include "identify/swing_plant.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("swingsim_saved_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(DiagnosedModel, CylinderModelLoadsBackWithTheRefittedCoefficientsAndTheAcceptedEffect) {
  const DiagnosisStudy study = loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-cylinder.yaml");
  const auto plant = loadDiagnosisPlant(study, 8);
  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  ASSERT_TRUE(dg.explained) << dg.verdict;
  const fs::path file = freshDir("cylinder") / "diagnosed.yaml";
  ASSERT_EQ(saveDiagnosedModel(study, *plant, dg, file.string(), "test").size(), 1u);
  const MauchCylinderParams saved = loadMauchCylinder(file.string());
  const MauchCylinderParams& final = cylinderParams(*dg.final.model);
  EXPECT_TRUE(saved.effects.orificeQuadratic);
  EXPECT_EQ(saved.effects.orificeCoefficient, final.effects.orificeCoefficient);
  for (int i = 0; i < final.phases; ++i) {
    EXPECT_EQ(saved.coefficients[static_cast<std::size_t>(i)].f, final.coefficients[static_cast<std::size_t>(i)].f);
    EXPECT_EQ(saved.coefficients[static_cast<std::size_t>(i)].c, final.coefficients[static_cast<std::size_t>(i)].c);
  }
  // Compared again with the data, the saved model is the final model: the same error.
  const Comparison again = plant->compare(CylinderModel(saved));
  const Comparison after = plant->compare(*dg.final.model);
  for (std::size_t r = 0; r < after.records.size(); ++r)
    EXPECT_NEAR(again.records[r].overall.rmse, after.records[r].overall.rmse, 1e-9);
}

TEST(DiagnosedModel, SwingKneeModelAndParticipantLoadBackAndGiveTheFinalModelsKneeMoment) {
  SWINGSIM_RELEASE_ONLY();  // 50-180 s under the sanitizers
  const DiagnosisStudy study = loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-swing.yaml");
  const auto plant = loadDiagnosisPlant(study, 8);
  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  ASSERT_TRUE(dg.explained) << dg.verdict;
  const fs::path dir = freshDir("swing");
  const auto written = saveDiagnosedModel(study, *plant, dg, (dir / "knee.yaml").string(), "test");
  ASSERT_EQ(written.size(), 2u);
  const Participant participant = loadParticipant(written[1]);
  EXPECT_EQ(fs::canonical(participant.kneeModelPath), fs::canonical(dir / "knee.yaml"));
  const KneeModel knee = loadKneeModel(participant.kneeModelPath);
  const SwingModelParams& final = swingParams(*dg.final.model);
  EXPECT_TRUE(knee.spec.hasKneeEffects);
  EXPECT_EQ(knee.spec.kneeEffects.assistStiffness, final.effects.knee.assistStiffness);
  EXPECT_EQ(knee.spec.kneeEffects.modelScale, final.kneeModelScale);
  // The saved knee law is the diagnosed one (model law scaled, effects, stop), sample by sample.
  const SwingBase& base = dynamic_cast<const SwingPlant&>(*plant).base();
  SwingBase savedBase{participant, knee, SwingDrive::kHipMoment, {}, true};
  const KneeLawSum diagnosed = makeSwingKneeLaw(base, final);
  const KneeLawSum reloaded = makeSwingKneeLaw(savedBase, SwingModelParams{});
  for (double flexion : {0.02, 0.3, 1.1})
    for (double rate : {-4.0, 0.5, 6.0}) {
      const KneeKinematics k{flexion, rate};
      EXPECT_NEAR(reloaded.calcMoment(k, nullptr), diagnosed.calcMoment(k, nullptr), 1e-12) << flexion << " " << rate;
    }
}

}  // namespace
}  // namespace swingsim
