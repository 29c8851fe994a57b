#include "study/uncertainty_swings_file.h"

#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "io/json_archive.h"
#include "study/shard_file_header.h"

namespace swingsim {

namespace {

constexpr const char* kFormat = "swingsim uncertainty swings";
// 2: swing_times_checksum added.
constexpr int kFormatVersion = 2;
// A shard of the largest analysis (100,000 samples of a few participants) holds millions of
// swing times at about 20 bytes each: far above the 16 MiB of an input file.
constexpr std::size_t kMaxSwingsFileBytes = std::size_t{512} << 20;
// Swings of the largest analysis, far above what 100,000 samples make.
constexpr std::uint64_t kMaxSwings = std::uint64_t{1} << 40;

const JsonFileKind kKind{"an uncertainty swings file", "sweep --shard or an interrupted sweep --uncertainty",
                         "this file is not a complete uncertainty swings file"};

// FNV-1a 64 over the slice's swings, exact (%a): which ran and their times. A shard edited
// by hand, or cut and spliced, no longer matches the checksum written with it.
std::string calcSwingTimesChecksum(const UncertaintySwingsFile& file) {
  Fingerprint f;
  f.add(std::to_string(file.first) + ".." + std::to_string(file.last));
  for (std::size_t k = 0; k < file.times.swingTimes.size(); ++k) {
    const double t = file.times.swingTimes[k];
    if (!file.times.finished[k])
      f.add(std::string("not run"));
    else if (std::isfinite(t))
      f.add(t);
    else
      f.add(std::string("null"));
  }
  return f.hex();
}

std::string describeCount(std::size_t finished, std::size_t total) {
  return std::to_string(finished) + " of " + std::to_string(total) + " swings";
}

ShardSlice describeSlice(const UncertaintySwingsFile& s) { return describeShardSlice(s, s.run.swingCount); }

}  // namespace

// The swings: swing_times_s (null where a swing ran without an end, or did not run) and
// not_run (the indices of the swings that did not run).
template <class Archive>
void serializeSwings(Archive& a, UncertaintySwingsFile& f) {
  const std::size_t count = f.last - f.first;
  std::vector<double> times;
  std::vector<std::uint64_t> notRun;
  for (std::size_t k = 0; !Archive::kReading && k < count; ++k) {
    times.push_back(f.times.finished[k] ? f.times.swingTimes[k] : std::numeric_limits<double>::quiet_NaN());
    if (!f.times.finished[k]) notRun.push_back(f.first + k);
  }
  a.numberLines("swing_times_s", times, mustBeSwingTime);
  a.require(times.size() == count, "swing_times_s",
            "a list of " + std::to_string(count) + " swing times (last_swing - first_swing)",
            [&] { return "a list of " + std::to_string(times.size()); });
  a.wholeLines("not_run", notRun, [&f](const std::uint64_t& s) {
    return s >= f.first && s < f.last ? std::string()
                                      : "a swing index from first_swing to last_swing - 1 (" + std::to_string(f.first) +
                                            " to " + std::to_string(f.last) + " - 1)";
  });
  if constexpr (Archive::kReading) {
    f.times = UncertaintySwingTimes::makeEmpty(count);
    f.times.swingTimes = std::move(times);
    for (auto& finished : f.times.finished) finished = 1;
    for (std::uint64_t s : notRun) f.times.finished[s - f.first] = 0;
  }
}

// The one list of the file's keys (io/json_archive.h), in the order they are written.
template <class Archive>
void serialize(Archive& a, UncertaintySwingsFile& f) {
  bool partial = f.isPartial();
  serializeShardFileHead(a, kFormat, kFormatVersion, partial, f.run);
  a.text("assumptions_fingerprint", f.run.assumptionsFingerprint);
  a.whole("samples", f.run.samples, static_cast<std::uint64_t>(kMaxUncertaintySamples));
  a.whole("seed", f.run.seed, std::numeric_limits<std::uint64_t>::max());
  a.flag("sensitivity", f.run.sensitivity);
  serializeShardKey(a, f);
  a.whole("swings_total", f.run.swingCount, kMaxSwings);
  a.whole("first_swing", f.first, f.run.swingCount);
  a.whole("last_swing", f.last, f.run.swingCount);
  a.require(f.last >= f.first, "last_swing", "at least first_swing (" + std::to_string(f.first) + ")",
            [&] { return std::to_string(f.last); });
  std::size_t finished = f.times.countFinished();
  a.whole("swings_finished", finished, kMaxSwings);
  a.whole("samples_finished", f.samplesFinished, static_cast<std::uint64_t>(f.run.samples));
  std::string checksum;
  const auto calcChecksum = [&f] { return calcSwingTimesChecksum(f); };
  serializePayloadChecksum(a, "swing_times_checksum", checksum, calcChecksum);
  serializeSwings(a, f);
  a.require(finished == f.times.countFinished(), "swings_finished",
            std::to_string(f.times.countFinished()) + " (the swings not in not_run)",
            [&] { return std::to_string(finished); });
  a.require(partial == f.isPartial(), "partial",
            f.isPartial() ? "true (not_run lists swings)" : "false (no swing is in not_run)",
            [&] { return partial ? "true" : "false"; });
  requirePayloadChecksum(a, "swing_times_checksum", checksum, calcChecksum, "swing_times_s and not_run",
                         "the swing times");
}

std::string calcAssumptionsFingerprint(const UncertaintyPlan& plan) {
  Fingerprint f;
  for (const auto& a : sweepAssumptions()) {
    f.add(a.key);
    f.add(a.unit);
    f.add(std::string(a.discrete ? "discrete" : "continuous") + (a.logUniform ? " log" : ""));
    for (const auto& c : a.choices) f.add(c);
  }
  for (const auto& participant : plan.ranges)
    for (const auto& r : participant) {
      f.add(r.nominal);
      f.add(r.low);
      f.add(r.high);
      f.add(std::string(r.applicable ? "applicable" : "n/a"));
    }
  for (const auto& run : plan.runs) f.add(static_cast<double>(run.lowerings.size()));
  return f.hex();
}

UncertaintyRunIdentity makeUncertaintyRunIdentity(const SweepStudy& study, const UncertaintyPlan& plan,
                                                  const std::string& version) {
  UncertaintyRunIdentity id;
  static_cast<ShardFileRun&>(id) = makeShardFileRun(study, version);
  id.assumptionsFingerprint = calcAssumptionsFingerprint(plan);
  id.samples = plan.options.samples;
  id.seed = plan.options.seed;
  id.sensitivity = plan.options.sensitivity;
  id.swingCount = plan.swingCount;
  return id;
}

std::string formatUncertaintySwingsJson(const UncertaintySwingsFile& file) { return formatJsonDocument(file); }

UncertaintySwingsFile readUncertaintySwingsFile(const std::string& path) {
  UncertaintySwingsFile f;
  f.path = path;
  readJsonDocument(path, kMaxSwingsFileBytes, kKind, f);
  return f;
}

void checkSameUncertaintyRun(const UncertaintyRunIdentity& expected, const UncertaintySwingsFile& found,
                             const std::string& what) {
  const SameRunCheck check(found.path, what, "these swings belong to another analysis");
  const UncertaintyRunIdentity& got = found.run;
  check.study(expected, got);
  check.count("samples", expected.samples, got.samples);
  check.count("seed", expected.seed, got.seed);
  if (got.sensitivity != expected.sensitivity)
    check.differ("sensitivity", expected.sensitivity ? "true" : "false", got.sensitivity ? "true" : "false");
  check.inputs(expected, got, ": the study, a participant or a knee model differs (edited, or calibrated otherwise)");
  if (got.assumptionsFingerprint != expected.assumptionsFingerprint)
    check.differ(
        "assumptions_fingerprint", expected.assumptionsFingerprint,
        got.assumptionsFingerprint + ": the assumption table or its ranges differ (another swingsim version?)");
  check.count("swings_total", expected.swingCount, got.swingCount);
  check.version(expected, got);
}

void copyFinishedSwings(const UncertaintySwingsFile& file, UncertaintySwingTimes& times) {
  for (std::size_t k = 0; k < file.times.finished.size(); ++k) {
    if (!file.times.finished[k]) continue;
    times.swingTimes[file.first + k] = file.times.swingTimes[k];
    times.finished[file.first + k] = 1;
  }
}

UncertaintySwingTimes mergeUncertaintyShards(const std::vector<UncertaintySwingsFile>& shards) {
  if (shards.empty()) throw InputError("merge: expected at least one shard file, found none");
  const UncertaintySwingsFile& head = shards.front();
  ShardIndexSet byIndex;
  for (const auto& s : shards) {
    requireShardFile(describeSlice(s));
    if (s.isPartial())
      throw InputError(s.path + ": partial: expected false (a finished shard), found true (" +
                       describeCount(s.times.countFinished(), s.last - s.first) + " of shard " +
                       std::to_string(s.shardIndex) + "/" + std::to_string(s.shardCount) +
                       " ran): rerun that shard's sweep --shard command to finish it");
    if (&s != &head) checkSameUncertaintyRun(head.run, s, "the first shard, " + head.path);
    checkShardSlice(describeSlice(s), describeSlice(head), "first_swing, last_swing");
    if (const std::string* also = byIndex.add(s.shardIndex, s.path))
      throw InputError(s.path + ": shard.index: expected each shard once, found shard " + std::to_string(s.shardIndex) +
                       "/" + std::to_string(s.shardCount) + " again (also in " + *also + ")");
  }
  int missingCount = 0;
  const std::string missing = byIndex.listMissing(head.shardCount, 20, missingCount);
  if (missingCount > 0)
    throw InputError("merge: expected all " + std::to_string(head.shardCount) + " shards of " + head.run.study +
                     " (K = 0 to " + std::to_string(head.shardCount - 1) + "), found " +
                     std::to_string(byIndex.size()) + "; missing K = " + missing + " (files " +
                     uncertaintyShardFileName(0, head.shardCount) + " and the like)");
  UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(head.run.swingCount);
  for (const auto& s : shards) copyFinishedSwings(s, times);
  return times;
}

std::string uncertaintyPartialFileName() { return "uncertainty.partial.json"; }

std::string uncertaintyShardFileName(int index, int shards) {
  return formatShardFileName("uncertainty", index, shards);
}

}  // namespace swingsim
