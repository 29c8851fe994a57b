// The cohort results file (docs/cohort.md): the exact text written, read back bit for bit,
// malformed or edited files refused with file, key, expected and found, and shard sets
// combined only when they are every shard of one run.
#include "study/cohort_results_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/output_files.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim-cohort-file-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

CohortRunIdentity identity() {
  CohortRunIdentity id;
  id.study = "tiny cohort";
  id.studyPath = "studies/tiny-cohort.yaml";
  id.inputsFingerprint = "0123456789abcdef";
  id.version = "0.test";
  id.participants = 4;
  id.seed = 5;
  return id;
}

// A result that ran: two lowerings, times whose decimal form is not short (a lossy writer
// would show), the second without a swing end.
CohortParticipantResult ranResult(std::size_t i) {
  CohortParticipantResult r;
  r.ran = true;
  r.calibrated = true;
  r.timeScale = 1.0 + static_cast<double>(i) / 3.0;
  r.calibrationSwings = 7;
  r.sweep.lowerings = {0.0, 0.01};
  r.sweep.swingTimes = {1.0 / 3.0 + static_cast<double>(i) / 7.0, std::numeric_limits<double>::quiet_NaN()};
  return r;
}

// Shard k of n of identity(), every participant ran.
CohortResultsFile makeShard(int k, int n) {
  CohortResultsFile f;
  f.run = identity();
  f.sharded = true;
  f.shardIndex = k;
  f.shardCount = n;
  std::tie(f.first, f.last) = calcShardSwings(static_cast<std::size_t>(f.run.participants), k, n);
  for (std::size_t i = f.first; i < f.last; ++i) f.results.push_back(ranResult(i));
  return f;
}

CohortResultsFile roundTrip(const CohortResultsFile& f, const std::string& name) {
  const std::string path = scratch(name);
  writeFileAtomic(path, formatCohortResultsJson(f));
  return readCohortResultsFile(path);
}

std::string refusal(const std::string& name, const std::string& content) {
  const std::string path = scratch(name);
  std::ofstream(path) << content;
  try {
    readCohortResultsFile(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// A whole run's partial result: one participant ran, one failed its calibration, two not run.
CohortResultsFile makePartial() {
  CohortResultsFile f;
  f.run = identity();
  f.first = 0;
  f.last = 4;
  f.results.resize(4);
  f.results[0] = ranResult(0);
  f.results[2].ran = true;
  f.results[2].failure = "no time scale reaches 0.5 s";
  f.results[2].timeScale = std::numeric_limits<double>::quiet_NaN();
  f.results[2].calibrationSwings = 12;
  return f;
}

// The text is the one swingsim writes (key order, indent, number forms); a file of format 1
// (no results_checksum) is refused with "rerun" (cohort_shard_checks_test.cpp).
TEST(CohortResultsFile, WritesTheTextItAlwaysHas) {
  EXPECT_EQ(formatCohortResultsJson(makePartial()), R"({
  "format": "swingsim cohort results",
  "format_version": 2,
  "partial": true,
  "study": "tiny cohort",
  "study_path": "studies/tiny-cohort.yaml",
  "swingsim_version": "0.test",
  "inputs_fingerprint": "0123456789abcdef",
  "participants": 4,
  "seed": 5,
  "shard": null,
  "first_participant": 0,
  "last_participant": 4,
  "participants_finished": 2,
  "results_checksum": "65246f268751abd8",
  "results": [
    {
      "participant": "C001",
      "ran": true,
      "calibrated": true,
      "failure": "",
      "time_scale": 1.0,
      "calibration_swings": 7,
      "lowerings_m": [
        0.0,
        0.01
      ],
      "swing_times_s": [
        0.3333333333333333,
        null
      ]
    },
    {
      "participant": "C002",
      "ran": false
    },
    {
      "participant": "C003",
      "ran": true,
      "calibrated": false,
      "failure": "no time scale reaches 0.5 s",
      "time_scale": null,
      "calibration_swings": 12,
      "lowerings_m": [],
      "swing_times_s": []
    },
    {
      "participant": "C004",
      "ran": false
    }
  ]
}
)");
  EXPECT_THAT(formatCohortResultsJson(makeShard(1, 2)), HasSubstr(R"(
  "shard": {
    "index": 1,
    "count": 2
  },
  "first_participant": 2,
  "last_participant": 4,
  "participants_finished": 2,)"));
}

TEST(CohortResultsFile, ReadsBackBitForBit) {
  const CohortResultsFile f = makePartial();
  const CohortResultsFile back = roundTrip(f, "partial.json");
  EXPECT_EQ(back.path, scratch("partial.json"));
  EXPECT_EQ(back.run.study, f.run.study);
  EXPECT_EQ(back.run.studyPath, f.run.studyPath);
  EXPECT_EQ(back.run.inputsFingerprint, f.run.inputsFingerprint);
  EXPECT_EQ(back.run.version, f.run.version);
  EXPECT_EQ(back.run.participants, 4);
  EXPECT_EQ(back.run.seed, 5u);
  EXPECT_FALSE(back.sharded);
  EXPECT_TRUE(back.isPartial());
  ASSERT_EQ(back.results.size(), 4u);
  EXPECT_EQ(back.countFinished(), 2u);
  const CohortParticipantResult& ran = back.results[0];
  EXPECT_TRUE(ran.calibrated);
  EXPECT_EQ(ran.timeScale, 1.0);
  EXPECT_EQ(ran.calibrationSwings, 7);
  EXPECT_EQ(ran.sweep.lowerings, f.results[0].sweep.lowerings);
  ASSERT_EQ(ran.sweep.swingTimes.size(), 2u);
  EXPECT_EQ(ran.sweep.swingTimes[0], 1.0 / 3.0);  // exact, not near
  EXPECT_TRUE(std::isnan(ran.sweep.swingTimes[1]));
  EXPECT_EQ(ran.sweep.best, 0);  // the fastest swing is picked again on reading
  EXPECT_FALSE(back.results[1].ran);
  EXPECT_TRUE(back.results[2].ran);
  EXPECT_FALSE(back.results[2].calibrated);
  EXPECT_EQ(back.results[2].failure, "no time scale reaches 0.5 s");
  EXPECT_TRUE(std::isnan(back.results[2].timeScale));
  EXPECT_EQ(back.results[2].calibrationSwings, 12);

  const CohortResultsFile shard = roundTrip(makeShard(1, 2), "shard.json");
  EXPECT_TRUE(shard.sharded);
  EXPECT_EQ(shard.shardIndex, 1);
  EXPECT_EQ(shard.shardCount, 2);
  EXPECT_EQ(shard.first, 2u);
  EXPECT_EQ(shard.last, 4u);
  EXPECT_FALSE(shard.isPartial());
  EXPECT_EQ(shard.results[1].timeScale, 2.0);
}

TEST(CohortResultsFile, IsRecognisedByItsHead) {
  const std::string cohort = scratch("head.json");
  writeFileAtomic(cohort, formatCohortResultsJson(makePartial()));
  EXPECT_TRUE(isCohortResultsFile(cohort));
  const std::string other = scratch("other.json");
  writeFileAtomic(other, R"({"format": "swingsim uncertainty swings"})");
  EXPECT_FALSE(isCohortResultsFile(other));
}

TEST(CohortResultsFile, MalformedFilesNameFileKeyExpectedAndFound) {
  const std::string text = formatCohortResultsJson(makePartial());
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace(at, from.size(), to);
  };
  const std::string p = scratch("");
  EXPECT_THAT(refusal("a.json", "{\"format\": "),
              HasSubstr(p + "a.json: expected the JSON of a cohort results file (sweep COHORT.yaml --shard K/N), "
                            "found text that is not JSON"));
  EXPECT_THAT(refusal("b.json", replace("\"seed\": 5,\n", "")),
              HasSubstr(p + "b.json: seed: expected the key (this is not a complete cohort results file), "
                            "found it missing"));
  EXPECT_THAT(refusal("c.json", replace("\"format\": \"swingsim cohort results\"", "\"format\": \"other\"")),
              HasSubstr(p + "c.json: format: expected \"swingsim cohort results\", found \"other\""));
  EXPECT_THAT(refusal("d.json", replace("\"format_version\": 2", "\"format_version\": 3")),
              HasSubstr(p + "d.json: format_version: expected 2 (this file was written by a newer swingsim: read it "
                            "with that version), found 3"));
  EXPECT_THAT(refusal("e.json", replace("\"seed\": 5", "\"seed\": \"5\"")),
              HasSubstr(p + "e.json: seed: expected a whole number from 0 to"));
  EXPECT_THAT(refusal("f.json", replace("\"last_participant\": 4", "\"last_participant\": 3")),
              HasSubstr(p + "f.json: results: expected a list of 3 participants, found a list of 4"));
  EXPECT_THAT(refusal("g.json", replace("\"calibration_swings\": 7", "\"calibration_swings\": -7")),
              HasSubstr(p + "g.json: results[0].calibration_swings: expected a whole number from 0 to 1000000, "
                            "found -7"));
  EXPECT_THAT(refusal("h.json", replace("\"ran\": true,\n      \"calibrated\": false", "\"calibrated\": false")),
              HasSubstr(p + "h.json: results[2].ran: expected the key"));
  EXPECT_THAT(refusal("i.json", replace("        0.01\n", "        0.01,\n        0.02\n")),
              HasSubstr(p + "i.json: results[0].swing_times_s: expected one swing time per lowering (3), found 2"));
  EXPECT_THAT(refusal("j.json", replace("\"failure\": \"\"", "\"failure\": false")),
              HasSubstr(p + "j.json: results[0].failure: expected a string, found false"));
  EXPECT_THAT(refusal("k.json", replace("\"time_scale\": 1.0", "\"time_scale\": \"1\"")),
              HasSubstr(p + "k.json: results[0].time_scale: expected a number or null, found \"1\""));
  EXPECT_EQ(refusal("l.json", text), "accepted");
}

// A value edited by hand that contradicts the rest of the file, or leaves its range.
TEST(CohortResultsFile, EditedValuesOutOfTheirCheckAreRefused) {
  const std::string text = formatCohortResultsJson(makePartial());
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace(at, from.size(), to);
  };
  const std::string p = scratch("");
  EXPECT_THAT(refusal("m.json", edit("\"participants_finished\": 2", "\"participants_finished\": 3")),
              HasSubstr(p + "m.json: participants_finished: expected 2 (the results with \"ran\": true), found 3"));
  EXPECT_THAT(refusal("n.json", edit("\"partial\": true", "\"partial\": false")),
              HasSubstr(p + "n.json: partial: expected true (some results have not run), found false"));
  EXPECT_THAT(refusal("o.json", edit("\"first_participant\": 0", "\"first_participant\": 5")),
              HasSubstr(p + "o.json: first_participant: expected a whole number from 0 to 4, found 5"));
  EXPECT_THAT(refusal("q.json", edit("\"participants\": 4", "\"participants\": 100001")),
              HasSubstr(p + "q.json: participants: expected a whole number from 0 to 100000, found 100001"));
  const std::string shard = formatCohortResultsJson(makeShard(1, 2));
  auto editShard = [&](const std::string& from, const std::string& to) {
    std::string t = shard;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? t : t.replace(at, from.size(), to);
  };
  EXPECT_THAT(refusal("r.json", editShard("\"index\": 1", "\"index\": 2")),
              HasSubstr(p + "r.json: shard.index: expected a whole number from 0 to 1, found 2"));
  EXPECT_THAT(refusal("s.json", editShard("\"count\": 2", "\"count\": 0")),
              HasSubstr(p + "s.json: shard.count: expected a shard count of at least 1, found 0"));
  EXPECT_THAT(refusal("t.json", editShard("\"index\": 1,\n", "")),
              HasSubstr(p + "t.json: shard.index: expected the key"));
}

TEST(CohortResultsFile, MergeNeedsEveryShardOfOneRunOnce) {
  std::vector<CohortResultsFile> set;
  for (int k = 0; k < 3; ++k) set.push_back(roundTrip(makeShard(k, 3), "s" + std::to_string(k) + ".json"));
  const std::vector<CohortParticipantResult> merged = mergeCohortShards(set);
  ASSERT_EQ(merged.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(merged[i].ran) << i;
    EXPECT_EQ(merged[i].sweep.swingTimes[0], 1.0 / 3.0 + static_cast<double>(i) / 7.0) << i;
  }
  auto refuse = [](const std::vector<CohortResultsFile>& files) {
    try {
      mergeCohortShards(files);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refuse({set[0], set[2]}), HasSubstr("missing K = 1"));
  EXPECT_THAT(refuse({set[0], set[1], set[1], set[2]}),
              HasSubstr(set[1].path + ": shard.index: expected each shard once"));
  CohortResultsFile otherSeed = set[1];
  otherSeed.run.seed = 6;
  EXPECT_THAT(refuse({set[0], otherSeed, set[2]}),
              HasSubstr(set[1].path + ": seed: expected 5 (the first shard, " + set[0].path +
                        "), found 6: "
                        "these results belong to another cohort run"));
  CohortResultsFile otherInputs = set[2];
  otherInputs.run.inputsFingerprint = "0000000000000000";
  EXPECT_THAT(refuse({set[0], set[1], otherInputs}), HasSubstr(": inputs_fingerprint: expected 0123456789abcdef"));
  CohortResultsFile unfinished = set[1];
  unfinished.results[0].ran = false;
  EXPECT_THAT(refuse({set[0], unfinished, set[2]}),
              HasSubstr(": partial: expected false (a finished shard), found true"));
  CohortResultsFile whole = set[0];
  whole.sharded = false;
  EXPECT_THAT(refuse({whole, set[1], set[2]}), HasSubstr(": shard: expected {\"index\": K, \"count\": N}"));
  CohortResultsFile moved = set[1];
  moved.first += 1;
  EXPECT_THAT(refuse({set[0], moved, set[2]}), HasSubstr(": first_participant, last_participant: expected "));
  EXPECT_THAT(refuse({}), HasSubstr("merge: expected at least one shard file, found none"));
}

}  // namespace
}  // namespace swingsim
