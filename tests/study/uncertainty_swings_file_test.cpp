// The uncertainty swings file (docs/uncertainty.md): written and read back bit for bit (swing times,
// no-swing-end nulls, swings not run), malformed files refused with file, key, expected and
// found, and shard sets combined only when they are every shard of one analysis.
#include "study/uncertainty_swings_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim-swings-file-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

UncertaintyRunIdentity identity() {
  UncertaintyRunIdentity id;
  id.study = "tiny";
  id.studyPath = "studies/tiny.yaml";
  id.inputsFingerprint = "0123456789abcdef";
  id.assumptionsFingerprint = "fedcba9876543210";
  id.samples = 2;
  id.seed = 5;
  id.swingCount = 10;
  id.version = "0.test";
  return id;
}

// Shard k of n of identity(), every swing finished with made-up times (1/3 + index / 7 s:
// numbers whose decimal form is not short, so a lossy writer would show).
UncertaintySwingsFile makeShard(int k, int n) {
  UncertaintySwingsFile f;
  f.run = identity();
  f.sharded = true;
  f.shardIndex = k;
  f.shardCount = n;
  std::tie(f.first, f.last) = calcShardSwings(f.run.swingCount, k, n);
  f.times = UncertaintySwingTimes::makeEmpty(f.last - f.first);
  for (std::size_t i = 0; i < f.last - f.first; ++i) {
    f.times.finished[i] = 1;
    f.times.swingTimes[i] = 1.0 / 3.0 + static_cast<double>(f.first + i) / 7.0;
  }
  return f;
}

UncertaintySwingsFile roundTrip(const UncertaintySwingsFile& f, const std::string& name) {
  const std::string path = scratch(name);
  writeFileAtomic(path, formatUncertaintySwingsJson(f));
  return readUncertaintySwingsFile(path);
}

TEST(UncertaintySwingsFile, ReadsBackBitForBit) {
  UncertaintySwingsFile f = makeShard(1, 3);
  f.times.swingTimes[1] = std::numeric_limits<double>::quiet_NaN();  // ran, no swing end
  f.times.finished[2] = 0;                                           // not run
  f.times.swingTimes[2] = std::numeric_limits<double>::quiet_NaN();
  const UncertaintySwingsFile back = roundTrip(f, "partial.json");
  EXPECT_TRUE(back.isPartial());
  EXPECT_TRUE(back.sharded);
  EXPECT_EQ(back.shardIndex, 1);
  EXPECT_EQ(back.shardCount, 3);
  EXPECT_EQ(back.first, f.first);
  EXPECT_EQ(back.last, f.last);
  EXPECT_EQ(back.run.inputsFingerprint, f.run.inputsFingerprint);
  EXPECT_EQ(back.run.seed, 5u);
  EXPECT_EQ(back.times.finished, f.times.finished);
  for (std::size_t i = 0; i < f.times.swingTimes.size(); ++i) {
    if (std::isnan(f.times.swingTimes[i]))
      EXPECT_TRUE(std::isnan(back.times.swingTimes[i])) << i;
    else
      EXPECT_EQ(back.times.swingTimes[i], f.times.swingTimes[i]) << i;  // exact, not near
  }
  EXPECT_THAT(formatUncertaintySwingsJson(f), HasSubstr("\"partial\": true"));
}

// The text is the one swingsim has always written (key order, indent, 17 significant digits,
// null for a swing without an end or not run), so files of earlier runs resume and merge.
TEST(UncertaintySwingsFile, WritesTheTextItAlwaysHas) {
  UncertaintySwingsFile f = makeShard(1, 3);
  f.times.swingTimes[1] = std::numeric_limits<double>::quiet_NaN();  // ran, no swing end
  f.times.finished[2] = 0;                                           // not run
  EXPECT_EQ(formatUncertaintySwingsJson(f), R"({
  "format": "swingsim uncertainty swings",
  "format_version": 2,
  "partial": true,
  "study": "tiny",
  "study_path": "studies/tiny.yaml",
  "swingsim_version": "0.test",
  "inputs_fingerprint": "0123456789abcdef",
  "assumptions_fingerprint": "fedcba9876543210",
  "samples": 2,
  "seed": 5,
  "sensitivity": true,
  "shard": {
    "index": 1,
    "count": 3
  },
  "swings_total": 10,
  "first_swing": 3,
  "last_swing": 6,
  "swings_finished": 2,
  "samples_finished": 0,
  "swing_times_checksum": "09797eed484621f0",
  "swing_times_s": [
    0.76190476190476186,
    null,
    null
  ],
  "not_run": [
    5
  ]
}
)");
}

TEST(UncertaintySwingsFile, MalformedFilesNameFileKeyExpectedAndFound) {
  const UncertaintySwingsFile good = makeShard(0, 2);
  const std::string text = formatUncertaintySwingsJson(good);
  auto refuse = [](const std::string& name, const std::string& content) {
    const std::string path = scratch(name);
    std::ofstream(path) << content;
    try {
      readUncertaintySwingsFile(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  const std::string p = scratch("");
  EXPECT_THAT(refuse("a.json", "not json"), HasSubstr(p + "a.json: expected the JSON of an uncertainty swings file"));
  EXPECT_THAT(refuse("b.json", replace("\"seed\": 5", "\"seed\": -5")),
              HasSubstr(p + "b.json: seed: expected a whole number from 0 to"));
  EXPECT_THAT(refuse("c.json", replace("\"seed\": 5,", "")), HasSubstr(p + "c.json: seed: expected the key"));
  EXPECT_THAT(refuse("d.json", replace("\"partial\": false", "\"partial\": true")),
              HasSubstr(p + "d.json: partial: expected false (no swing is in not_run), found true"));
  EXPECT_THAT(refuse("e.json", replace("\"index\": 0", "\"index\": 2")),
              HasSubstr(p + "e.json: shard.index: expected a whole number from 0 to 1, found 2"));
  EXPECT_THAT(
      refuse("f.json", replace("\"last_swing\": 5", "\"last_swing\": 6")),
      HasSubstr(
          p + "f.json: swing_times_s: expected a list of 6 swing times (last_swing - first_swing), found a list of 5"));
  EXPECT_THAT(refuse("g.json", replace("\"format_version\": 2", "\"format_version\": 3")),
              HasSubstr(p + "g.json: format_version: expected 2 (this file was written by a newer swingsim: read it "
                            "with that version), found 3"));
  EXPECT_THAT(refuse("g2.json", replace("\"shard\": {", "\"shard\": 3, \"x\": {")),
              HasSubstr(p + "g2.json: shard: expected null or {\"index\": K, \"count\": N}, found 3"));
  UncertaintySwingsFile partial = makeShard(1, 3);
  partial.times.finished[2] = 0;
  std::string notRun = formatUncertaintySwingsJson(partial);
  notRun.replace(notRun.rfind("    5\n"), 6, "    9\n");
  EXPECT_THAT(
      refuse("g3.json", notRun),
      HasSubstr(p + "g3.json: not_run[0]: expected a swing index from first_swing to last_swing - 1 (3 to 6 - 1), "
                    "found 9"));
}

TEST(UncertaintySwingsFile, EditedSwingTimesAreRefusedByRangeAndChecksum) {
  const std::string text = formatUncertaintySwingsJson(makeShard(0, 2));
  char first[40];
  std::snprintf(first, sizeof first, "%.17g", 1.0 / 3.0);  // the shard's first swing time, as written
  auto refuse = [&](const std::string& name, const std::string& to) {
    std::string t = text;
    const auto at = t.find(first);
    EXPECT_NE(at, std::string::npos) << first;
    t.replace(at, std::string(first).size(), to);
    const std::string path = scratch(name);
    std::ofstream(path) << t;
    try {
      readUncertaintySwingsFile(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string p = scratch("");
  // A finite but absurd time: no swing outlasts the 10 s a participant's time_limit_s allows.
  EXPECT_THAT(refuse("h.json", "1e300"),
              HasSubstr(p + "h.json: swing_times_s[0]: expected a swing time above 0 and at most 10 s"));
  // A plausible time that is not the one computed: only the checksum tells.
  EXPECT_THAT(refuse("i.json", "0.5"), HasSubstr(p + "i.json: swing_times_checksum: expected "));
  EXPECT_THAT(refuse("i.json", "0.5"), HasSubstr("the swing times were changed after swingsim wrote them"));
  EXPECT_EQ(refuse("j.json", first), "accepted");
}

TEST(UncertaintySwingsFile, MergeNeedsEveryShardOfOneAnalysisOnce) {
  std::vector<UncertaintySwingsFile> set;
  for (int k = 0; k < 3; ++k) set.push_back(roundTrip(makeShard(k, 3), "s" + std::to_string(k) + ".json"));
  const UncertaintySwingTimes merged = mergeUncertaintyShards(set);
  EXPECT_EQ(merged.countFinished(), 10u);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(merged.swingTimes[i], 1.0 / 3.0 + static_cast<double>(i) / 7.0);

  auto refusal = [](const std::vector<UncertaintySwingsFile>& files) {
    try {
      mergeUncertaintyShards(files);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refusal({set[0], set[2]}), HasSubstr("missing K = 1"));
  EXPECT_THAT(refusal({set[0], set[1], set[1], set[2]}),
              HasSubstr(set[1].path + ": shard.index: expected each shard once"));
  UncertaintySwingsFile otherSeed = set[1];
  otherSeed.run.seed = 6;
  EXPECT_THAT(refusal({set[0], otherSeed, set[2]}),
              HasSubstr(": seed: expected 5 (the first shard, " + set[0].path + "), found 6"));
  UncertaintySwingsFile otherN = set[1];
  otherN.run.samples = 3;
  EXPECT_THAT(refusal({set[0], otherN, set[2]}),
              HasSubstr(": samples: expected 2 (the first shard, " + set[0].path + "), found 3"));
  UncertaintySwingsFile otherStudy = set[2];
  otherStudy.run.inputsFingerprint = "0000000000000000";
  EXPECT_THAT(refusal({set[0], set[1], otherStudy}), HasSubstr(": inputs_fingerprint: expected 0123456789abcdef"));
  UncertaintySwingsFile otherTable = set[2];
  otherTable.run.assumptionsFingerprint = "0000000000000000";
  EXPECT_THAT(refusal({set[0], set[1], otherTable}), HasSubstr(": assumptions_fingerprint: expected fedcba9876543210"));
  UncertaintySwingsFile unfinished = set[1];
  unfinished.times.finished[0] = 0;
  EXPECT_THAT(refusal({set[0], unfinished, set[2]}),
              HasSubstr(": partial: expected false (a finished shard), found true"));
  UncertaintySwingsFile whole = set[0];
  whole.sharded = false;
  EXPECT_THAT(refusal({whole, set[1], set[2]}), HasSubstr(": shard: expected {\"index\": K, \"count\": N}"));
  UncertaintySwingsFile moved = set[1];
  moved.first += 1;
  EXPECT_THAT(refusal({set[0], moved, set[2]}), HasSubstr(": first_swing, last_swing: expected "));
}

}  // namespace
}  // namespace swingsim
