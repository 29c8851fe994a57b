#include "study/cohort_results_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/json_file.h"
#include "study/results_file_fields.h"
#include "study/shard_file_header.h"
#include "study/uncertainty_swings_file.h"

namespace swingsim {

namespace {

constexpr const char* kFormat = "swingsim cohort results";
constexpr int kFormatVersion = 1;
// The largest cohort (100,000 participants of a few dozen swing times each, about 30 bytes a
// number as JSON) is far above the 16 MiB of an input file.
constexpr std::size_t kMaxResultsFileBytes = std::size_t{512} << 20;

const std::string kNotComplete = "this is not a complete cohort results file";

/// Reads keys of one JSON object of a results file, failing with file: key: expected, found.
class Fields : public ResultsFileFields {
 public:
  Fields(const std::string& path, const Json& object, std::string prefix = "")
      : ResultsFileFields(path, object, kNotComplete, std::move(prefix)) {}
};

Json formatNumberOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json formatResult(const std::string& name, const CohortParticipantResult& r) {
  Json j;
  j["participant"] = name;
  j["ran"] = r.ran;
  if (!r.ran) return j;
  j["calibrated"] = r.calibrated;
  j["failure"] = r.failure;
  j["time_scale"] = formatNumberOrNull(r.timeScale);
  j["calibration_swings"] = r.calibrationSwings;
  Json lowerings = Json::array(), times = Json::array();
  for (double d : r.sweep.lowerings) lowerings.push_back(d);
  for (double t : r.sweep.swingTimes) times.push_back(formatNumberOrNull(t));
  j["lowerings_m"] = lowerings;
  j["swing_times_s"] = times;
  return j;
}

ShardSlice describeSlice(const CohortResultsFile& s) {
  return describeShardSlice(s, static_cast<std::size_t>(s.run.participants));
}

CohortParticipantResult readResult(const std::string& path, const Json& j, const std::string& prefix) {
  const Fields f(path, j, prefix);
  CohortParticipantResult r;
  r.ran = f.flag("ran");
  if (!r.ran) return r;
  r.calibrated = f.flag("calibrated");
  r.failure = f.text("failure");
  r.timeScale = f.number("time_scale");
  r.calibrationSwings = static_cast<int>(f.whole("calibration_swings", 1000000));
  r.sweep.lowerings = f.numbers("lowerings_m");
  r.sweep.swingTimes = f.numbers("swing_times_s");
  if (r.sweep.lowerings.size() != r.sweep.swingTimes.size())
    f.fail("swing_times_s", "one swing time per lowering (" + std::to_string(r.sweep.lowerings.size()) + ")",
           std::to_string(r.sweep.swingTimes.size()));
  pickBest(r.sweep);
  return r;
}

}  // namespace

std::size_t CohortResultsFile::countFinished() const {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(), [](const CohortParticipantResult& r) { return r.ran; }));
}

CohortRunIdentity makeCohortRunIdentity(const Cohort& cohort, const std::string& version) {
  CohortRunIdentity id;
  static_cast<ShardFileRun&>(id) = makeShardFileRun(cohort.study, version);
  id.participants = cohort.count;
  id.seed = cohort.seed;
  return id;
}

std::string formatCohortResultsJson(const CohortResultsFile& file) {
  Json j;
  formatShardFileHead(j, kFormat, kFormatVersion, file.isPartial(), file.run);
  j["participants"] = file.run.participants;
  j["seed"] = file.run.seed;
  j["shard"] = formatShardKey(file.sharded, file.shardIndex, file.shardCount);
  j["first_participant"] = file.first;
  j["last_participant"] = file.last;
  j["participants_finished"] = file.countFinished();
  Json results = Json::array();
  for (std::size_t k = 0; k < file.results.size(); ++k)
    results.push_back(formatResult(cohortParticipantName(file.first + k, static_cast<std::size_t>(file.run.participants)),
                                   file.results[k]));
  j["results"] = results;
  return formatJson(j);
}

bool isCohortResultsFile(const std::string& path) {
  // The format key comes first in every file this writes: its head decides, without reading
  // (or parsing) a large uncertainty shard twice.
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find(std::string("\"format\": \"") + kFormat + "\"") != std::string::npos;
}

CohortResultsFile readCohortResultsFile(const std::string& path) {
  Json doc;
  try {
    doc = Json::parse(readFile(path, kMaxResultsFileBytes));
  } catch (const Json::parse_error& e) {
    throw InputError(path + ": expected the JSON of a cohort results file (sweep COHORT.yaml --shard K/N), found text "
                     "that is not JSON (" + e.what() + ")");
  }
  const Fields f(path, doc);
  CohortResultsFile file;
  file.path = path;
  static_cast<ShardFileRun&>(file.run) = readShardFileHead(f, doc, kFormat, kFormatVersion);
  file.run.participants = static_cast<int>(f.whole("participants", static_cast<std::uint64_t>(kMaxCohortParticipants)));
  file.run.seed = f.whole("seed", std::numeric_limits<std::uint64_t>::max());
  const Json& shard = f.at("shard");
  if (!shard.is_null()) {
    file.sharded = true;
    readShardKey(Fields(path, shard, "shard."), file.shardIndex, file.shardCount);
  }
  const auto total = static_cast<std::uint64_t>(file.run.participants);
  file.first = f.whole("first_participant", total);
  file.last = f.whole("last_participant", total);
  if (file.last < file.first)
    f.fail("last_participant", "at least first_participant (" + std::to_string(file.first) + ")",
           std::to_string(file.last));
  const Json& results = f.at("results");
  if (!results.is_array() || results.size() != file.last - file.first)
    f.fail("results", "a list of " + std::to_string(file.last - file.first) + " participants",
           results.is_array() ? "a list of " + std::to_string(results.size()) : describeJsonValue(results));
  for (std::size_t k = 0; k < results.size(); ++k)
    file.results.push_back(readResult(path, results[k], "results[" + std::to_string(k) + "]."));
  if (f.whole("participants_finished", total) != file.countFinished())
    f.fail("participants_finished", std::to_string(file.countFinished()) + " (the results with \"ran\": true)",
           describeJsonValue(doc.at("participants_finished")));
  if (f.flag("partial") != file.isPartial())
    f.fail("partial", file.isPartial() ? "true (some results have not run)" : "false (every result ran)",
           file.isPartial() ? "false" : "true");
  return file;
}

void checkSameCohortRun(const CohortRunIdentity& expected, const CohortResultsFile& found, const std::string& what) {
  const SameRunCheck check(found.path, what, "these results belong to another cohort run");
  const CohortRunIdentity& got = found.run;
  check.study(expected, got);
  check.count("participants", expected.participants, got.participants);
  check.count("seed", expected.seed, got.seed);
  check.inputs(expected, got, ": the study, its template or a knee model differs");
  check.version(expected, got);
}

std::vector<CohortParticipantResult> mergeCohortShards(const std::vector<CohortResultsFile>& shards) {
  if (shards.empty()) throw InputError("merge: expected at least one shard file, found none");
  const CohortResultsFile& head = shards.front();
  ShardIndexSet byIndex;
  for (const auto& s : shards) {
    requireShardFile(describeSlice(s));
    if (s.isPartial())
      throw InputError(s.path + ": partial: expected false (a finished shard), found true (" +
                       std::to_string(s.countFinished()) + " of " + std::to_string(s.last - s.first) +
                       " participants ran): rerun that shard's sweep --shard command to finish it");
    if (&s != &head) checkSameCohortRun(head.run, s, "the first shard, " + head.path);
    checkShardSlice(describeSlice(s), describeSlice(head), "first_participant, last_participant");
    if (const std::string* also = byIndex.add(s.shardIndex, s.path))
      failResultsFileKey(s.path, "shard.index", "each shard once",
                         "shard " + std::to_string(s.shardIndex) + " again (also in " + *also + ")");
  }
  int missingCount = 0;
  const std::string missing = byIndex.listMissing(head.shardCount, head.shardCount, missingCount);
  if (missingCount > 0)
    throw InputError("merge: expected all " + std::to_string(head.shardCount) + " shards of " + head.run.study +
                     ", found " + std::to_string(byIndex.size()) + "; missing K = " + missing + " (files " +
                     cohortShardFileName(0, head.shardCount) + " and the like)");
  std::vector<CohortParticipantResult> all(static_cast<std::size_t>(head.run.participants));
  for (const auto& s : shards)
    for (std::size_t k = 0; k < s.results.size(); ++k) all[s.first + k] = s.results[k];
  return all;
}

std::string cohortPartialFileName() { return "cohort.partial.json"; }

std::string cohortShardFileName(int index, int shards) { return formatShardFileName("cohort", index, shards); }

}  // namespace swingsim
