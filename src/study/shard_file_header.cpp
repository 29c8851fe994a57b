#include "study/shard_file_header.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "study/sweep_study.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

void Fingerprint::add(const std::string& text) {
  for (unsigned char c : text) hash_ = (hash_ ^ c) * 0x100000001b3ULL;
  hash_ = (hash_ ^ 0xffU) * 0x100000001b3ULL;  // a separator, so "ab"+"c" != "a"+"bc"
}

void Fingerprint::add(double value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", value);  // exact
  add(std::string(buf));
}

std::string Fingerprint::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash_));
  return buf;
}

namespace {

std::string absolutePath(const std::string& path) {
  std::error_code ec;
  const auto p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

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

ShardFileRun makeShardFileRun(const SweepStudy& study, const std::string& version) {
  ShardFileRun run;
  run.study = study.name;
  run.studyPath = study.path;
  run.inputsFingerprint = calcStudyInputsFingerprint(study);
  run.version = version;
  return run;
}

JsonCheck<std::uint64_t> mustBeFormatVersion(std::uint64_t expected) {
  return [expected](const std::uint64_t& v) {
    if (v == expected) return std::string();
    if (v < expected)
      return std::to_string(expected) +
             " (this file was written by an older swingsim, before its payload was "
             "checksummed and range-checked: rerun the shard, or the sweep, that wrote it)";
    return std::to_string(expected) + " (this file was written by a newer swingsim: read it with that version)";
  };
}

std::string mustBeSwingTime(const double& t) {
  return t > kSwingTimeRange.lower && t <= kSwingTimeRange.upper
             ? std::string()
             : "a swing time above 0 and at most " + formatNumber(kSwingTimeRange.upper) + " s (" +
                   kSwingTimeRange.reason + "), or null";
}

JsonCheck<double> mustBePlausibleNumber(const PlausibleRange& range, std::string what) {
  return [range, what = std::move(what)](const double& v) {
    const std::string problem = checkPlausible(v, range, what);
    return problem.empty() ? problem : problem.substr(std::string("expected ").size());  // the archive says "expected"
  };
}

SameRunCheck::SameRunCheck(std::string path, std::string what, std::string otherRun)
    : path_(std::move(path)), what_(std::move(what)), otherRun_(std::move(otherRun)) {}

void SameRunCheck::differ(const std::string& key, const std::string& expected, const std::string& found) const {
  throw InputError(path_ + ": " + key + ": expected " + expected + " (" + what_ + "), found " + found + ": " +
                   otherRun_);
}

void SameRunCheck::study(const ShardFileRun& expected, const ShardFileRun& found) const {
  if (found.study != expected.study) differ("study", "\"" + expected.study + "\"", "\"" + found.study + "\"");
}

void SameRunCheck::inputs(const ShardFileRun& expected, const ShardFileRun& found, const std::string& why) const {
  if (found.inputsFingerprint != expected.inputsFingerprint)
    differ("inputs_fingerprint", expected.inputsFingerprint + " (" + expected.studyPath + ")",
           found.inputsFingerprint + " (" + found.studyPath + ")" + why);
}

void SameRunCheck::version(const ShardFileRun& expected, const ShardFileRun& found) const {
  if (found.version != expected.version) differ("swingsim_version", expected.version, found.version);
}

void requireShardFile(const ShardSlice& s) {
  if (!s.sharded)
    throw InputError(*s.path +
                     ": shard: expected {\"index\": K, \"count\": N} (a file written by sweep --shard K/N), "
                     "found null (the partial result of a whole run: rerun its sweep command to resume it)");
}

void checkShardSlice(const ShardSlice& s, const ShardSlice& head, const std::string& sliceKeys) {
  if (s.count != head.count)
    failJsonFileKey(*s.path, "shard.count", std::to_string(head.count) + " (the first shard, " + *head.path + ")",
                    std::to_string(s.count));
  const auto slice = calcShardSwings(s.total, s.index, s.count);
  if (s.first != slice.first || s.last != slice.second)
    failJsonFileKey(*s.path, sliceKeys,
                    std::to_string(slice.first) + ", " + std::to_string(slice.second) + " (shard " +
                        std::to_string(s.index) + "/" + std::to_string(s.count) + ")",
                    std::to_string(s.first) + ", " + std::to_string(s.last));
}

std::string formatShardFileName(const std::string& stem, int index, int shards) {
  const int width = static_cast<int>(std::to_string(std::max(0, shards - 1)).size());
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s-shard-%0*d-of-%d.json", stem.c_str(), width, index, shards);
  return buf;
}

const std::string* ShardIndexSet::add(int index, const std::string& path) {
  const auto [it, added] = byIndex_.emplace(index, &path);
  return added ? nullptr : it->second;
}

std::string ShardIndexSet::listMissing(int count, int listed, int& missingCount) const {
  std::string missing;
  missingCount = 0;
  for (int k = 0; k < count; ++k) {
    if (byIndex_.count(k)) continue;
    if (++missingCount <= listed) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  }
  if (missingCount > listed) missing += ", ...";
  return missing;
}

std::string formatShardKey(bool sharded, int index, int count) {
  return sharded ? std::to_string(index) + "/" + std::to_string(count) : std::string("null");
}

void checkSameShardKey(const std::string& path, const std::string& expected, const std::string& found) {
  if (expected != found) throw InputError(path + ": shard: expected " + expected + " (this run), found " + found);
}

}  // namespace swingsim
