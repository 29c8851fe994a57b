// A cohort results file is checked as an uncertainty swings file is: a number edited by
// hand, even to a plausible value, no longer matches the checksum written over the results;
// a value no swing computes (a negative swing time, a lowering off the shank, a time scale
// calibration never finds) is refused naming its key and range even when the checksum was
// recomputed to match; a file of the earlier format (no checksum) is refused with what to do.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "core/output_files.h"
#include "study/cohort_results_file.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("swingsim-cohort-checks-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// Shard 0 of 2 of a run of 4 participants, both of its participants calibrated and swept.
CohortResultsFile makeShard() {
  CohortResultsFile f;
  f.run.study = "tiny cohort";
  f.run.studyPath = "studies/tiny-cohort.yaml";
  f.run.inputsFingerprint = "0123456789abcdef";
  f.run.version = "0.test";
  f.run.participants = 4;
  f.run.seed = 5;
  f.sharded = true;
  f.shardIndex = 0;
  f.shardCount = 2;
  f.first = 0;
  f.last = 2;
  for (int i = 0; i < 2; ++i) {
    CohortParticipantResult r;
    r.ran = r.calibrated = true;
    r.timeScale = 1.25;
    r.calibrationSwings = 7;
    r.sweep.lowerings = {0.0, 0.05};
    r.sweep.swingTimes = {0.4375, 0.40625};
    f.results.push_back(r);
  }
  return f;
}

// What reading the file with `text` says ("accepted" if nothing).
std::string refusal(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  try {
    readCohortResultsFile(path);
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

TEST(CohortShardChecks, AWrittenFileReadsBack) {
  const std::string path = scratch("good.json");
  EXPECT_EQ(refusal(path, formatCohortResultsJson(makeShard())), "accepted");
}

TEST(CohortShardChecks, APlausibleEditIsRefusedByTheChecksumNamingTheFile) {
  // 0.40625 s x 0.8 = 0.325 s: a swing time like any other, only the checksum tells.
  const std::string path = scratch("plausible.json");
  const std::string text = edit(formatCohortResultsJson(makeShard()), "0.40625", "0.325");
  const std::string message = refusal(path, text);
  EXPECT_THAT(message, HasSubstr(path + ": results_checksum: expected "));
  EXPECT_THAT(message, HasSubstr("(computed from results), found \""));
  EXPECT_THAT(message, HasSubstr("the results were changed after swingsim wrote them; rerun the shard"));
  // Any other number of the payload too: a time scale, a lowering, a participant's flag.
  EXPECT_THAT(refusal(path, edit(formatCohortResultsJson(makeShard()), "1.25", "1.0")),
              HasSubstr(path + ": results_checksum: expected "));
  EXPECT_THAT(refusal(path, edit(formatCohortResultsJson(makeShard()), "0.05", "0.04")),
              HasSubstr(path + ": results_checksum: expected "));
}

TEST(CohortShardChecks, AnImplausibleValueWithAMatchingChecksumIsRefusedNamingKeyAndRange) {
  // Written by the writer, which checks nothing: the checksum matches the edited values.
  const std::string path = scratch("implausible.json");
  CohortResultsFile f = makeShard();
  f.results[1].sweep.swingTimes[0] = -0.4;
  EXPECT_EQ(refusal(path, formatCohortResultsJson(f)),
            path +
                ": results[1].swing_times_s[0]: expected a swing time above 0 and at most 10 s (the largest "
                "time_limit_s a participant takes), or null, found -0.4");
  f = makeShard();
  f.results[0].sweep.swingTimes[1] = 50;
  EXPECT_THAT(refusal(path, formatCohortResultsJson(f)),
              HasSubstr(path + ": results[0].swing_times_s[1]: expected a swing time above 0 and at most 10 s"));
  f = makeShard();
  f.results[0].sweep.lowerings[1] = 5;
  EXPECT_THAT(refusal(path, formatCohortResultsJson(f)),
              HasSubstr(path + ": results[0].lowerings_m[1]: expected a lowering in [0, 1.5] m (the knee axis is "
                               "lowered along a shank of at most 1.5 m), found 5"));
  f = makeShard();
  f.results[0].sweep.lowerings = {0.05, 0.0};
  EXPECT_THAT(refusal(path, formatCohortResultsJson(f)),
              HasSubstr(path + ": results[0].lowerings_m: expected lowerings rising from 0 (the study's grid), found "
                               "[0.05,0.0]"));
  f = makeShard();
  f.results[1].timeScale = 100;
  EXPECT_THAT(refusal(path, formatCohortResultsJson(f)),
              HasSubstr(path + ": results[1].time_scale: expected a hip time scale in [0.2, 5]"));
}

TEST(CohortShardChecks, AFileOfTheEarlierFormatIsRefusedWithWhatToDo) {
  const std::string path = scratch("older.json");
  const std::string text = edit(formatCohortResultsJson(makeShard()), "\"format_version\": 2", "\"format_version\": 1");
  EXPECT_THAT(refusal(path, text),
              HasSubstr(path + ": format_version: expected 2 (this file was written by an older swingsim, before its "
                               "payload was checksummed and range-checked: rerun the shard, or the sweep, that wrote "
                               "it), found 1"));
}

}  // namespace
}  // namespace swingsim
