#include "study/cohort_results_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/input_error.h"
#include "core/plausible_ranges.h"
#include "io/json_archive.h"
#include "study/shard_file_header.h"

namespace swingsim {

namespace {

constexpr const char* kFormat = "swingsim cohort results";
// 2: results_checksum added, every number range-checked.
constexpr int kFormatVersion = 2;
// The largest cohort (100,000 participants of a few dozen swing times each, about 30 bytes a
// number as JSON) is far above the 16 MiB of an input file.
constexpr std::size_t kMaxResultsFileBytes = std::size_t{512} << 20;
// Swings a calibration may report: far above what its scan and search take.
constexpr std::uint64_t kMaxCalibrationSwings = 1000000;

const JsonFileKind kKind{"a cohort results file", "sweep COHORT.yaml --shard K/N",
                         "this is not a complete cohort results file"};

// A number as the file holds it: exact, or null for any value that is not finite.
void addNumber(Fingerprint& f, double v) {
  if (std::isfinite(v))
    f.add(v);
  else
    f.add(std::string("null"));
}

// FNV-1a 64 over the slice's results, exact (%a): a shard edited by hand, or cut and
// spliced, no longer matches the checksum written with it.
std::string calcResultsChecksum(const CohortResultsFile& file) {
  Fingerprint f;
  f.add(std::to_string(file.first) + ".." + std::to_string(file.last));
  for (const auto& r : file.results) {
    f.add(std::string(r.ran ? "ran" : "not run"));
    if (!r.ran) continue;
    f.add(std::string(r.calibrated ? "calibrated" : "not calibrated"));
    f.add(r.failure);
    addNumber(f, r.timeScale);
    f.add(std::to_string(r.calibrationSwings));
    f.add(std::to_string(r.sweep.lowerings.size()));
    for (double d : r.sweep.lowerings) addNumber(f, d);
    for (double t : r.sweep.swingTimes) addNumber(f, t);
  }
  return f.hex();
}

// The lowerings of a sweep rise from 0 (the study's grid, sweepGridLowerings).
bool isLoweringGrid(const std::vector<double>& lowerings) {
  for (std::size_t k = 0; k < lowerings.size(); ++k)
    if (!(k == 0 ? lowerings[k] == 0 : lowerings[k] > lowerings[k - 1])) return false;
  return true;
}

ShardSlice describeSlice(const CohortResultsFile& s) {
  return describeShardSlice(s, static_cast<std::size_t>(s.run.participants));
}

}  // namespace

std::size_t CohortResultsFile::countFinished() const {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(), [](const CohortParticipantResult& r) { return r.ran; }));
}

// Result `k` of `file` (participant first + k); a result not yet run has only its name and
// "ran": false.
template <class Archive>
void serialize(Archive& a, CohortParticipantResult& r, std::size_t k, const CohortResultsFile& file) {
  std::string name = cohortParticipantName(file.first + k, static_cast<std::size_t>(file.run.participants));
  a.text("participant", name, mustBeText(name));
  a.flag("ran", r.ran);
  if (!r.ran) return;
  a.flag("calibrated", r.calibrated);
  a.text("failure", r.failure);
  a.number("time_scale", r.timeScale, mustBePlausibleNumber(kTimeScaleRange, "a hip time scale"));
  a.whole("calibration_swings", r.calibrationSwings, kMaxCalibrationSwings);
  a.numbers("lowerings_m", r.sweep.lowerings, mustBePlausibleNumber(kLoweringRange, "a lowering"));
  a.require(isLoweringGrid(r.sweep.lowerings), "lowerings_m", "lowerings rising from 0 (the study's grid)",
            [&] { return describeJsonValue(Json(r.sweep.lowerings)); });
  a.numbers("swing_times_s", r.sweep.swingTimes, mustBeSwingTime);
  a.require(r.sweep.lowerings.size() == r.sweep.swingTimes.size(), "swing_times_s",
            "one swing time per lowering (" + std::to_string(r.sweep.lowerings.size()) + ")",
            [&] { return std::to_string(r.sweep.swingTimes.size()); });
  if constexpr (Archive::kReading) pickBest(r.sweep);
}

// The one list of the file's keys (io/json_archive.h), in the order they are written.
template <class Archive>
void serialize(Archive& a, CohortResultsFile& f) {
  bool partial = f.isPartial();
  serializeShardFileHead(a, kFormat, kFormatVersion, partial, f.run);
  a.whole("participants", f.run.participants, static_cast<std::uint64_t>(kMaxCohortParticipants));
  a.whole("seed", f.run.seed, std::numeric_limits<std::uint64_t>::max());
  serializeShardKey(a, f);
  const auto total = static_cast<std::uint64_t>(f.run.participants);
  a.whole("first_participant", f.first, total);
  a.whole("last_participant", f.last, total);
  a.require(f.last >= f.first, "last_participant", "at least first_participant (" + std::to_string(f.first) + ")",
            [&] { return std::to_string(f.last); });
  std::size_t finished = f.countFinished();
  a.whole("participants_finished", finished, total);
  std::string checksum;
  const auto calcChecksum = [&f] { return calcResultsChecksum(f); };
  serializePayloadChecksum(a, "results_checksum", checksum, calcChecksum);
  a.objectList("results", f.results, f);
  a.require(f.results.size() == f.last - f.first, "results",
            "a list of " + std::to_string(f.last - f.first) + " participants",
            [&] { return "a list of " + std::to_string(f.results.size()); });
  a.require(finished == f.countFinished(), "participants_finished",
            std::to_string(f.countFinished()) + " (the results with \"ran\": true)",
            [&] { return std::to_string(finished); });
  a.require(partial == f.isPartial(), "partial",
            f.isPartial() ? "true (some results have not run)" : "false (every result ran)",
            [&] { return partial ? "true" : "false"; });
  requirePayloadChecksum(a, "results_checksum", checksum, calcChecksum, "results", "the results");
}

CohortRunIdentity makeCohortRunIdentity(const Cohort& cohort, const std::string& version) {
  CohortRunIdentity id;
  static_cast<ShardFileRun&>(id) = makeShardFileRun(cohort.study, version);
  id.participants = cohort.count;
  id.seed = cohort.seed;
  return id;
}

std::string formatCohortResultsJson(const CohortResultsFile& file) { return formatJsonDocument(file); }

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
  CohortResultsFile file;
  file.path = path;
  readJsonDocument(path, kMaxResultsFileBytes, kKind, file);
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
      failJsonFileKey(s.path, "shard.index", "each shard once",
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
