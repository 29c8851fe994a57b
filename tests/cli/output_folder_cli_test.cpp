// One run per output folder, from the command line: a sweep or fit that cannot put its whole
// set in place leaves the earlier run intact, a second sweep leaves no figure of the first, a
// killed run's staging is cleaned (a live sibling's is not), simulate's CSV, .sto and figure
// appear together or not at all, and an over-long --out is answered with its length first.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/output_files.h"
#include "run_swingsim.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::runSwingsim;
using testing::slurp;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_output_folder_cli_test", name); }

// A sweep study of `participants` (file names under participants/), two lowerings.
fs::path writeStudy(const fs::path& dir, const std::vector<std::string>& participants) {
  const fs::path path = dir / "study.yaml";
  std::ofstream out(path);
  out << "kind: knee-axis-sweep\nname: two\nparticipants: [";
  for (std::size_t i = 0; i < participants.size(); ++i)
    out << (i ? ", " : "") << SWINGSIM_SOURCE_DIR << "/participants/" << participants[i];
  out << "]\nlowering: {step_m: 0.05, max_m: 0.05, include_published: false}\n";
  return path;
}

// Every name below `dir` that shows staging or a temporary file.
std::vector<std::string> litterIn(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".staging-") != std::string::npos || name.find(".tmp-") != std::string::npos) found.push_back(name);
  }
  return found;
}

TEST(OutputFolderCli, ASweepWithAFolderInTheWayOfSweepCsvKeepsTheEarlierRunIntact) {
  const fs::path dir = freshDir("in-the-way");
  const fs::path study = writeStudy(dir, {"p1.yaml"}), out = dir / "out";
  ASSERT_EQ(runSwingsim("sweep " + study.string() + " --out " + out.string()).code, 0);
  // Marks to tell the earlier run's files from a new run's.
  std::ofstream(out / "report.md") << "earlier report";
  std::ofstream(out / "figures" / "P1-swing-time.svg") << "earlier figure";
  fs::remove(out / "sweep.csv");
  fs::create_directories(out / "sweep.csv");
  const auto r = runSwingsim("sweep " + study.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--out " + out.string() + ": a folder is in the way of the output file sweep.csv"));
  EXPECT_THAT(r.output, Not(HasSubstr(".staging")));
  EXPECT_EQ(slurp(out / "report.md"), "earlier report");
  EXPECT_EQ(slurp(out / "figures" / "P1-swing-time.svg"), "earlier figure");
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(OutputFolderCli, TwoSweepsIntoOneFolderLeaveOnlyTheSecondsFigures) {
  const fs::path dir = freshDir("two-sweeps");
  const fs::path out = dir / "out";
  ASSERT_EQ(runSwingsim("sweep " + writeStudy(dir, {"p1.yaml", "p2.yaml"}).string() + " --out " + out.string()).code,
            0);
  ASSERT_TRUE(fs::exists(out / "figures" / "P2-swing-time.svg"));
  std::ofstream(out / "my-notes.txt") << "mine";
  ASSERT_EQ(runSwingsim("sweep " + writeStudy(dir, {"p1.yaml"}).string() + " --out " + out.string()).code, 0);
  EXPECT_TRUE(fs::exists(out / "figures" / "P1-swing-time.svg"));
  for (const char* figure : {"P2-swing-time.svg", "P2-knee-flexion.svg", "P2-filmstrip.svg"})
    EXPECT_FALSE(fs::exists(out / "figures" / figure)) << figure;
  EXPECT_THAT(slurp(out / "report.md"), Not(HasSubstr("P2")));
  EXPECT_EQ(slurp(out / "my-notes.txt"), "mine");
}

TEST(OutputFolderCli, ASweepCleansTheStagingOfAKilledRunButNotOfALiveSibling) {
  const fs::path dir = freshDir("killed");
  const fs::path out = dir / "out";
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const std::string mine = makeStagingFolderName(), host = mine.substr(0, mine.rfind('-') + 1);
  // A run SIGKILLed while writing its report, and a Slurm sibling (this test) still running.
  for (const std::string& name : {host + std::to_string(dead), host + std::to_string(::getpid())}) {
    fs::create_directories(out / name / "figures");
    std::ofstream(out / name / "report.md") << "half";
  }
  ASSERT_EQ(runSwingsim("sweep " + writeStudy(dir, {"p1.yaml"}).string() + " --out " + out.string()).code, 0);
  EXPECT_FALSE(fs::exists(out / (host + std::to_string(dead))));
  EXPECT_EQ(slurp(out / (host + std::to_string(::getpid())) / "report.md"), "half");
}

TEST(OutputFolderCli, SimulateWritesItsCsvStoAndFigureTogetherOrNone) {
  const fs::path dir = freshDir("simulate");
  const fs::path out = dir / "out";
  fs::create_directories(out / "P1-lower000mm.sto");  // the second of the three files cannot be written
  const auto r = runSwingsim("simulate " + std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml --out " +
                             out.string() + " --json " + (dir / "r.json").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("--out " + out.string() + ": a folder is in the way of the output file P1-lower000mm.sto"));
  EXPECT_FALSE(fs::exists(out / "P1-lower000mm.csv"));
  EXPECT_FALSE(fs::exists(out / "P1-lower000mm-moments.svg"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(OutputFolderCli, AFitWithAFolderInTheWayOfItsCsvWritesNoFigureAndKeepsTheEarlierReport) {
  const fs::path dir = freshDir("fit");
  const fs::path out = dir / "out";
  const std::string fit = "fit " + std::string(SWINGSIM_SOURCE_DIR) + "/studies/mauch2014.yaml --out " + out.string();
  ASSERT_EQ(runSwingsim(fit).code, 0);
  std::ofstream(out / "report.md") << "earlier report";
  fs::remove(out / "mauch-2phase-slow-force.svg");
  fs::remove(out / "coefficients.csv");
  fs::create_directories(out / "coefficients.csv");
  const auto r = runSwingsim(fit);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("--out " + out.string() + ": a folder is in the way of the output file coefficients.csv"));
  EXPECT_EQ(slurp(out / "report.md"), "earlier report");
  EXPECT_FALSE(fs::exists(out / "mauch-2phase-slow-force.svg"));  // the figures come before the CSV
  EXPECT_EQ(litterIn(dir), std::vector<std::string>{});
}

TEST(OutputFolderCli, AFiveThousandCharacterOutIsAnsweredWithItsLength) {
  const fs::path dir = freshDir("long");
  const std::string longOut = (dir / std::string(5000, 'b')).string();
  const auto r = runSwingsim("simulate " + std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml --out " + longOut);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--out: path too long (" + std::to_string(longOut.size()) +
                                  " characters; this system allows "));
  EXPECT_THAT(r.output, HasSubstr(" per path here / 255 per name)"));
  EXPECT_LT(r.output.size(), 1000u) << "the path is quoted whole";
}

}  // namespace
}  // namespace swingsim
