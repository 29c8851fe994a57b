// The sweep plant's refusals and its participants outside the model (identify/sweep_plant.h):
// a measured table the sweep cannot use is refused with the file, line and column; a
// participant the model cannot reach is reported with its reason, never silently dropped;
// a leave-one-participant-out diagnosis needs two participants inside, and the refusal
// names why each of the others is outside.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "identify/diagnosis_engine.h"
#include "study/diagnosis_study.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

class SweepPlantInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("swingsim-sweep-plant-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The plant of a sweep diagnosis of Burkett's sweep study against `csv`.
  std::unique_ptr<DiagnosisPlant> load(const std::string& csv, const std::string& extra = "") {
    std::ofstream(dir_ / "m.csv") << csv;
    std::ofstream(dir_ / "s.yaml") << "kind: sweep-diagnosis\nname: t\nsweep: " << SWINGSIM_SOURCE_DIR
                                   << "/studies/burkett2004.yaml\nmeasured: m.csv\n"
                                   << extra;
    const DiagnosisStudy study = loadDiagnosisStudy((dir_ / "s.yaml").string());
    return loadDiagnosisPlant(study, 0);
  }

  fs::path dir_;
};

const std::string kHeader = "participant,lowering_m,swing_time_s,sd_s,n\n";

TEST_F(SweepPlantInput, AParticipantNotInTheStudyIsRefusedWithItsLine) {
  try {
    load(kHeader + "P1,0,0.463,0.031,5\nP9,0.05,0.42,0.031,5\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(std::string("m.csv:3: participant")), std::string::npos) << m;
    EXPECT_NE(m.find("P1, P2, P3, P4"), std::string::npos) << m;
    EXPECT_NE(m.find("'P9'"), std::string::npos) << m;
  }
}

TEST_F(SweepPlantInput, ARunnerWithoutAStandardRowIsRefused) {
  try {
    load(kHeader + "P1,0,0.463,0.031,5\nP1,0.05,0.42,0.031,5\nP3,0.14,0.502,0.046,5\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("participant P3: expected a row at lowering_m 0"), std::string::npos) << m;
  }
}

TEST_F(SweepPlantInput, RowsWithoutNoiseNeedTheStudysMeasurementNoise) {
  EXPECT_THROW(load("participant,lowering_m,swing_time_s\nP1,0,0.463\nP1,0.05,0.42\n"), InputError);
}

TEST_F(SweepPlantInput, FewerThanTwoRunnersInsideIsRefusedNamingWhyEachOtherIsOutside) {
  try {
    load(kHeader + "P1,0,0.463,0.031,5\nP1,0.05,0.423,0.031,5\nP3,0,0.496,0.046,5\n");
    FAIL() << "no error";
  } catch (const RunError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("needs at least two participants inside the model"), std::string::npos) << m;
    EXPECT_NE(m.find("1 of 4"), std::string::npos) << m;
    // Every participant outside, each with its own reason.
    EXPECT_NE(m.find("P2 is outside the model and takes no part in the fits or folds: not measured"), std::string::npos)
        << m;
    EXPECT_NE(m.find("P3 is outside the model and takes no part in the fits or folds: no lowered row to compare"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("P4 is outside the model and takes no part in the fits or folds: not measured"), std::string::npos)
        << m;
  }
}

TEST_F(SweepPlantInput, ARowBeyondTheShankIsLeftOutWithItsLineAndP2IsOutside) {
  // Table 4's P1 and P4, one impossible lowering for P1, and P2's standard time, which no
  // hip time scale in range reaches (docs/diagnosis.md, "The sweep").
  const auto plant = load(kHeader +
                          "P1,0,0.463,0.031,5\nP1,0.05,0.423,0.031,5\nP1,0.45,0.40,0.031,5\n"
                          "P2,0,0.385,0.047,5\nP2,0.08,0.361,0.047,5\n"
                          "P4,0,0.444,0.033,5\nP4,0.09,0.417,0.033,5\n");
  const auto notes = plant->warnings();
  std::string all;
  for (const auto& n : notes) all += n + "\n";
  EXPECT_NE(all.find(std::string("m.csv:4: P1 at 450 mm is beyond the shank's physical limit")), std::string::npos)
      << all;
  EXPECT_NE(all.find("P2 is outside the model"), std::string::npos) << all;
  EXPECT_NE(all.find("P3 is outside the model and takes no part in the fits or folds: not measured"), std::string::npos)
      << all;
  EXPECT_EQ(plant->validationStems(), (std::vector<std::string>{"P1", "P4"}));
}

}  // namespace
}  // namespace swingsim
