// A catalogue of the ways users get input files wrong, for every loader: each
// case either gives a clear InputError naming the file (and line and key where there is
// one) or is a documented, tested acceptance. Acceptances: a UTF-8 byte-order mark and
// CRLF line ends simply work. Numbers that are finite but absurd are refused at load by
// their plausible range (core/plausible_ranges.h, docs/robustness.md).
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "../cli/run_swingsim.h"
#include "../core/cpu_time.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "io/bench_csv.h"
#include "io/csv_table.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/yaml_reader.h"
#include "knee/bench_profile.h"
#include "study/cylinder_study.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// YAML loaders
// ---------------------------------------------------------------------------------------

using YamlParse = std::function<void(const std::string& text, const std::string& path)>;

void parseCylinderStudy(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  if (!yaml.has("kind")) yaml.getString("kind");
  if (yaml.getChoice("kind", {"cylinder-bench", "cylinder-fit"}, "") == "cylinder-bench")
    readCylinderBenchStudy(yaml);
  else
    readCylinderFitStudy(yaml);
  yaml.finish();
}

/// One YAML loader with a real file it accepts and a numeric key in it to corrupt.
struct YamlLoader {
  std::string name;
  std::string file;        ///< bundled file, relative to the source folder
  std::string numericKey;  ///< a key of that file holding a plain number
  YamlParse parse;
};

std::vector<YamlLoader> yamlLoaders() {
  return {
      {"participant", "participants/p1.yaml", "knee_friction_Nm",
       [](const std::string& t, const std::string& p) { parseParticipant(t, p); }},
      {"knee model (damping table)", "models/damping-table-default.yaml", "extension_factor",
       [](const std::string& t, const std::string& p) { parseKneeModel(t, p); }},
      {"knee model (Mauch)", "models/mauch-4phase.yaml", "latch_rate_per_s",
       [](const std::string& t, const std::string& p) { parseKneeModel(t, p); }},
      {"sweep study", "studies/burkett2004.yaml", "accuracy",
       [](const std::string& t, const std::string& p) { parseSweepStudy(t, p); }},
      {"cylinder-fit study", "studies/mauch2014.yaml", "plot_seconds", parseCylinderStudy},
      {"cylinder-bench study", "studies/mauch2014-bench.yaml", "noise_N", parseCylinderStudy},
  };
}

/// The InputError message, "" if the text loads, or a marker for any other exception.
std::string errorOf(const YamlLoader& l, const std::string& text) {
  try {
    l.parse(text, l.file);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(not an InputError) ") + e.what();
  }
  return "";
}

/// The loader's file with `key: VALUE` given a new value.
std::string withValue(const YamlLoader& l, const std::string& value) {
  std::string text = readFile(l.file);
  const auto at = text.find(l.numericKey + ": ");
  EXPECT_NE(at, std::string::npos) << l.file << " has no " << l.numericKey;
  const auto begin = at + l.numericKey.size() + 2;
  const auto end = text.find_first_of(" \r\n#,}", begin);
  return text.replace(begin, end - begin, value);
}

TEST(BadInputCatalogue, YamlBundledFilesLoad) {
  for (const auto& l : yamlLoaders()) EXPECT_EQ(errorOf(l, readFile(l.file)), "") << l.name;
}

TEST(BadInputCatalogue, YamlEmptyFileOrOnlyCommentsNeedsAMapping) {
  for (const auto& l : yamlLoaders()) {
    for (const char* text : {"", "\n\n", "# nothing here\n", "\xEF\xBB\xBF"}) {
      EXPECT_THAT(errorOf(l, text), StartsWith(l.file + ":1: expected a YAML mapping of keys (got nothing)")) << l.name;
    }
  }
}

TEST(BadInputCatalogue, YamlBinaryGarbageIsAnInputErrorNamingTheFile) {
  std::string garbage;
  for (int i = 0; i < 512; ++i) garbage.push_back(static_cast<char>((i * 73 + 11) % 256));
  const std::string nulls("\0\0\0\x01\x02", 5);
  for (const auto& l : yamlLoaders()) {
    for (const std::string& text : {garbage, nulls, std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)}) {
      EXPECT_THAT(errorOf(l, text), StartsWith(l.file + ":")) << l.name;
    }
  }
}

TEST(BadInputCatalogue, YamlByteOrderMarkAndCrlfSimplyWork) {
  for (const auto& l : yamlLoaders()) {
    const std::string text = readFile(l.file);
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(errorOf(l, "\xEF\xBB\xBF" + text), "") << l.name << " with a BOM";
    EXPECT_EQ(errorOf(l, crlf), "") << l.name << " with CRLF";
    EXPECT_EQ(errorOf(l, "\xEF\xBB\xBF" + crlf), "") << l.name << " with a BOM and CRLF";
  }
  // The values are the same, not just accepted.
  const std::string p1 = readFile("participants/p1.yaml");
  std::string crlf;
  for (char c : p1) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const Participant a = parseParticipant(p1, "participants/p1.yaml");
  const Participant b = parseParticipant("\xEF\xBB\xBF" + crlf, "participants/p1.yaml");
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.kneeModelPath, b.kneeModelPath);
  EXPECT_EQ(a.thigh.inertia, b.thigh.inertia);
  EXPECT_EQ(a.hipMoment.timeScale, b.hipMoment.timeScale);
}

TEST(BadInputCatalogue, YamlCommaDecimalSeparatorIsNamed) {
  for (const auto& l : yamlLoaders()) {
    EXPECT_THAT(errorOf(l, withValue(l, "0,5")),
                HasSubstr(l.numericKey + ": expected a number with a decimal point, not a comma (got '0,5')"))
        << l.name;
  }
}

TEST(BadInputCatalogue, YamlDuplicatedKeyIsNamedWithItsLine) {
  for (const auto& l : yamlLoaders()) {
    const std::string text = readFile(l.file) + "name: again\n";
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    EXPECT_THAT(errorOf(l, text), HasSubstr(l.file + ":" + std::to_string(lines) + ": name: key appears twice"))
        << l.name;
  }
}

TEST(BadInputCatalogue, YamlNanAndInfinityAreRefused) {
  for (const auto& l : yamlLoaders()) {
    for (const char* v : {".nan", "NaN", "nan", ".inf", "-.inf", "inf", "1e999", "-1e999"}) {
      EXPECT_THAT(errorOf(l, withValue(l, v)), HasSubstr(l.numericKey + ": expected a finite number"))
          << l.name << " " << v;
    }
  }
}

TEST(BadInputCatalogue, YamlNotANumberAndWrongTypes) {
  for (const auto& l : yamlLoaders()) {
    EXPECT_THAT(errorOf(l, withValue(l, "ten")), HasSubstr(l.numericKey + ": expected a number (got 'ten')")) << l.name;
    EXPECT_THAT(errorOf(l, withValue(l, "[1, 2]")), HasSubstr(l.numericKey + ": expected a number (got a list)"))
        << l.name;
  }
}

// Documented acceptance: `key:` with nothing after it is YAML's null, read as "not given":
// an optional key takes its default, a required key is reported missing.
TEST(BadInputCatalogue, YamlEmptyValueMeansNotGiven) {
  for (const auto& l : yamlLoaders()) {
    const std::string e = errorOf(l, withValue(l, ""));
    EXPECT_TRUE(e.empty() || e.find(l.numericKey) != std::string::npos) << l.name << ": " << e;
  }
  EXPECT_THAT(errorOf(yamlLoaders()[0], withValue(yamlLoaders()[0], "")),
              HasSubstr("knee_friction_Nm: expected a number (got nothing)"));
  const Participant p =
      parseParticipant(readFile("participants/p1.yaml")
                           .replace(readFile("participants/p1.yaml").find("time_limit_s: 1.5"), 17, "time_limit_s:"),
                       "participants/p1.yaml");
  EXPECT_EQ(p.swingEnd.timeLimit, SwingEndRule{}.timeLimit);
}

TEST(BadInputCatalogue, YamlSyntaxErrorsNameTheLine) {
  for (const auto& l : yamlLoaders()) {
    EXPECT_THAT(errorOf(l, readFile(l.file) + "oops: [1, 2\n"), HasSubstr(": YAML syntax error")) << l.name;
    EXPECT_THAT(errorOf(l, "name: x\n\tindented: with a tab\n"), StartsWith(l.file + ":")) << l.name;
  }
}

TEST(BadInputCatalogue, YamlUnknownKeyIsNamed) {
  for (const auto& l : yamlLoaders()) {
    EXPECT_THAT(errorOf(l, readFile(l.file) + "colour: blue\n"), HasSubstr("colour: unknown key")) << l.name;
  }
}

// Documented acceptance: huge but finite numbers load wherever no physical bound is
// known (a viscous coefficient, a noise level); where one is known the loader refuses.
TEST(BadInputCatalogue, YamlHugeNumbers) {
  for (const auto& l : yamlLoaders()) {
    const std::string e = errorOf(l, withValue(l, "1e300"));
    EXPECT_THAT(e, ::testing::Not(HasSubstr("not an InputError"))) << l.name;
  }
  const YamlLoader participant = yamlLoaders()[0];
  EXPECT_THAT(errorOf(participant,
                      readFile("participants/p1.yaml")
                          .replace(readFile("participants/p1.yaml").find("height_m: 1.83"), 14, "height_m: 1e300")),
              HasSubstr("height_m: expected a standing height between 0.5 and 2.6 m (got 1e+300)"));
  const YamlLoader sweep = yamlLoaders()[3];
  EXPECT_THAT(errorOf(sweep, withValue(sweep, "1e300")),
              HasSubstr("accuracy: expected a relative accuracy in [1e-14, 0.01] (got 1e+300)"));
}

// An alias that refers to an alias ... ("billion laughs") must not take exponential time.
TEST(BadInputCatalogue, YamlAliasBombIsRefusedQuickly) {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 12; ++i) {
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) text += (k ? ", *a" : "*a") + std::to_string(i - 1);
    text += "]\n";
  }
  const double seconds = swingsim::testing::cpuSecondsOf([&] {
    for (const auto& l : yamlLoaders()) EXPECT_THAT(errorOf(l, text), StartsWith(l.file + ":")) << l.name;
  });
  constexpr double kQuick = 10.0;  // CPU s, for all loaders under sanitizers (1.4 s); 10^12 nodes would take days
  EXPECT_LT(seconds, kQuick);
}

TEST(BadInputCatalogue, YamlDeepNestingIsAnErrorNotAStackOverflow) {
  for (const auto& l : yamlLoaders()) {
    EXPECT_THAT(errorOf(l, "name: " + std::string(100000, '[') + "\n"), StartsWith(l.file + ":")) << l.name;
    EXPECT_THAT(errorOf(l, "name: " + std::string(100000, '{') + "\n"), StartsWith(l.file + ":")) << l.name;
  }
}

TEST(BadInputCatalogue, YamlMissingFileSaysSo) {
  EXPECT_THAT(
      errorOf(YamlLoader{"missing", "", "",
                         [](const std::string&, const std::string&) { loadParticipant("participants/nobody.yaml"); }},
              ""),
      HasSubstr("participants/nobody.yaml: cannot open file"));
  try {
    loadKneeModel("models");  // a directory
    ADD_FAILURE() << "a directory loaded as a knee model";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith("models"));
  }
}

// ---------------------------------------------------------------------------------------
// CSV readers: the bench data (cylinder fit) and the generic reader
// ---------------------------------------------------------------------------------------

fs::path tempDir() { return testing::suiteTempDir("swingsim_bad_input_catalogue"); }

std::string writeTemp(const std::string& name, const std::string& text) {
  return testing::writeSuiteTempFile("swingsim_bad_input_catalogue", name, text);
}

std::string benchError(const std::string& name, const std::string& text) {
  try {
    readBenchCsv(writeTemp(name, text), 3);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(not an InputError) ") + e.what();
  }
  return "";
}

const std::string kBenchGood = "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,12\n0.02,0.004,15\n0.03,0.003,11\n";

TEST(BadInputCatalogue, CsvGoodBenchFileReads) {
  const BenchData d = readBenchCsv(writeTemp("good.csv", kBenchGood), 3);
  EXPECT_EQ(d.time.size(), 4u);
  EXPECT_EQ(d.force[2], 15);
}

TEST(BadInputCatalogue, CsvEmptyFile) {
  EXPECT_THAT(benchError("empty.csv", ""), HasSubstr("empty.csv:1: empty file (expected a header row: time_s,...)"));
  EXPECT_THAT(benchError("blank.csv", "\n\n"), HasSubstr("blank.csv:1: empty file"));
  EXPECT_THAT(benchError("header.csv", "time_s,position_m,force_N\n"),
              HasSubstr("header.csv: too few data rows (got 0, need at least 3)"));
}

TEST(BadInputCatalogue, CsvBinaryGarbage) {
  std::string garbage("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
  EXPECT_THAT(benchError("png.csv", garbage), HasSubstr("png.csv: not a text CSV file (contains NUL bytes)"));
  std::string noNul;
  for (int i = 0; i < 512; ++i) noNul.push_back(static_cast<char>(1 + (i * 73 + 11) % 255));
  EXPECT_THAT(benchError("noise.csv", noNul), StartsWith(tempDir().string() + "/noise.csv:"));
  // UTF-16, as some Windows software exports: NUL bytes between the letters.
  std::string utf16 = "\xFF\xFE";
  for (char c : kBenchGood) utf16 += std::string(1, c) + '\0';
  EXPECT_THAT(benchError("utf16.csv", utf16), HasSubstr("utf16.csv: not a text CSV file (contains NUL bytes)"));
}

TEST(BadInputCatalogue, CsvByteOrderMarkAndCrlfSimplyWork) {
  std::string crlf;
  for (char c : kBenchGood) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  for (const auto& [name, text] :
       std::vector<std::pair<std::string, std::string>>{{"bom.csv", "\xEF\xBB\xBF" + kBenchGood},
                                                        {"crlf.csv", crlf},
                                                        {"bomcrlf.csv", "\xEF\xBB\xBF" + crlf},
                                                        {"noeol.csv", kBenchGood.substr(0, kBenchGood.size() - 1)},
                                                        {"trailing.csv", kBenchGood + "\n\r\n\n"}}) {
    const BenchData d = readBenchCsv(writeTemp(name, text), 3);
    EXPECT_EQ(d.time.size(), 4u) << name;
    EXPECT_EQ(d.position[3], 0.003) << name;
  }
}

TEST(BadInputCatalogue, CsvCommaDecimalSeparator) {
  // Semicolon-separated with decimal commas (a German or French spreadsheet export).
  EXPECT_THAT(benchError("semicolon.csv", "time_s;position_m;force_N\n0;0,001;10\n0,01;0,002;12\n0,02;0,004;15\n"),
              HasSubstr("semicolon.csv:1: time_s: required column is missing"));
  // Comma-separated with decimal commas: the cell counts disagree with the header.
  EXPECT_THAT(benchError("comma.csv", "time_s,position_m,force_N\n0,0,001,10\n0,01,0,002,12\n0,02,0,004,15\n"),
              HasSubstr("comma.csv:2: expected 3 comma-separated values (got 4); is the decimal separator a comma?"));
  // Quoted decimal commas.
  EXPECT_THAT(benchError("quoted.csv", "time_s,position_m,force_N\n\"0\",\"0,001\",\"10\"\n"),
              HasSubstr("quoted.csv:2: expected 3 comma-separated values (got 4)"));
}

TEST(BadInputCatalogue, CsvDuplicatedAndMissingColumns) {
  EXPECT_THAT(benchError("dup.csv", "time_s,position_m,force_N,force_N\n0,0,1,1\n"),
              HasSubstr("dup.csv:1: force_N: column appears twice in the header"));
  EXPECT_THAT(benchError("dupextra.csv", "time_s,position_m,force_N,note,note\n0,0,1,1,1\n"),
              HasSubstr("dupextra.csv:1: note: column appears twice in the header"));
  EXPECT_THAT(benchError("missing.csv", "time_s,force_N\n0,1\n0.1,2\n0.2,3\n"),
              HasSubstr("missing.csv:1: position_m: required column is missing (got header 'time_s,force_N')"));
  EXPECT_THAT(benchError("noheader.csv", "0,0.001,10\n0.01,0.002,12\n0.02,0.004,15\n"),
              HasSubstr("noheader.csv:1: time_s: required column is missing (got header '0,0.001,10')"));
  EXPECT_THAT(benchError("case.csv", "Time_s,position_m,force_N\n0,0,1\n"),
              HasSubstr("time_s: required column is missing"));
  EXPECT_THAT(benchError("ragged.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002\n"),
              HasSubstr("ragged.csv:3: expected 3 comma-separated values (got 2)"));
  // Extra columns are read past and listed (documented acceptance).
  CsvSpec spec;
  spec.required = {"time_s"};
  const CsvTable t = parseCsv("time_s,comment\n0,left heel\n1,right heel\n", "extra.csv", spec);
  EXPECT_EQ(t.ignored, std::vector<std::string>{"comment"});
}

TEST(BadInputCatalogue, CsvNonMonotonicOrRepeatedTime) {
  EXPECT_THAT(benchError("back.csv", "time_s,position_m,force_N\n0,0.001,10\n0.02,0.002,12\n0.01,0.004,15\n"),
              HasSubstr("back.csv:4: time_s: must be strictly increasing (got 0.01 after 0.02)"));
  EXPECT_THAT(benchError("repeat.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,12\n0.01,0.004,15\n"),
              HasSubstr("repeat.csv:4: time_s: must be strictly increasing (got 0.01 after 0.01)"));
}

TEST(BadInputCatalogue, CsvNanInfinityHugeAndGaps) {
  for (const char* v : {"nan", "NaN", "-nan", "inf", "-Infinity", "1e309", "-1e400"}) {
    EXPECT_THAT(
        benchError("nonfinite.csv", std::string("time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,") + v + "\n"),
        HasSubstr("nonfinite.csv:3: force_N: expected a finite number (got '" + std::string(v) + "')"));
  }
  // A gap (empty cell) as lab software writes for a lost marker.
  EXPECT_THAT(benchError("gap.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,,12\n"),
              HasSubstr("gap.csv:3: position_m: expected a number (got '')"));
  EXPECT_THAT(benchError("text.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,n/a,12\n"),
              HasSubstr("text.csv:3: position_m: expected a number (got 'n/a')"));
  // Huge finite numbers are outside the plausible range (section "Plausibility ranges").
  EXPECT_THAT(benchError("huge.csv", "time_s,position_m,force_N\n0,0.001,1e300\n0.01,0.002,-1e300\n0.02,0.004,1\n"),
              HasSubstr("huge.csv:2: force_N: expected a force in [-100000, 100000] N"));
}

// A file with more rows than CsvSpec::maxRows is refused while reading, before the whole
// file is in memory (README "Robustness" gives the measured peak memory).
TEST(BadInputCatalogue, CsvTenMillionRowsAreRefusedQuickly) {
  const fs::path path = tempDir() / "ten-million.csv";
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("time_s,position_m,force_N\n", f);
    char line[64];
    for (long i = 0; i < 10000000; ++i) {
      const int n = std::snprintf(line, sizeof line, "%ld.%03ld,0.001,%ld\n", i / 1000, i % 1000, i % 97);
      std::fwrite(line, 1, static_cast<std::size_t>(n), f);
    }
    std::fclose(f);
  }
  std::string error;
  const double seconds = swingsim::testing::cpuSecondsOf([&] {
    try {
      readBenchCsv(path.string(), 3);
    } catch (const InputError& e) {
      error = e.what();
    }
  });
  fs::remove(path);
  EXPECT_THAT(error, HasSubstr("ten-million.csv: too many rows (more than 2000000"));
  EXPECT_THAT(error, HasSubstr("split the file or resample it"));
  constexpr double kQuick = 30.0;  // CPU s, under sanitizers (13.5 s; plain build: < 1 s)
  EXPECT_LT(seconds, kQuick);
}

TEST(BadInputCatalogue, CsvJustUnderTheRowLimitReads) {
  CsvSpec spec;
  spec.required = {"t"};
  spec.maxRows = 5;
  EXPECT_EQ(parseCsv("t\n1\n2\n3\n4\n5\n", "five.csv", spec).rows(), 5u);
  try {
    parseCsv("t\n1\n2\n3\n4\n5\n6\n", "six.csv", spec);
    ADD_FAILURE() << "six rows read with maxRows = 5";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("six.csv: too many rows"));
  }
}

// A file with no line breaks (a binary export, one endless line of numbers) is refused once a
// line passes the limit, not read whole; so is a file past the byte limit.
TEST(BadInputCatalogue, CsvEndlessLineAndOversizedFileAreRefusedAtTheLimit) {
  const std::string endless = "time_s,position_m,force_N\n" + std::string(3u << 20, '7');
  EXPECT_THAT(benchError("endless.csv", endless), HasSubstr("endless.csv:2: line longer than 1 MiB (the limit"));
  CsvSpec spec;
  spec.required = {"t"};
  spec.maxBytes = 20;
  EXPECT_EQ(parseCsv("t\n1\n2\n3\n", "small.csv", spec).rows(), 3u);
  try {
    parseCsv("t\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n", "big.csv", spec);
    ADD_FAILURE() << "read past maxBytes";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("big.csv: larger than 20 bytes (the limit"));
  }
}

TEST(BadInputCatalogue, CsvMissingFileAndDirectory) {
  EXPECT_THAT(benchError("../no/such/dir/x.csv", ""), HasSubstr("cannot"));
  try {
    readBenchCsv(tempDir().string(), 3);
    ADD_FAILURE() << "a directory read as CSV";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(tempDir().string()));
  }
}

// Documented acceptance: a gait cycle with no hyperextension (the piston never goes below
// x = 0) still fits the 4-phase model: the smooth hyperextension switch (position width
// 0.5 mm) keeps phase 4 partly active near full extension, enough to identify it. A record
// that never comes near extension is refused (FailingRuns.SingularRegression...).
TEST(BadInputCatalogue, BenchGaitCycleWithoutHyperextensionStillFits) {
  const MauchCylinderParams truth = loadMauchCylinder("models/mauch-4phase.yaml");
  BenchData d = readBenchCsv("studies/data/mauch2014/normal.csv", 3);
  for (double& x : d.position) x = std::max(x, 0.0);
  d.velocity = estimatePistonVelocity(d.time, d.position);
  d.force = calcCylinderTrace(MauchCylinder(truth), d.time, d.position, d.velocity).force;
  const CylinderFit fit = fitCylinder(truth, {d});
  EXPECT_EQ(fit.regression.rank, 12);
  constexpr double kRecovered = 1e-6;  // relative: noise-free data generated by the same model
  for (std::size_t ph = 0; ph < 4; ++ph)
    EXPECT_NEAR(fit.params.coefficients[ph].k, truth.coefficients[ph].k,
                kRecovered * std::fabs(truth.coefficients[ph].k))
        << ph;
}

// The Winter knee-angle table used by `swingsim generate`.
TEST(BadInputCatalogue, KneeAngleStrideMissingFramesAndBadColumns) {
  std::string text = "frame,knee_deg\n";
  for (int f = 1; f <= 20; ++f) text += std::to_string(f) + "," + std::to_string(f) + "\n";
  EXPECT_EQ(readKneeAngleStride(writeTemp("w.csv", text), 2, 12).flexion.size(), 10u);
  EXPECT_THAT(
      [&] {
        try {
          readKneeAngleStride(writeTemp("w.csv", text), 15, 40);
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      HasSubstr("frames 15 to 40 are not all present (found 6)"));
  try {
    readKneeAngleStride(writeTemp("w2.csv", "frame,knee\n1,2\n"), 1, 10);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("w2.csv:1: knee_deg: required column is missing"));
  }
}

// ---------------------------------------------------------------------------------------
// Size limits before parsing: a bounded reader, a YAML value count taken on the
// parser's events, and a directory named as one.
// ---------------------------------------------------------------------------------------

std::string loadError(const std::function<void()>& load) {
  try {
    load();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("(not an InputError) ") + e.what();
  }
  return "";
}

using swingsim::testing::cpuSecondsOf;

constexpr double kQuickRefusal =
    2.0;  // CPU s (0.5 s under sanitizers): a refusal reads at most 16 MiB, never the whole input

TEST(BadInputCatalogue, YamlFileOverTheSizeLimitIsRefusedNamingItsSizeAndTheLimit) {
  const fs::path path = tempDir() / "huge.yaml";
  {
    std::ofstream out(path, std::ios::binary);
    const std::string line(1023, '#');
    for (int i = 0; i < 17 * 1024; ++i) out << line << '\n';  // 17 MiB of comments
  }
  std::string e;
  EXPECT_LT(cpuSecondsOf([&] { e = loadError([&] { loadParticipant(path.string()); }); }), kQuickRefusal);
  fs::remove(path);
  EXPECT_THAT(e, StartsWith(path.string() + ": file too large"));
  EXPECT_THAT(e, HasSubstr("(17 MiB; the limit is 16 MiB"));
}

TEST(BadInputCatalogue, DevZeroIsRefusedByTheBoundedReaderNotReadForever) {
  std::string e;
  EXPECT_LT(cpuSecondsOf([&] { e = loadError([] { loadParticipant("/dev/zero"); }); }), kQuickRefusal);
  EXPECT_THAT(e, StartsWith("/dev/zero: file too large"));
  EXPECT_THAT(e, HasSubstr("not at its end (a device or a pipe?)"));
  EXPECT_THAT(e, HasSubstr("the limit is 16 MiB"));
}

TEST(BadInputCatalogue, AFifoThatNeverEndsIsRefusedAtTheLimit) {
  const fs::path fifo = tempDir() / "endless.yaml";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::signal(SIGPIPE, SIG_IGN);  // the writer learns of the closed pipe from write()
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    const std::string chunk(65536, 'a');
    while (fd >= 0 && ::write(fd, chunk.data(), chunk.size()) > 0) {
    }
    if (fd >= 0) ::close(fd);
  });
  const std::string e = loadError([&] { readFile(fifo.string()); });
  writer.join();
  fs::remove(fifo);
  EXPECT_THAT(e, StartsWith(fifo.string() + ": file too large"));
  EXPECT_THAT(e, HasSubstr("a device or a pipe?"));
}

TEST(BadInputCatalogue, ReadFileLimitIsExactToTheByte) {
  const std::string path = writeTemp("ten.txt", "0123456789");
  EXPECT_EQ(readFile(path, 10), "0123456789");
  EXPECT_THAT(loadError([&] { readFile(path, 9); }),
              HasSubstr("ten.txt: file too large for an input file (10 bytes; the limit is 9 bytes)"));
}

TEST(BadInputCatalogue, LongFlowListUnderAnUnknownKeyIsRefusedQuickly) {
  std::string text = readFile("participants/p1.yaml") + "junk: [0";
  text.reserve(text.size() + 10'000'000);
  for (int i = 0; i < 5'000'000; ++i) text += ",0";  // 5 million values, 10 MB
  text += "]\n";
  std::string e;
  EXPECT_LT(cpuSecondsOf([&] { e = loadError([&] { parseParticipant(text, "participants/p1.yaml"); }); }),
            kQuickRefusal);
  EXPECT_THAT(e, StartsWith("participants/p1.yaml:"));
  EXPECT_THAT(e, HasSubstr("more than 100000 YAML values in one file"));
}

TEST(BadInputCatalogue, LongBlockListIsRefusedQuicklyWithItsLine) {
  std::string text = "kind: knee-axis-sweep\nname: bomb\njunk:\n";
  for (int i = 0; i < 2'000'000; ++i) text += "- 0\n";
  std::string e;
  EXPECT_LT(cpuSecondsOf([&] { e = loadError([&] { parseSweepStudy(text, "bomb.yaml"); }); }), kQuickRefusal);
  // Keys count as values: the top map, three keys, two values and the list are 7, so the
  // 100001st value is list item 99994, on line 3 + 99994.
  EXPECT_THAT(e, StartsWith("bomb.yaml:99997: more than 100000 YAML values"));
}

TEST(BadInputCatalogue, ListUnderTheValueLimitReachesTheUnknownKeyCheck) {
  std::string text = readFile("participants/p1.yaml") + "junk: [0";
  for (int i = 0; i < 50'000; ++i) text += ",0";
  text += "]\n";
  EXPECT_THAT(loadError([&] { parseParticipant(text, "participants/p1.yaml"); }), HasSubstr("junk: unknown key"));
}

TEST(BadInputCatalogue, DirectoryGivenForAYamlFileIsNamedAsADirectory) {
  EXPECT_EQ(loadError([] { loadParticipant("participants"); }), "participants: is a directory (expected a file)");
  EXPECT_EQ(loadError([] { loadSweepStudy("studies"); }), "studies: is a directory (expected a file)");
  EXPECT_EQ(loadError([] { readFile("models"); }), "models: is a directory (expected a file)");
}

// ---------------------------------------------------------------------------------------
// Unit mistakes: values that only make sense in another unit are named so.
// ---------------------------------------------------------------------------------------

std::string participantWith(const std::string& from, const std::string& to) {
  std::string text = readFile("participants/p1.yaml");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return loadError([&] { parseParticipant(text.replace(at, from.size(), to), "participants/p1.yaml"); });
}

TEST(BadInputCatalogue, SegmentMassOf1e300IsRefusedAsHeavierThanABody) {
  EXPECT_THAT(participantWith("mass_kg: 3.350", "mass_kg: 1e300"),
              HasSubstr("participants/p1.yaml:10: segments.thigh.mass_kg: expected a segment mass of at most 150 kg "
                        "(heavier than a whole body: is it in grams? the key is in kg) (got 1e+300)"));
}

TEST(BadInputCatalogue, SegmentMassInGramsIsNamed) {
  EXPECT_THAT(participantWith("mass_kg: 0.785", "mass_kg: 785"),
              HasSubstr("participants/p1.yaml:11: segments.shank.mass_kg: expected a segment mass of at most 150 kg "
                        "(heavier than a whole body: is it in grams?"));
}

TEST(BadInputCatalogue, SegmentLengthInMillimetresIsNamed) {
  EXPECT_THAT(participantWith("length_m: 0.515", "length_m: 515"),
              HasSubstr("participants/p1.yaml:11: segments.shank.length_m: expected a segment length of at most 1.5 m "
                        "(is it in millimetres? the key is in metres) (got 515)"));
}

TEST(BadInputCatalogue, BodyMassInGramsIsNamed) {
  EXPECT_THAT(participantWith("body_mass_kg: 70", "body_mass_kg: 70000"),
              HasSubstr("participants/p1.yaml:8: body_mass_kg: expected a body mass of at most 500 kg (is it in "
                        "grams?) (got 70000)"));
}

TEST(BadInputCatalogue, PlausibleMassesAndLengthsAtTheBoundsStillLoad) {
  EXPECT_EQ(participantWith("mass_kg: 3.350", "mass_kg: 150"), "");
  EXPECT_EQ(participantWith("length_m: 0.240", "length_m: 0.3"), "");
}

TEST(BadInputCatalogue, KneeLinkLengthInMillimetresIsNamed) {
  std::string text = readFile("models/mauch-4phase.yaml");
  text.replace(text.find("ab_m: 0.1603"), 12, "ab_m: 160.3");
  EXPECT_THAT(loadError([&] { parseKneeModel(text, "models/mauch-4phase.yaml"); }),
              HasSubstr("models/mauch-4phase.yaml:11: geometry.ab_m: expected a link length of at most 0.5 m (is it in "
                        "millimetres?"));
}

std::string swingRecordText(double kneeScale) {
  std::string text = "time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm\n";
  for (int i = 0; i < 20; ++i) {
    const double knee = 60 * std::sin(kPi * i / 19);  // deg
    text +=
        std::to_string(0.02 * i) + "," + std::to_string(-15 + 2 * i) + "," + std::to_string(knee * kneeScale) + ",1\n";
  }
  return text;
}

// The swing record of swingRecordText(1) with `column` on its second data row set to `value`.
std::string readSwingRecordError(const std::string& text, const std::string& column, const std::string& value) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const std::vector<std::string> names = {"time_s", "hip_flexion_deg", "knee_flexion_deg", "hip_moment_Nm"};
  const auto at = static_cast<std::size_t>(std::find(names.begin(), names.end(), column) - names.begin());
  std::vector<std::string> cells;
  std::istringstream row(lines[2]);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  cells[at] = value;
  lines[2] = cells[0] + "," + cells[1] + "," + cells[2] + "," + cells[3];
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return loadError([&] { readSwingRecord(writeTemp("bigknee.csv", out)); });
}

TEST(BadInputCatalogue, SwingRecordAnglesInRadiansAreNamed) {
  const std::string path = writeTemp("radians.csv", swingRecordText(kDegToRad));
  EXPECT_THAT(loadError([&] { readSwingRecord(path); }),
              HasSubstr("radians.csv: knee_flexion_deg: the knee moves through only 1.04"));
  EXPECT_THAT(loadError([&] { readSwingRecord(path); }), HasSubstr("the column looks like radians, expected degrees"));
}

TEST(BadInputCatalogue, SwingRecordInDegreesReads) {
  const SwingRecord r = readSwingRecord(writeTemp("degrees.csv", swingRecordText(1)));
  ASSERT_EQ(r.kneeFlexion.size(), 20u);
  constexpr double kRoundTrip = 1e-5;  // rad: six decimals written by std::to_string
  EXPECT_NEAR(*std::max_element(r.kneeFlexion.begin(), r.kneeFlexion.end()), 60 * std::sin(kPi * 9 / 19) * kDegToRad,
              kRoundTrip);
}

TEST(BadInputCatalogue, BenchPositionsInMillimetresAreNamed) {
  EXPECT_THAT(
      benchError("mm.csv", "time_s,position_m,force_N\n0,1,10\n0.01,2,12\n0.02,4,15\n0.03,3,11\n"),
      HasSubstr("mm.csv: position_m: the piston reaches 4 m (a knee cylinder's stroke is a few centimetres; more "
                "than 1 m): the column looks like millimetres, expected metres"));
  EXPECT_THAT(benchError("negmm.csv", "time_s,position_m,force_N\n0,-12,10\n0.01,2,12\n0.02,4,15\n"),
              HasSubstr("the piston reaches -12 m"));
}

TEST(BadInputCatalogue, SweepStudyAccuracyBelowRoundOffIsRefused) {
  const YamlLoader sweep = yamlLoaders()[3];
  EXPECT_THAT(errorOf(sweep, withValue(sweep, "1e-300")),
              HasSubstr("accuracy: expected a relative accuracy in [1e-14, 0.01] (got 1e-300)"));
  EXPECT_EQ(errorOf(sweep, withValue(sweep, "1e-14")), "");
}

// ---------------------------------------------------------------------------------------
// Plausibility ranges (core/plausible_ranges.h): finite but absurd numbers are refused at
// load with the file, line, key, the range and its reason, before a fit or a swing runs.
// ---------------------------------------------------------------------------------------

TEST(BadInputCatalogue, BenchForcesOutsideThePlausibleRangeAreRefusedWithTheirLine) {
  EXPECT_THAT(
      benchError("force.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,1e300\n0.02,0.004,15\n"),
      HasSubstr("force.csv:3: force_N: expected a force in [-100000, 100000] N (a knee cylinder carries at most a "
                "few kN (150 N m on a 2 cm lever is 7.5 kN))"));
  EXPECT_THAT(
      benchError("force.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,2e5\n0.02,0.004,15\n"),
      HasSubstr("force.csv:3: force_N: expected a force in [-100000, 100000] N (a knee cylinder carries at most a "
                "few kN (150 N m on a 2 cm lever is 7.5 kN)) (got 2e5)"));
  // The missing-data marker of lab exports is named as such.
  EXPECT_THAT(benchError("marker.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,9.9e37\n0.02,0.004,15\n"),
              HasSubstr("marker.csv:3: force_N: expected a force in [-100000, 100000] N"));
  EXPECT_THAT(benchError("marker.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,9.9e37\n0.02,0.004,15\n"),
              HasSubstr("usually a missing-data marker"));
  // At the bound it still reads.
  EXPECT_EQ(benchError("bound.csv", "time_s,position_m,force_N\n0,0.001,1e5\n0.01,0.002,-1e5\n0.02,0.004,15\n"), "");
}

TEST(BadInputCatalogue, BenchTimeStepsAndTimesOutsideTheirRangeAreRefused) {
  EXPECT_THAT(benchError("step.csv", "time_s,position_m,force_N\n0,0.001,10\n1e-200,0.002,12\n0.02,0.004,15\n"),
              HasSubstr("step.csv:3: time_s: expected steps of at least 1e-06 (got 1e-200 after 0, a step of 1e-200)"));
  EXPECT_THAT(benchError("time.csv", "time_s,position_m,force_N\n0,0.001,10\n0.01,0.002,12\n1e300,0.004,15\n"),
              HasSubstr("time.csv:4: time_s: expected a sample time in [-1e+07, 1e+07] s"));
}

TEST(BadInputCatalogue, SwingRecordAnglesAndMomentsOutsideTheirRangeAreRefused) {
  std::string text = swingRecordText(1);
  const std::string knee = readSwingRecordError(text, "knee_flexion_deg", "1e6");
  EXPECT_THAT(knee, HasSubstr("bigknee.csv:3: knee_flexion_deg: expected a knee angle in [-360, 360] deg"));
  EXPECT_THAT(readSwingRecordError(text, "hip_moment_Nm", "1e300"),
              HasSubstr("bigknee.csv:3: hip_moment_Nm: expected a hip moment in [-2000, 2000] N m"));
}

TEST(BadInputCatalogue, ParticipantInitialStateAndTimeScaleOutsideTheirRangeAreRefused) {
  EXPECT_THAT(
      participantWith("knee_flexion_deg: 10", "knee_flexion_deg: 1e6"),
      HasSubstr("participants/p1.yaml:19: initial.knee_flexion_deg: expected an initial knee angle in [-30, 180] deg"));
  EXPECT_THAT(participantWith("time_scale: 1.088747", "time_scale: 1e-300"),
              HasSubstr("participants/p1.yaml:38: hip_moment.time_scale: expected a time scale in [0.2, 5] (calibrated "
                        "scales lie in 0.85-1.8"));
  EXPECT_EQ(participantWith("knee_flexion_deg: 10", "knee_flexion_deg: 180"), "");
}

TEST(BadInputCatalogue, NegativeMauchDampingIsRefusedAtLoadNotBlamedOnTheHipLater) {
  std::string text = readFile("models/mauch-4phase.yaml");
  text.replace(text.find("c_Ns_per_m: 17087.9"), 19, "c_Ns_per_m: -500");
  EXPECT_THAT(
      loadError([&] { parseKneeModel(text, "models/mauch-4phase.yaml"); }),
      HasSubstr(
          "models/mauch-4phase.yaml:42: settings[0].coefficients[0].c_Ns_per_m: expected a damping in "
          "[0, 1e+06] N s/m (a hydraulic cylinder dissipates, and fitted phases have 500-17,700 N s/m) (got -500)"));
}

TEST(BadInputCatalogue, GeneratorNoiseOutsideItsRangeIsRefused) {
  const YamlLoader bench = yamlLoaders()[5];
  EXPECT_THAT(
      errorOf(bench, withValue(bench, "1e300")),
      HasSubstr("studies/mauch2014-bench.yaml:21: noise_N: expected a force noise in [0, 1000] N (a bench load cell "
                "is good to a few N)"));
  EXPECT_EQ(errorOf(bench, withValue(bench, "1000")), "");
}

// ---------------------------------------------------------------------------------------
// Messages that point at the right thing
// ---------------------------------------------------------------------------------------

TEST(BadInputCatalogue, CrOnlyLineEndsAreNamedNotADuplicatedColumn) {
  EXPECT_THAT(benchError("mac.csv", "time_s,position_m,force_N\r0,0.001,10\r0.01,0.002,12\r0.02,0.004,15\r"),
              HasSubstr("mac.csv:1: CR-only line ends"));
  // CRLF still reads.
  EXPECT_EQ(benchError("crlf.csv", "time_s,position_m,force_N\r\n0,0.001,10\r\n0.01,0.002,12\r\n0.02,0.004,15\r\n"),
            "");
}

TEST(BadInputCatalogue, YamlSecondDocumentIsRefusedWithItsLine) {
  for (const auto& l : yamlLoaders()) {
    const std::string text = readFile(l.file);
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    EXPECT_THAT(errorOf(l, text + "---\nname: second\n"),
                HasSubstr(l.file + ":" + std::to_string(lines + 1) + ": a second YAML document starts here"))
        << l.name;
    // The line of the '---'. A document-start line at the top is one document.
    EXPECT_EQ(errorOf(l, "---\n" + text), "") << l.name;
  }
}

TEST(BadInputCatalogue, AByteOrderMarkKeepsTheCommentBlockOnRewrite) {
  const std::string original = readFile("participants/p1.yaml");
  const std::string path = writeTemp("bom-participant.yaml", "\xEF\xBB\xBF" + original);
  Participant p = loadParticipant(path);
  p.hipMoment.timeScale = 1.2;
  storeParticipants({{path, p}});
  const std::string rewritten = readFile(path);
  EXPECT_THAT(rewritten, HasSubstr("# Participant P1: Burkett, Smeathers & Barker (2004)"));
  EXPECT_EQ(loadParticipant(path).hipMoment.timeScale, 1.2);
}

// A knee model given in place of the participant's (simulate --knee, a study's knee_model)
// is the one a late failure names.
TEST(BadInputCatalogue, ASwingSetupNamesTheKneeFileActuallyUsed) {
  const Participant p = loadParticipant("participants/p1.yaml");
  const KneeModel other = loadKneeModel("models/mauch-4phase.yaml");
  ASSERT_NE(p.kneeModelPath, other.path);
  EXPECT_EQ(makeSwingSetup(p, other).participant.kneeModelPath, other.path);
}

}  // namespace
}  // namespace swingsim
