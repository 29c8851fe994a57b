// No command writes over one of its own inputs (core/output_paths.h, checkOutputsAreNotInputs):
// an --out, --json or --save-model that is an input file, by the same path, another
// spelling of it or a link to it, is refused before any work, exit 1, naming both, and
// the input is left as it was. Also the .osim import's messages name the model, not the YAML.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_swingsim.h"

namespace swingsim::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

namespace fs = std::filesystem;

const std::string kSuite = "OutputOverInput";
const std::string kTinyLeg = std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/osim-tiny-leg.osim";

// A copy of the tiny leg model in a fresh folder `name`.
std::string copyTinyLeg(const std::string& name) {
  const fs::path dir = freshTempDir(kSuite, name);
  fs::copy_file(kTinyLeg, dir / "model.osim");
  return (dir / "model.osim").string();
}

TEST(OutputOverInput, ImportOsimOutOntoItsModelIsRefusedAndTheModelKept) {
  const std::string model = copyTinyLeg("import");
  const std::string before = slurp(model);
  const CliRun run = runSwingsim("import-osim " + model + " --side r --out " + model);
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--out '" + model + "': would write over the input MODEL.osim '" + model + "'"));
  EXPECT_EQ(slurp(model), before);
  // Another spelling of the same file: ./ and .. in the path, and a link to it.
  const fs::path dir = fs::path(model).parent_path();
  const std::string dotted = (dir / "." / ".." / dir.filename() / "model.osim").string();
  EXPECT_EQ(runSwingsim("import-osim " + model + " --out " + dotted).code, 1);
  fs::create_symlink(model, dir / "link.osim");
  const CliRun link = runSwingsim("import-osim " + model + " --out " + (dir / "link.osim").string());
  EXPECT_EQ(link.code, 1) << link.output;
  EXPECT_THAT(link.output, HasSubstr("would write over the input MODEL.osim"));
  EXPECT_EQ(slurp(model), before);
}

TEST(OutputOverInput, SimulateJsonOntoItsParticipantIsRefused) {
  const std::string model = copyTinyLeg("simulate");
  const std::string participant = (fs::path(model).parent_path() / "p.yaml").string();
  ASSERT_EQ(runSwingsim("import-osim " + model + " --out " + participant).code, 0);
  const std::string before = slurp(participant);
  const CliRun run = runSwingsim("simulate " + participant + " --out " +
                                 (fs::path(model).parent_path() / "out").string() + " --json " + participant);
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--json '" + participant + "': would write over the input PARTICIPANT.yaml"));
  EXPECT_THAT(run.output, Not(HasSubstr("swing time")));  // refused before the swing
  EXPECT_EQ(slurp(participant), before);
}

TEST(OutputOverInput, SweepJsonOntoItsStudyIsRefused) {
  const std::string study =
      writeSuiteTempFile(kSuite, "sweep.yaml",
                         "kind: knee-axis-sweep\nname: tiny\nparticipants:\n  - " + std::string(SWINGSIM_SOURCE_DIR) +
                             "/participants/p1.yaml\nlowering:\n  step_m: 0.01\n  max_m: 0.01\n");
  const std::string before = slurp(study);
  const CliRun run =
      runSwingsim("sweep " + study + " --out " + (suiteTempDir(kSuite) / "sweep-out").string() + " --json " + study);
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--json '" + study + "': would write over the input STUDY.yaml '" + study + "'"));
  EXPECT_EQ(slurp(study), before);
}

TEST(OutputOverInput, SweepOutFolderHoldingItsStudyAsAReportFileIsRefused) {
  // The study is named like the report the sweep writes into --out.
  const fs::path dir = freshTempDir(kSuite, "sweep-folder");
  const std::string study = (dir / "report.md").string();
  fs::copy_file(
      writeSuiteTempFile(kSuite, "sweep-for-folder.yaml",
                         "kind: knee-axis-sweep\nname: tiny\nparticipants:\n  - " + std::string(SWINGSIM_SOURCE_DIR) +
                             "/participants/p1.yaml\nlowering:\n  step_m: 0.01\n  max_m: 0.01\n"),
      study);
  const std::string before = slurp(study);
  const CliRun run = runSwingsim("sweep " + study + " --out " + dir.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--out '" + study + "': would write over the input STUDY.yaml"));
  EXPECT_EQ(slurp(study), before);
}

TEST(OutputOverInput, SweepOutFolderHoldingAParticipantOfTheStudyAsAReportFileIsRefused) {
  // A participant file the study names is named like the report the sweep writes into --out.
  const fs::path dir = freshTempDir(kSuite, "sweep-participant");
  const fs::path participant = dir / "report.md";
  std::string p1 = slurp(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml");
  const std::string relativeModel = "knee_model: ../models/";
  ASSERT_NE(p1.find(relativeModel), std::string::npos);
  p1.replace(p1.find(relativeModel), relativeModel.size(),
             "knee_model: " + std::string(SWINGSIM_SOURCE_DIR) + "/models/");
  std::ofstream(participant) << p1;
  const std::string study =
      writeSuiteTempFile(kSuite, "sweep-participant.yaml",
                         "kind: knee-axis-sweep\nname: tiny\nparticipants:\n  - " + participant.string() +
                             "\nlowering:\n  step_m: 0.01\n  max_m: 0.01\n");
  const std::string before = slurp(participant.string());
  const CliRun run = runSwingsim("sweep " + study + " --out " + dir.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output,
              HasSubstr("--out '" + participant.string() + "': would write over the input STUDY.yaml: participant"));
  EXPECT_EQ(slurp(participant.string()), before);
}

TEST(OutputOverInput, DiagnoseAndCompareJsonOntoATrainingRecordOfTheStudyAreRefused) {
  // A copy of the cylinder demo (its records copied too), so a failing check writes over
  // nothing of the repository.
  const fs::path dir = freshTempDir(kSuite, "diagnose-record");
  const std::string data = std::string(SWINGSIM_SOURCE_DIR) + "/studies/data/diagnose-demo-cylinder/";
  for (const char* name : {"normal.csv", "slow.csv", "fast.csv"}) fs::copy_file(data + name, dir / name);
  const fs::path study = dir / "study.yaml";
  std::ofstream(study) << "kind: cylinder-diagnosis\nname: copy\nbase_model: " << SWINGSIM_SOURCE_DIR
                       << "/models/mauch-4phase.yaml\ntrain:\n  - normal.csv\nvalidate:\n  - slow.csv\n  - fast.csv\n";
  const fs::path record = dir / "normal.csv";
  const std::string before = slurp(record.string());
  for (const std::string command : {"diagnose", "compare"}) {
    const CliRun run =
        runSwingsim(command + " " + study.string() + " --out " + (dir / "out").string() + " --json " + record.string());
    EXPECT_EQ(run.code, 1) << command << ": " << run.output;
    EXPECT_THAT(run.output, HasSubstr("--json '" + record.string() +
                                      "': would write over the input STUDY.yaml: train record normal"))
        << command;
    EXPECT_EQ(slurp(record.string()), before) << command;
  }
}

TEST(OutputOverInput, SwingsJsonOntoItsMotionFileIsRefused) {
  const fs::path dir = freshTempDir(kSuite, "swings");
  const fs::path mot = dir / "ik.mot";
  fs::copy_file(std::string(SWINGSIM_SOURCE_DIR) + "/tests/data/opensim-running/hamner_subject02_running_ik.mot", mot);
  const std::string before = slurp(mot);
  const CliRun run = runSwingsim("swings " + mot.string() + " --json " + mot.string());
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--json '" + mot.string() + "': would write over the input FILE.mot"));
  EXPECT_EQ(slurp(mot), before);
}

TEST(OutputOverInput, ImportOsimMessagesNameTheModelElementNotTheOutputYaml) {
  // A negative inertia used to be reported at the participant YAML not yet written.
  const std::string model = copyTinyLeg("inertia");
  std::string xml = slurp(model);
  xml.replace(xml.find("0.04 0.005 0.05"), 15, "0.04 0.005 -0.05");
  writeSuiteTempFile(kSuite, "inertia/model.osim", xml);
  const std::string out = (fs::path(model).parent_path() / "o.yaml").string();
  const CliRun run = runSwingsim("import-osim " + model + " --out " + out);
  EXPECT_EQ(run.code, 1) << run.output;
  EXPECT_THAT(run.output,
              HasSubstr(model + ":7: <Body name=\"tibia_r\">: <inertia>: expected moments of inertia >= 0"));
  EXPECT_THAT(run.output, Not(HasSubstr("o.yaml")));
  EXPECT_FALSE(fs::exists(out));
  // What only the participant file's checks see (a prosthesis heavier than 150 kg) is named
  // by the model and the key, not by the YAML and its line.
  const std::string tiny = copyTinyLeg("heavy");
  const CliRun heavy = runSwingsim("import-osim " + tiny + " --shank-mass-kg 200 --out " + out);
  EXPECT_EQ(heavy.code, 1) << heavy.output;
  EXPECT_THAT(heavy.output,
              HasSubstr(tiny + ": the participant imported from it is refused: segments.shank.mass_kg: expected "
                               "a segment mass of at most 150 kg"));
  EXPECT_THAT(heavy.output, Not(HasSubstr("o.yaml")));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace swingsim::testing
