// What both results files share: their head and "shard" key written in order and read back,
// a file of another format, a missing key or a shard key out of its check refused; a file of
// another run refused key by key; the checks merge makes of a shard set; the fingerprints.
#include "study/shard_file_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// A results file with nothing but the shared keys.
struct HeadOnly {
  ShardFileRun run;
  bool partial = false;
  bool sharded = false;
  int shardIndex = 0, shardCount = 1;
};

template <class A>
void serialize(A& a, HeadOnly& f) {
  serializeShardFileHead(a, "swingsim head only", 3, f.partial, f.run);
  serializeShardKey(a, f);
}

const JsonFileKind kKind{"a head-only file", "the test", "this is not a complete head-only file"};

HeadOnly makeShard(int k, int n) {
  HeadOnly f;
  f.run.study = "tiny";
  f.run.studyPath = "studies/tiny.yaml";
  f.run.inputsFingerprint = "0123456789abcdef";
  f.run.version = "0.test";
  f.partial = true;
  f.sharded = true;
  f.shardIndex = k;
  f.shardCount = n;
  return f;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim-shard-header-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

HeadOnly readText(const std::string& name, const std::string& text) {
  const std::string path = scratch(name);
  std::ofstream(path) << text;
  HeadOnly f;
  readJsonDocument(path, kMaxInputFileBytes, kKind, f);
  return f;
}

std::string refusal(const std::string& name, const std::string& text) {
  try {
    readText(name, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

std::string edit(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(ShardFileHeader, HeadAndShardKeyAreWrittenInOrderAndReadBack) {
  const HeadOnly f = makeShard(1, 2);
  EXPECT_EQ(formatJsonDocument(f), R"({
  "format": "swingsim head only",
  "format_version": 3,
  "partial": true,
  "study": "tiny",
  "study_path": "studies/tiny.yaml",
  "swingsim_version": "0.test",
  "inputs_fingerprint": "0123456789abcdef",
  "shard": {
    "index": 1,
    "count": 2
  }
}
)");
  const HeadOnly back = readText("shard.json", formatJsonDocument(f));
  EXPECT_EQ(back.run.study, "tiny");
  EXPECT_EQ(back.run.studyPath, "studies/tiny.yaml");
  EXPECT_EQ(back.run.inputsFingerprint, "0123456789abcdef");
  EXPECT_EQ(back.run.version, "0.test");
  EXPECT_TRUE(back.partial);
  EXPECT_TRUE(back.sharded);
  EXPECT_EQ(back.shardIndex, 1);
  EXPECT_EQ(back.shardCount, 2);

  HeadOnly whole = makeShard(0, 1);
  whole.sharded = false;
  EXPECT_THAT(formatJsonDocument(whole), HasSubstr("\"shard\": null\n"));
  EXPECT_FALSE(readText("whole.json", formatJsonDocument(whole)).sharded);
}

TEST(ShardFileHeader, AFileOfAnotherFormatOrAMissingKeyIsRefused) {
  const std::string text = formatJsonDocument(makeShard(0, 2));
  const std::string p = scratch("");
  EXPECT_EQ(refusal("a.json", edit(text, "\"swingsim head only\"", "\"swingsim cohort results\"")),
            p + "a.json: format: expected \"swingsim head only\", found \"swingsim cohort results\"");
  EXPECT_EQ(refusal("b.json", edit(text, "\"format_version\": 3", "\"format_version\": 2")),
            p + "b.json: format_version: expected 3 (this file was written by an older swingsim, before its payload "
                "was checksummed and range-checked: rerun the shard, or the sweep, that wrote it), found 2");
  EXPECT_EQ(refusal("c.json", edit(text, "\"format_version\": 3", "\"format_version\": 1001")),
            p + "c.json: format_version: expected a whole number from 0 to 1000, found 1001");
  EXPECT_EQ(refusal("d.json", edit(text, "  \"study_path\": \"studies/tiny.yaml\",\n", "")),
            p + "d.json: study_path: expected the key (this is not a complete head-only file), found it missing");
  EXPECT_EQ(refusal("e.json", edit(text, "\"partial\": true", "\"partial\": \"yes\"")),
            p + "e.json: partial: expected true or false, found \"yes\"");
  EXPECT_EQ(refusal("f.json", edit(text, "\"shard\": {", "\"shard\": [0, 2], \"x\": {")),
            p + "f.json: shard: expected null or {\"index\": K, \"count\": N}, found [0,2]");
}

// An edited shard key out of its check: K beyond N - 1, N of 0, N beyond the largest.
TEST(ShardFileHeader, AShardKeyOutOfItsCheckIsRefused) {
  const std::string text = formatJsonDocument(makeShard(1, 2));
  const std::string p = scratch("");
  EXPECT_EQ(refusal("g.json", edit(text, "\"index\": 1", "\"index\": 2")),
            p + "g.json: shard.index: expected a whole number from 0 to 1, found 2");
  EXPECT_EQ(refusal("h.json", edit(text, "\"index\": 1", "\"index\": -1")),
            p + "h.json: shard.index: expected a whole number from 0 to 999999, found -1");
  EXPECT_EQ(refusal("i.json", edit(text, "\"count\": 2", "\"count\": 0")),
            p + "i.json: shard.count: expected a shard count of at least 1, found 0");
  EXPECT_EQ(refusal("j.json", edit(text, "\"count\": 2", "\"count\": 1000001")),
            p + "j.json: shard.count: expected a whole number from 0 to 1000000, found 1000001");
  EXPECT_EQ(refusal("k.json", edit(text, "    \"index\": 1,\n", "")),
            p + "k.json: shard.index: expected the key (this is not a complete head-only file), found it missing");
}

TEST(ShardFileHeader, AFileOfAnotherRunIsRefusedKeyByKey) {
  const ShardFileRun expected = makeShard(0, 2).run;
  const SameRunCheck check("s1.json", "the first shard, s0.json", "these belong to another run");
  auto refusalOf = [&](const ShardFileRun& found) {
    try {
      check.study(expected, found);
      check.inputs(expected, found, ": the study differs");
      check.version(expected, found);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusalOf(expected), "accepted");
  ShardFileRun otherStudy = expected;
  otherStudy.study = "other";
  EXPECT_EQ(refusalOf(otherStudy),
            "s1.json: study: expected \"tiny\" (the first shard, s0.json), found \"other\": "
            "these belong to another run");
  ShardFileRun otherInputs = expected;
  otherInputs.inputsFingerprint = "fedcba9876543210";
  otherInputs.studyPath = "elsewhere/tiny.yaml";
  EXPECT_EQ(refusalOf(otherInputs),
            "s1.json: inputs_fingerprint: expected 0123456789abcdef (studies/tiny.yaml) (the first shard, s0.json), "
            "found fedcba9876543210 (elsewhere/tiny.yaml): the study differs: these belong to another run");
  ShardFileRun otherVersion = expected;
  otherVersion.version = "0.other";
  EXPECT_THAT(refusalOf(otherVersion), HasSubstr("s1.json: swingsim_version: expected 0.test (the first shard"));
  EXPECT_THROW(check.count("seed", 5, 6), InputError);
  EXPECT_NO_THROW(check.count("seed", 5, 5));
}

TEST(ShardFileHeader, MergeChecksEachShardAgainstTheFirst) {
  const std::string head = "s0.json", other = "s1.json";
  auto slice = [](const std::string& path, int k, int n, std::size_t total) {
    ShardSlice s;
    s.path = &path;
    s.sharded = true;
    s.index = k;
    s.count = n;
    std::tie(s.first, s.last) = calcShardSwings(total, k, n);
    s.total = total;
    return s;
  };
  auto refusalOf = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const ShardSlice first = slice(head, 0, 2, 10);
  EXPECT_EQ(refusalOf([&] { checkShardSlice(slice(other, 1, 2, 10), first, "first, last"); }), "accepted");
  EXPECT_EQ(refusalOf([&] { checkShardSlice(slice(other, 1, 3, 10), first, "first, last"); }),
            "s1.json: shard.count: expected 2 (the first shard, s0.json), found 3");
  ShardSlice moved = slice(other, 1, 2, 10);
  moved.first += 1;
  EXPECT_EQ(refusalOf([&] { checkShardSlice(moved, first, "first, last"); }),
            "s1.json: first, last: expected 5, 10 (shard 1/2), found 6, 10");
  ShardSlice whole = first;
  whole.sharded = false;
  EXPECT_THAT(refusalOf([&] { requireShardFile(whole); }),
              HasSubstr("s0.json: shard: expected {\"index\": K, \"count\": N} (a file written by sweep --shard K/N), "
                        "found null"));
  ShardIndexSet set;
  EXPECT_EQ(set.add(0, head), nullptr);
  EXPECT_EQ(set.add(3, other), nullptr);
  const std::string* also = set.add(0, other);
  ASSERT_NE(also, nullptr);
  EXPECT_EQ(*also, head);
  int missing = 0;
  EXPECT_EQ(set.listMissing(6, 2, missing), "1, 2, ...");
  EXPECT_EQ(missing, 4);  // 1, 2, 4, 5
  EXPECT_EQ(formatShardFileName("cohort", 3, 12), "cohort-shard-03-of-12.json");
  EXPECT_EQ(formatShardFileName("uncertainty", 0, 1), "uncertainty-shard-0-of-1.json");
}

TEST(ShardFileHeader, FingerprintSeparatesItsPiecesAndTakesExactNumbers) {
  auto hexOf = [](std::initializer_list<std::string> pieces) {
    Fingerprint f;
    for (const auto& piece : pieces) f.add(piece);
    return f.hex();
  };
  EXPECT_EQ(Fingerprint().hex(), "cbf29ce484222325");  // FNV-1a 64's offset basis: nothing added
  EXPECT_EQ(hexOf({"ab"}).size(), 16u);
  EXPECT_NE(hexOf({"ab", "c"}), hexOf({"a", "bc"}));
  Fingerprint third, nearThird;
  third.add(1.0 / 3.0);
  nearThird.add(std::nextafter(1.0 / 3.0, 1.0));  // one bit apart
  EXPECT_NE(third.hex(), nearThird.hex());
}

// The inputs fingerprint covers a measured thigh drive's samples, not only its file name:
// shards run against different contents of the same CSV must not merge. A hip-moment study
// keeps the fingerprint it had (no samples, nothing added).
TEST(ShardFileHeader, InputsFingerprintCoversTheThighDrivesSamples) {
  SweepStudy study = loadSweepStudy("studies/burkett2004.yaml");
  const std::string hipMoment = calcStudyInputsFingerprint(study);
  EXPECT_EQ(makeShardFileRun(study, "0.test").inputsFingerprint, hipMoment);
  study.participants[0].thighKinematics.path = "thigh.csv";
  study.participants[0].thighKinematics.time = {0.0, 0.1, 0.2};
  study.participants[0].thighKinematics.hipFlexion = {-0.2, 0.1, 0.3};
  const std::string measured = calcStudyInputsFingerprint(study);
  EXPECT_NE(measured, hipMoment);
  study.participants[0].thighKinematics.hipFlexion[1] = 0.1000001;  // one sample edited in place
  EXPECT_NE(calcStudyInputsFingerprint(study), measured);
  study.participants[0].thighKinematics.hipFlexion[1] = 0.1;
  EXPECT_EQ(calcStudyInputsFingerprint(study), measured);
  study.participants[0].thighKinematics = ThighKinematics{};
  EXPECT_EQ(calcStudyInputsFingerprint(study), hipMoment);
}

// The file an earlier interrupted run left must hold this run's slice: the same K/N, or both
// a whole run's ("null").
TEST(ShardFileHeader, AnEarlierFileOfAnotherSliceIsRefusedNamingBoth) {
  struct Slice {
    bool sharded;
    int shardIndex, shardCount;
  };
  const Slice shard0{true, 0, 2}, shard1{true, 1, 2}, whole{false, 0, 1};
  EXPECT_NO_THROW(checkSameShard(shard0, Slice{true, 0, 2}, "p.json"));
  EXPECT_NO_THROW(checkSameShard(whole, Slice{false, 0, 1}, "p.json"));
  auto refusal = [](const Slice& thisRun, const Slice& earlier) {
    try {
      checkSameShard(thisRun, earlier, "p.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(shard0, shard1), "p.json: shard: expected 0/2 (this run), found 1/2");
  EXPECT_EQ(refusal(shard0, whole), "p.json: shard: expected 0/2 (this run), found null");
  EXPECT_EQ(refusal(whole, shard1), "p.json: shard: expected null (this run), found 1/2");
}

}  // namespace
}  // namespace swingsim
