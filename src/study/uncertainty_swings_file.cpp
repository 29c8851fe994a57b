#include "study/uncertainty_swings_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/json_file.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "study/results_file_fields.h"
#include "study/shard_file_header.h"
#include "study/sweep_study.h"

namespace swingsim {

namespace {

constexpr const char* kFormat = "swingsim uncertainty swings";
// 2: swing_times_checksum added.
constexpr int kFormatVersion = 2;
// s: no swing outlasts its participant's time_limit_s, which a participant file takes up to
// 10 s (participant_loader.cpp); a longer time in a file was not computed by a swing.
constexpr double kMaxSwingTime = 10;
// A shard of the largest analysis (100,000 samples of a few participants) holds millions of
// swing times at about 20 bytes each: far above the 16 MiB of an input file.
constexpr std::size_t kMaxSwingsFileBytes = std::size_t{512} << 20;

/// FNV-1a 64 over text fed piece by piece.
class Fingerprint {
 public:
  void add(const std::string& text) {
    for (unsigned char c : text) hash_ = (hash_ ^ c) * 0x100000001b3ULL;
    hash_ = (hash_ ^ 0xffU) * 0x100000001b3ULL;  // a separator, so "ab"+"c" != "a"+"bc"
  }
  void add(double value) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", value);  // exact
    add(std::string(buf));
  }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
    return buf;
  }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

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

std::string absolutePath(const std::string& path) {
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

// ---- Reading, with file: key: expected ..., found ... messages ----------------------------

const std::string kNotComplete = "this file is not a complete uncertainty swings file";

/// Reads keys of the file's JSON object (or of its "shard" object, with prefix "shard.").
class Reader : public ResultsFileFields {
 public:
  Reader(const std::string& path, const Json& doc, std::string prefix = "")
      : ResultsFileFields(path, doc, kNotComplete, std::move(prefix)) {}
};

std::string describeCount(std::size_t finished, std::size_t total) {
  return std::to_string(finished) + " of " + std::to_string(total) + " swings";
}

ShardSlice describeSlice(const UncertaintySwingsFile& s) { return describeShardSlice(s, s.run.swingCount); }

}  // namespace

std::string calcStudyInputsFingerprint(const SweepStudy& study) {
  const std::string folder = std::filesystem::path(absolutePath(study.path)).parent_path().string();
  Fingerprint f;
  f.add(formatSweepStudyYaml(study, folder));
  for (const Participant& p : study.participants) {
    f.add(formatParticipantYaml(p, folder));
    // A measured thigh drive's samples: the YAML names only their file (nothing is added
    // for a hip-moment drive, so such studies keep their fingerprints).
    for (double t : p.thighKinematics.time) f.add(t);
    for (double q : p.thighKinematics.hipFlexion) f.add(q);
  }
  for (const auto& [path, model] : study.kneeModels) {
    f.add(std::filesystem::path(path).filename().string());
    f.add(formatKneeModelYaml(model.spec));
  }
  return f.hex();
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

std::string formatUncertaintySwingsJson(const UncertaintySwingsFile& file) {
  Json j;
  formatShardFileHead(j, kFormat, kFormatVersion, file.isPartial(), file.run);
  j["assumptions_fingerprint"] = file.run.assumptionsFingerprint;
  j["samples"] = file.run.samples;
  j["seed"] = file.run.seed;
  j["sensitivity"] = file.run.sensitivity;
  j["shard"] = formatShardKey(file.sharded, file.shardIndex, file.shardCount);
  j["swings_total"] = file.run.swingCount;
  j["first_swing"] = file.first;
  j["last_swing"] = file.last;
  j["swings_finished"] = file.times.countFinished();
  j["samples_finished"] = file.samplesFinished;
  j["swing_times_checksum"] = calcSwingTimesChecksum(file);
  // The two lists are written as text into placeholders: as a Json tree they would take
  // about 100 bytes a swing (86,100 swings for --uncertainty 1000), as text about 25.
  // 17 significant digits read back to the same double.
  const std::string timesKey = "@swing_times_s@", notRunKey = "@not_run@";
  j["swing_times_s"] = timesKey;  // null: no swing end, or listed in not_run
  j["not_run"] = notRunKey;
  std::string times, notRun;
  times.reserve(28 * file.times.swingTimes.size() + 8);
  char buf[40];
  for (std::size_t k = 0; k < file.times.swingTimes.size(); ++k) {
    const double t = file.times.swingTimes[k];
    if (file.times.finished[k] && std::isfinite(t))
      std::snprintf(buf, sizeof buf, "%.17g", t);
    else
      std::snprintf(buf, sizeof buf, "null");
    times += (k == 0 ? "\n    " : ",\n    ");
    times += buf;
    if (!file.times.finished[k]) {
      std::snprintf(buf, sizeof buf, "%zu", file.first + k);
      notRun += (notRun.empty() ? "\n    " : ",\n    ");
      notRun += buf;
    }
  }
  std::string text = formatJson(j);
  const auto splice = [&text](const std::string& key, const std::string& items) {
    const std::string quoted = "\"" + key + "\"";
    text.replace(text.rfind(quoted), quoted.size(), items.empty() ? "[]" : "[" + items + "\n  ]");
  };
  splice(timesKey, times);
  splice(notRunKey, notRun);
  return text;
}

UncertaintySwingsFile readUncertaintySwingsFile(const std::string& path) {
  const std::string text = readFile(path, kMaxSwingsFileBytes);
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InputError(path + ": expected the JSON of an uncertainty swings file (sweep --shard or an interrupted "
                     "sweep --uncertainty), found text that is not JSON (" + e.what() + ")");
  }
  if (!doc.is_object())
    throw InputError(path + ": expected a JSON object (an uncertainty swings file), found " + describeJsonValue(doc));
  const Reader r(path, doc);
  UncertaintySwingsFile f;
  f.path = path;
  static_cast<ShardFileRun&>(f.run) = readShardFileHead(r, doc, kFormat, kFormatVersion);
  f.run.assumptionsFingerprint = r.text("assumptions_fingerprint");
  f.run.samples = static_cast<int>(r.whole("samples", static_cast<std::uint64_t>(kMaxUncertaintySamples)));
  f.run.seed = r.whole("seed", std::numeric_limits<std::uint64_t>::max());
  f.run.sensitivity = r.flag("sensitivity");
  const Json& shard = r.at("shard");
  if (!shard.is_null()) {
    if (!shard.is_object() || !shard.contains("index") || !shard.contains("count"))
      r.fail("shard", "null or {\"index\": K, \"count\": N}", describeJsonValue(shard));
    f.sharded = true;
    readShardKey(Reader(path, shard, "shard."), f.shardIndex, f.shardCount);
  }
  constexpr std::uint64_t kMaxSwings = std::uint64_t{1} << 40;
  f.run.swingCount = r.whole("swings_total", kMaxSwings);
  f.first = r.whole("first_swing", f.run.swingCount);
  f.last = r.whole("last_swing", f.run.swingCount);
  if (f.last < f.first)
    r.fail("last_swing", "at least first_swing (" + std::to_string(f.first) + ")", std::to_string(f.last));
  const Json& times = r.at("swing_times_s");
  if (!times.is_array() || times.size() != f.last - f.first)
    r.fail("swing_times_s", "a list of " + std::to_string(f.last - f.first) + " swing times (last_swing - first_swing)",
           times.is_array() ? "a list of " + std::to_string(times.size()) : describeJsonValue(times));
  f.times = UncertaintySwingTimes::makeEmpty(f.last - f.first);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const Json& t = times[k];
    if (t.is_number() && std::isfinite(t.get<double>()) && t.get<double>() > 0 && t.get<double>() <= kMaxSwingTime)
      f.times.swingTimes[k] = t.get<double>();
    else if (!t.is_null())
      r.fail("swing_times_s[" + std::to_string(k) + "]",
             "a swing time above 0 and at most " + formatNumber(kMaxSwingTime) +
                 " s (the largest time_limit_s a participant takes), or null",
             describeJsonValue(t));
    f.times.finished[k] = 1;
  }
  const Json& notRun = r.at("not_run");
  if (!notRun.is_array()) r.fail("not_run", "a list of swing indices", describeJsonValue(notRun));
  for (const Json& s : notRun) {
    if (!s.is_number_unsigned() || s.get<std::uint64_t>() < f.first || s.get<std::uint64_t>() >= f.last)
      r.fail("not_run", "swing indices from first_swing to last_swing - 1 (" + std::to_string(f.first) + " to " +
                            std::to_string(f.last) + " - 1)", describeJsonValue(s));
    f.times.finished[s.get<std::size_t>() - f.first] = 0;
  }
  const std::size_t finished = static_cast<std::size_t>(r.whole("swings_finished", kMaxSwings));
  if (finished != f.times.countFinished())
    r.fail("swings_finished", std::to_string(f.times.countFinished()) + " (the swings not in not_run)",
           std::to_string(finished));
  if (r.flag("partial") != f.isPartial())
    r.fail("partial", f.isPartial() ? "true (not_run lists swings)" : "false (no swing is in not_run)",
           f.isPartial() ? "false" : "true");
  f.samplesFinished = static_cast<int>(r.whole("samples_finished", static_cast<std::uint64_t>(f.run.samples)));
  const std::string checksum = calcSwingTimesChecksum(f);
  if (r.text("swing_times_checksum") != checksum)
    r.fail("swing_times_checksum", checksum + " (computed from swing_times_s and not_run)",
           "\"" + r.text("swing_times_checksum") + "\": the swing times were changed after swingsim wrote them; "
           "rerun the shard (or the sweep) that wrote this file");
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
    check.differ("assumptions_fingerprint", expected.assumptionsFingerprint,
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
                     " (K = 0 to " + std::to_string(head.shardCount - 1) + "), found " + std::to_string(byIndex.size()) +
                     "; missing K = " + missing + " (files " +
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
