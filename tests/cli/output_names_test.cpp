// Names from user files become file names: they stay inside --out, never collide, and keep
// the CSV readable; an empty --out is a usage error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "core/output_files.h"
#include "run_swingsim.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
const std::string kRoot = SWINGSIM_SOURCE_DIR;

fs::path freshDir(const std::string& name) { return testing::freshTempDir("swingsim_output_names_test", name); }

// P1 under another name, its knee model path made absolute.
fs::path writeParticipant(const fs::path& dir, const std::string& file, const std::string& name) {
  std::string t = testing::slurp(kRoot + "/participants/p1.yaml");
  t = std::regex_replace(t, std::regex("\\.\\./models/"), kRoot + "/models/");
  t = std::regex_replace(t, std::regex("\nname: P1\n"), "\nname: \"" + name + "\"\n");
  std::ofstream(dir / file) << t;
  return dir / file;
}

fs::path writeStudy(const fs::path& dir, const std::vector<fs::path>& participants) {
  std::string list;
  for (const auto& p : participants) list += (list.empty() ? "" : ", ") + p.string();
  std::ofstream(dir / "study.yaml") << "kind: knee-axis-sweep\nname: names\nparticipants: [" << list
                                    << "]\nlowering: {step_m: 0.1, max_m: 0.1, include_published: false}\n";
  return dir / "study.yaml";
}

TEST(OutputNames, SafeStemsKeepSeparatorsOutAndStayUnique) {
  EXPECT_EQ(makeSafeFileStem("P1"), "P1");
  EXPECT_EQ(makeSafeFileStem("P1-a_b.2"), "P1-a_b.2");
  const std::string escaped = makeSafeFileStem("../../../escaped/P1");
  EXPECT_EQ(escaped.find('/'), std::string::npos);
  EXPECT_NE(escaped.rfind("..", 0), 0u);
  EXPECT_NE(makeSafeFileStem("a/b"), makeSafeFileStem("a_b"));
  const std::string longName(300, 'x');
  EXPECT_LE(makeSafeFileStem(longName).size(), 64u);
  EXPECT_NE(makeSafeFileStem(longName), makeSafeFileStem(longName + "y"));
}

TEST(OutputNames, AParticipantNamedWithSeparatorsAndACommaWritesOnlyInsideOut) {
  const fs::path dir = freshDir("escape");
  const fs::path study = writeStudy(dir, {writeParticipant(dir, "p.yaml", "../../../escaped/P1, left")});
  const fs::path out = dir / "out";
  const auto r = testing::runSwingsim("sweep " + study.string() + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / "escaped"));
  EXPECT_FALSE(fs::exists(fs::path(kRoot).parent_path() / "escaped"));
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string path = fs::canonical(e.path()).string();
    EXPECT_EQ(path.rfind(fs::canonical(dir).string(), 0), 0u) << path;
  }
  // The CSV quotes the name (RFC 4180): every row still has 11 fields.
  const std::string csv = testing::slurp(out / "sweep.csv");
  EXPECT_THAT(csv, HasSubstr("\"../../../escaped/P1, left\",0.000,"));
}

TEST(OutputNames, TwoParticipantsWithOneNameAreAnError) {
  const fs::path dir = freshDir("duplicate");
  const fs::path study =
      writeStudy(dir, {writeParticipant(dir, "a.yaml", "P1"), writeParticipant(dir, "b.yaml", "P1")});
  const auto r = testing::runSwingsim("sweep " + study.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.output, HasSubstr("study.yaml:3: participants: two participant files have the same name 'P1'"));
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(OutputNames, EmptyOutIsAUsageErrorAndNearbyLoweringsGetTheirOwnFiles) {
  const auto empty = testing::runSwingsim("simulate participants/p1.yaml --out \"\"");
  EXPECT_EQ(empty.code, 2);
  EXPECT_THAT(empty.output, HasSubstr("--out: expected a value, got an empty string"));
  const fs::path dir = freshDir("lowering");
  ASSERT_EQ(testing::runSwingsim("simulate participants/p1.yaml --out " + dir.string()).code, 0);
  ASSERT_EQ(testing::runSwingsim("simulate participants/p1.yaml --lowering 0.0004 --out " + dir.string()).code, 0);
  EXPECT_TRUE(fs::exists(dir / "P1-lower000mm.csv"));
  EXPECT_TRUE(fs::exists(dir / "P1-lower0.4mm.csv"));
}

}  // namespace
}  // namespace swingsim
