#include "study/shard_file_header.h"

#include <algorithm>
#include <cstdio>

#include "core/input_error.h"
#include "study/uncertainty_swings_file.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

ShardFileRun makeShardFileRun(const SweepStudy& study, const std::string& version) {
  ShardFileRun run;
  run.study = study.name;
  run.studyPath = study.path;
  run.inputsFingerprint = calcStudyInputsFingerprint(study);
  run.version = version;
  return run;
}

void formatShardFileHead(Json& j, const char* format, int formatVersion, bool partial, const ShardFileRun& run) {
  j["format"] = format;
  j["format_version"] = formatVersion;
  j["partial"] = partial;
  j["study"] = run.study;
  j["study_path"] = run.studyPath;
  j["swingsim_version"] = run.version;
  j["inputs_fingerprint"] = run.inputsFingerprint;
}

Json formatShardKey(bool sharded, int index, int count) {
  if (!sharded) return nullptr;
  return {{"index", index}, {"count", count}};
}

ShardFileRun readShardFileHead(const ResultsFileFields& f, const Json& doc, const char* format, int formatVersion) {
  if (f.text("format") != format)
    f.fail("format", std::string("\"") + format + "\"", describeJsonValue(doc.at("format")));
  if (f.whole("format_version", 1000) != static_cast<std::uint64_t>(formatVersion))
    f.fail("format_version", std::to_string(formatVersion), describeJsonValue(doc.at("format_version")));
  ShardFileRun run;
  run.study = f.text("study");
  run.studyPath = f.text("study_path");
  run.version = f.text("swingsim_version");
  run.inputsFingerprint = f.text("inputs_fingerprint");
  return run;
}

void readShardKey(const ResultsFileFields& shard, int& index, int& count) {
  count = static_cast<int>(shard.whole("count", 1000000));
  if (count < 1) shard.fail("count", "a shard count of at least 1", "0");
  index = static_cast<int>(shard.whole("index", static_cast<std::uint64_t>(count - 1)));
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
    throw InputError(*s.path + ": shard: expected {\"index\": K, \"count\": N} (a file written by sweep --shard K/N), "
                     "found null (the partial result of a whole run: rerun its sweep command to resume it)");
}

void checkShardSlice(const ShardSlice& s, const ShardSlice& head, const std::string& sliceKeys) {
  if (s.count != head.count)
    failResultsFileKey(*s.path, "shard.count", std::to_string(head.count) + " (the first shard, " + *head.path + ")",
                       std::to_string(s.count));
  const auto slice = calcShardSwings(s.total, s.index, s.count);
  if (s.first != slice.first || s.last != slice.second)
    failResultsFileKey(*s.path, sliceKeys,
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

}  // namespace swingsim
