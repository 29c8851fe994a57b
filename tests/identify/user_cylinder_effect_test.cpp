// A user's cylinder effect (identify/user_cylinder_effect.h): a cylinder force written as an
// expression, registered as a record of the library's kind, read from a study's candidates,
// and, on bench records the independent generator makes (tests/independent/, no code shared
// with src/) with an effect outside the library, fitted, accepted, given an interval by the
// library's rules and saved into the knee model.
#include "identify/user_cylinder_effect.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "../independent/mauch_bench_generator.h"
#include "diagnosis_outcome.h"
#include "identify/cylinder_plant.h"
#include "io/knee_model_loader.h"
#include "study/diagnosed_model_writer.h"
#include "study/diagnosis_study.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

UserEffect stop(const std::string& name) {
  UserEffect e{name, "k * max(0, position_mm - s)^2", {{"k", "N/mm^2", 0.0, 50.0, 1.0}, {"s", "mm", 10.0, 25.0, 15.0}}};
  e.plant = PlantKind::kCylinder;
  return e;
}

TEST(UserCylinderEffect, RegistersARecordThatMovesTheExpressionInAndOut) {
  const EffectId id = registerUserCylinderEffect(stop("test_stop"));
  EXPECT_TRUE(isUserEffect(id));
  EXPECT_EQ(describeEffect(id).plant, PlantKind::kCylinder);
  EXPECT_EQ(describeEffect(id).fittedParameters, 2);
  const CylinderEffectRecord& r = findCylinderEffectRecord(id);
  ASSERT_EQ(r.expressionBounds.size(), 2u);
  EXPECT_EQ(r.expressionBounds[1].upper, 25.0);
  MauchCylinderParams p;
  p.coefficients.assign(4, {});
  EXPECT_FALSE(r.has(p));
  r.add(p, 0);
  ASSERT_TRUE(r.has(p));
  EXPECT_EQ(r.values(p), (std::vector<double>{1.0, 15.0}));
  // The force adds to the cylinder's: 1 N/mm^2 * (20 - 15 mm)^2 = 25 N at 20 mm, none at 10 mm.
  const MauchCylinder with(p);
  MauchCylinderParams plain = p;
  r.remove(plain);
  EXPECT_TRUE(plain.effects.expressions.empty());
  const MauchCylinder without(plain);
  EXPECT_NEAR(with.calcForce(0.020, 0.1, 1.0) - without.calcForce(0.020, 0.1, 1.0), 25.0, 1e-9);
  EXPECT_NEAR(with.calcForce(0.010, 0.1, 1.0) - without.calcForce(0.010, 0.1, 1.0), 0.0, 1e-12);
}

TEST(UserCylinderEffect, RefusesALibraryNameBadBoundsAndABadExpression) {
  EXPECT_THROW(registerUserCylinderEffect(stop("coulomb_friction")), std::invalid_argument);
  UserEffect e = stop("test_bad_stop");
  e.parameters[1].start = 30;  // outside [10, 25]
  EXPECT_THROW(registerUserCylinderEffect(e), std::invalid_argument);
  e = stop("test_bad_stop");
  e.expression = "k * max(0, knee_deg - s)^2";  // a knee moment's variable, not the cylinder's
  EXPECT_THROW(registerUserCylinderEffect(e), KneeExpressionError);
}

// ---- A study on independent bench records ------------------------------------------------

constexpr double kNoise = 15.0;  // N, as the independent cylinder diagnosis test

struct StudyFiles {
  fs::path dir, study;
};

// Bench records of `truth` (train normal, validate slow and fast) and a study naming them.
StudyFiles writeStudy(const independent::MauchTruth& truth, std::uint64_t seed, const std::string& tag,
                      const std::string& candidates) {
  StudyFiles f;
  f.dir = fs::temp_directory_path() / ("swingsim-user-cyl-" + tag + "-" + std::to_string(::getpid()));
  fs::create_directories(f.dir);
  for (const auto& g : independent::chienGaits())
    independent::writeCsv(independent::generate(truth, g, kNoise, seed++), (f.dir / (g.name + ".csv")).string());
  f.study = f.dir / "study.yaml";
  std::ofstream(f.study) << "kind: cylinder-diagnosis\nname: " << tag << "\nbase_model: " << SWINGSIM_SOURCE_DIR
                         << "/models/mauch-4phase.yaml\ntrain: [normal.csv]\nvalidate: [slow.csv, fast.csv]\n"
                         << candidates;
  return f;
}

const char* const kStopCandidates =
    "candidates:\n"
    "  - coulomb_friction\n  - orifice_quadratic\n  - position_dependent_damping\n"
    "  - name: my_end_stop\n"
    "    cylinder_force_N: \"k * max(0, position_mm - s)^2\"\n"
    "    parameters:\n"
    "      k: {unit: N/mm^2, min: 0, max: 50, start: 1}\n"
    "      s: {unit: mm, min: 10, max: 25, start: 15}\n";

Diagnosis diagnoseStudy(const StudyFiles& f, const std::string& tag, const std::string& saveModel = "") {
  const DiagnosisStudy study = loadDiagnosisStudy(f.study.string());
  const auto plant = loadDiagnosisPlant(study, 0);
  const Diagnosis dg = runDiagnosis(*plant, study.settings);
  testing::printOutcome(tag, dg, "N", kNoise);
  if (!saveModel.empty()) saveDiagnosedModel(study, *plant, dg, saveModel, "test");
  return dg;
}

// An end stop outside the library leaves the library NOT explained; the user's expression of
// its form is accepted, its interval holds the truth and the held-out error falls to the noise;
// saved, the knee model carries it.
TEST(UserCylinderEffect, AnEndStopOutsideTheLibraryIsExplainedByTheUsersExpression) {
  independent::MauchTruth truth;
  truth.laws = independent::chienTable1(4);
  truth.endStop = 3e6;         // N/m^2 = 3 N/mm^2: ~110 N at the normal swing's 26 mm
  truth.endStopStart = 0.020;  // m
  const StudyFiles library = writeStudy(
      truth, 301, "stop-library", "candidates: [coulomb_friction, orifice_quadratic, position_dependent_damping]\n");
  const Diagnosis before = diagnoseStudy(library, "stop-library");
  fs::remove_all(library.dir);
  EXPECT_FALSE(before.explained) << before.verdict;
  // Where the missing force acts: its largest region pushes the piston out (+) in deep flexion,
  // starting within 5 mm of the stop's 20 mm (the refitted phases absorb part of it elsewhere).
  std::printf("  library: %s\n", before.missingNote.c_str());
  EXPECT_EQ(before.missingNote.rfind("missing force: +", 0), 0u) << before.missingNote;
  const std::size_t at = before.missingNote.find(" at piston ");
  ASSERT_NE(at, std::string::npos) << before.missingNote;
  EXPECT_NEAR(std::stod(before.missingNote.substr(at + 11)), 20.0, 5.0) << before.missingNote;

  const StudyFiles user = writeStudy(truth, 301, "stop-user", kStopCandidates);
  const std::string saved = (user.dir / "diagnosed.yaml").string();
  const Diagnosis dg = diagnoseStudy(user, "stop-user", saved);
  ASSERT_FALSE(dg.accepted.empty()) << dg.verdict;
  EXPECT_EQ(dg.accepted.front(), "my_end_stop");
  EXPECT_TRUE(dg.explained) << dg.verdict;
  ASSERT_EQ(dg.acceptedScores.front().parameters.size(), 2u);
  const EffectParameter& k = dg.acceptedScores.front().parameters[0];
  const EffectParameter& s = dg.acceptedScores.front().parameters[1];
  std::printf("  my_end_stop k = %.3f (95 %% CI %.3f .. %.3f) N/mm^2, s = %.3f (%.3f .. %.3f) mm; truth 3, 20\n",
              k.value, k.lower, k.upper, s.value, s.lower, s.upper);
  EXPECT_LE(k.lower, 3.0);
  EXPECT_GE(k.upper, 3.0);
  EXPECT_LE(s.lower, 20.0);
  EXPECT_GE(s.upper, 20.0);
  EXPECT_LE(testing::worstHeldOut(dg), 1.5 * kNoise);
  EXPECT_LT(testing::worstHeldOut(dg), testing::worstHeldOut(before));
  const KneeModel knee = loadKneeModel(saved);
  fs::remove_all(user.dir);
  const MauchKnee* mauch = knee.spec.as<MauchKnee>();
  ASSERT_NE(mauch, nullptr);
  ASSERT_EQ(mauch->cylinder.effects.expressions.size(), 1u);
  const KneeExpressionParams& x = mauch->cylinder.effects.expressions[0];
  EXPECT_EQ(x.name, "my_end_stop");
  ASSERT_EQ(x.parameters.size(), 2u);
  EXPECT_EQ(x.parameters[0].unit, "N/mm^2");
  EXPECT_DOUBLE_EQ(x.parameters[0].value, k.value);
}

// A null with the user's expression among the candidates accepts nothing.
TEST(UserCylinderEffect, ANullAcceptsNeitherTheLibraryNorTheUsersExpression) {
  independent::MauchTruth truth;
  truth.laws = independent::chienTable1(4);
  const StudyFiles f = writeStudy(truth, 311, "stop-null", kStopCandidates);
  const Diagnosis dg = diagnoseStudy(f, "stop-null");
  fs::remove_all(f.dir);
  EXPECT_TRUE(dg.accepted.empty()) << dg.accepted.front();
}

// A study's own effect must be its plant's quantity.
TEST(UserCylinderEffect, AStudyRefusesAKneeMomentInACylinderStudy) {
  independent::MauchTruth truth;
  truth.laws = independent::chienTable1(4);
  const StudyFiles f = writeStudy(truth, 321, "stop-wrong",
                                  "candidates:\n  - name: my_moment\n    knee_moment_Nm: \"-c * knee_rate_rad_s\"\n"
                                  "    parameters: {c: {min: 0, max: 5, start: 0}}\n");
  try {
    loadDiagnosisStudy(f.study.string());
    ADD_FAILURE() << "a knee moment was accepted in a cylinder study";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("cylinder_force_N"), std::string::npos) << e.what();
  }
  fs::remove_all(f.dir);
}

}  // namespace
}  // namespace swingsim
