#pragma once
// What the two resumable, shardable results files (cohort_results_file.h,
// uncertainty_swings_file.h) have in common: the header keys they begin with and their
// "shard" key (fields of their one list for io/json_archive.h), the fingerprint of the
// study's inputs that names their run, the checksum over their payload and the range checks
// of the numbers in it, the check that a file belongs to the same run, and
// the checks merge makes of a set of shard files (each a finished shard of the same count,
// its slice the one calcShardSwings gives its K, each K once, none missing). The wording of
// a message that one format words otherwise stays with that format.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/plausible_ranges.h"
#include "io/json_archive.h"
#include "sweep/sweep.h"

namespace swingsim {

/// The part of a run's identity every results file names; files combine only if it agrees
/// (and the format's own keys do).
struct ShardFileRun {
  std::string study;              ///< the study's name
  std::string studyPath;          ///< the study file as the command line gave it
  std::string inputsFingerprint;  ///< calcStudyInputsFingerprint of the study
  std::string version;            ///< swingsim version that computed the results
};

/// FNV-1a 64 over text fed piece by piece: the fingerprints and checksums of results files.
class Fingerprint {
 public:
  void add(const std::string& text);
  /// The exact value (hexadecimal floating point).
  void add(double value);
  /// 16 hex digits.
  std::string hex() const;

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// Fingerprint (16 hex digits, FNV-1a 64) of everything in the study that a run's results
/// depend on, after any calibration: the study, every participant and every knee model as
/// swingsim would write them (paths relative to the study's folder), and the samples of a
/// measured thigh drive (its CSV's contents, not only its name).
std::string calcStudyInputsFingerprint(const SweepStudy& study);

/// The run part of `study` as given (its path as the command line gave it: merge loads it
/// from there, shards and merge sharing a working folder), computed by swingsim `version`.
ShardFileRun makeShardFileRun(const SweepStudy& study, const std::string& version);

/// Largest "format_version" a results file may name.
constexpr std::uint64_t kMaxResultsFormatVersion = 1000;
/// Largest N of `--shard K/N` a results file may name.
constexpr std::uint64_t kMaxShardCount = 1000000;

/// Accepts only `expected`; a file of an older version (written before its payload was
/// checksummed and range-checked) is refused with what to do: rerun what wrote it.
JsonCheck<std::uint64_t> mustBeFormatVersion(std::uint64_t expected);

/// The keys a results file begins with, in this order: format (must be `format`),
/// format_version (must be `formatVersion`), partial, study, study_path, swingsim_version,
/// inputs_fingerprint. "format" comes first (isCohortResultsFile reads only a file's head).
template <class Archive>
void serializeShardFileHead(Archive& a, const char* format, int formatVersion, bool& partial, ShardFileRun& run) {
  std::string name = format;
  a.text("format", name, mustBeText(format));
  int version = formatVersion;
  a.whole("format_version", version, kMaxResultsFormatVersion,
          mustBeFormatVersion(static_cast<std::uint64_t>(formatVersion)));
  a.flag("partial", partial);
  a.text("study", run.study);
  a.text("study_path", run.studyPath);
  a.text("swingsim_version", run.version);
  a.text("inputs_fingerprint", run.inputsFingerprint);
}

/// The check of a swing time in a results file (s; null, i.e. NaN, is not checked): above 0
/// and at most kSwingTimeRange's upper end (core/plausible_ranges.h).
std::string mustBeSwingTime(const double& t);
/// The check of a number in a results file against its plausible range (null, i.e. NaN,
/// is not checked): "<what> in [lower, upper] unit (reason)".
JsonCheck<double> mustBePlausibleNumber(const PlausibleRange& range, std::string what);

/// The checksum of a results file's payload (a Fingerprint of it, exact), written under
/// `key` before the payload: the writer writes `calc()`, the reader reads it into `stored`;
/// requirePayloadChecksum compares it once the payload is read.
template <class Archive>
void serializePayloadChecksum(Archive& a, const char* key, std::string& stored,
                              const std::function<std::string()>& calc) {
  if constexpr (!Archive::kReading) stored = calc();
  a.text(key, stored);
}

/// After the payload is read: refuses a file whose payload no longer gives the checksum
/// written with it (a number edited by hand, results cut and spliced) with `FILE: KEY:
/// expected COMPUTED (computed from FROM), found "STORED": WHAT were changed after swingsim
/// wrote them; rerun ...`. `from`: the payload's keys; `what`: "the swing times".
template <class Archive>
void requirePayloadChecksum(Archive& a, const char* key, const std::string& stored,
                            const std::function<std::string()>& calc, const std::string& from,
                            const std::string& what) {
  if constexpr (Archive::kReading) {
    const std::string computed = calc();
    a.require(stored == computed, key, computed + " (computed from " + from + ")", [&] {
      return "\"" + stored + "\": " + what +
             " were changed after swingsim wrote them; rerun the shard (or the sweep) "
             "that wrote this file";
    });
  }
}

/// Tag of the "shard" object's keys (serialize below).
struct ShardKeyOf {};

/// The "shard" object of a results file (CohortResultsFile, UncertaintySwingsFile:
/// shardIndex, shardCount): index (0 to count - 1), count (at least 1).
template <class Archive, class ResultsFile>
void serialize(Archive& a, ResultsFile& f, ShardKeyOf) {
  a.whole("index", f.shardIndex, kMaxShardCount - 1);
  a.whole("count", f.shardCount, kMaxShardCount,
          [](const std::uint64_t& n) { return n >= 1 ? std::string() : "a shard count of at least 1"; });
  a.require(f.shardIndex < f.shardCount, "index", "a whole number from 0 to " + std::to_string(f.shardCount - 1),
            [&f] { return std::to_string(f.shardIndex); });
}

/// The "shard" key of a results file: {"index": K, "count": N} for a shard (`f.sharded`),
/// null for a whole run's partial result.
template <class Archive, class ResultsFile>
void serializeShardKey(Archive& a, ResultsFile& f) {
  a.nullOrObject("shard", f, f.sharded, "{\"index\": K, \"count\": N}", ShardKeyOf{});
}

/// Compares a file's run with the run expected, key by key in the caller's order; the first
/// key that differs throws InputError `FILE: KEY: expected E (WHAT), found F: OTHER_RUN`.
class SameRunCheck {
 public:
  /// `path`: the file; `what`: the expected side ("this run", "the first shard, FILE");
  /// `otherRun`: what a difference means ("these swings belong to another analysis").
  SameRunCheck(std::string path, std::string what, std::string otherRun);
  [[noreturn]] void differ(const std::string& key, const std::string& expected, const std::string& found) const;
  /// The "study" key (names quoted).
  void study(const ShardFileRun& expected, const ShardFileRun& found) const;
  /// The "inputs_fingerprint" key, each with its study path; `why` follows the found side
  /// (": the study, ... differs").
  void inputs(const ShardFileRun& expected, const ShardFileRun& found, const std::string& why) const;
  /// The "swingsim_version" key.
  void version(const ShardFileRun& expected, const ShardFileRun& found) const;
  /// A whole-number key (participants, samples, seed, swings_total).
  template <class T>
  void count(const std::string& key, T expected, T found) const {
    if (found != expected) differ(key, std::to_string(expected), std::to_string(found));
  }

 private:
  std::string path_;
  std::string what_;
  std::string otherRun_;
};

/// What merge checks of one shard file.
struct ShardSlice {
  const std::string* path = nullptr;
  bool sharded = false;
  int index = 0, count = 1;         ///< K and N of `--shard K/N`
  std::size_t first = 0, last = 0;  ///< the items it covers, [first, last)
  std::size_t total = 0;            ///< items of the whole run (participants, swings)
};

/// The slice of a results file (CohortResultsFile, UncertaintySwingsFile: path, sharded,
/// shardIndex, shardCount, first, last) of a run of `total` items.
template <class ResultsFile>
ShardSlice describeShardSlice(const ResultsFile& file, std::size_t total) {
  ShardSlice slice;
  slice.path = &file.path;
  slice.sharded = file.sharded;
  slice.index = file.shardIndex;
  slice.count = file.shardCount;
  slice.first = file.first;
  slice.last = file.last;
  slice.total = total;
  return slice;
}

/// `K/N` of `--shard K/N`, or "null" for a whole run's file.
std::string formatShardKey(bool sharded, int index, int count);
/// Throws InputError `PATH: shard: expected EXPECTED (this run), found FOUND` unless they agree.
void checkSameShardKey(const std::string& path, const std::string& expected, const std::string& found);
/// The check that the file an earlier interrupted run left at `path` (CohortResultsFile,
/// UncertaintySwingsFile) holds the same slice as this run's: the same shard, or both not
/// sharded. Throws InputError naming the file and the key `shard`.
template <class ResultsFile>
void checkSameShard(const ResultsFile& thisRun, const ResultsFile& earlier, const std::string& path) {
  checkSameShardKey(path, formatShardKey(thisRun.sharded, thisRun.shardIndex, thisRun.shardCount),
                    formatShardKey(earlier.sharded, earlier.shardIndex, earlier.shardCount));
}

/// Throws InputError `FILE: shard: expected {"index": K, "count": N} ..., found null ...`
/// if the file is a whole run's partial result, not a shard.
void requireShardFile(const ShardSlice& s);
/// The checks of a shard against the first of its set, in this order: the same shard count
/// as `head` (key shard.count), then the slice calcShardSwings gives its K (key
/// `sliceKeys`, e.g. "first_swing, last_swing"). Throws InputError naming file and key.
void checkShardSlice(const ShardSlice& s, const ShardSlice& head, const std::string& sliceKeys);

/// The file name of shard K of N: `STEM-shard-K-of-N.json`, K zero-padded to the width of
/// N - 1 ("cohort-shard-03-of-12.json").
std::string formatShardFileName(const std::string& stem, int index, int shards);

/// The K of a shard set as merge meets them, each with its file.
class ShardIndexSet {
 public:
  /// Records shard K of the file at `path` (kept by reference); returns the file that had
  /// this K already, or nullptr.
  const std::string* add(int index, const std::string& path);
  std::size_t size() const { return byIndex_.size(); }
  /// The K from 0 to count - 1 that no file had, in order: "0, 3" (at most `listed`, then
  /// ", ..."), and how many they are in `missingCount`.
  std::string listMissing(int count, int listed, int& missingCount) const;

 private:
  std::map<int, const std::string*> byIndex_;
};

}  // namespace swingsim
