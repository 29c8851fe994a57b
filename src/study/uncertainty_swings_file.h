#pragma once
// The swing times of an uncertainty analysis, or of a slice of it, as a JSON file
// (docs/uncertainty.md): what an interrupted `sweep --uncertainty N` keeps
// (`uncertainty.partial.json`, resumed by the same command) and what `sweep --shard K/N`
// writes (`uncertainty-shard-K-of-N.json`, combined by `swingsim merge`). The file names
// the run it belongs to (study, fingerprints of its inputs and of the assumption table,
// samples, seed, slice), so a resume or a merge refuses swings from another run. Swing times
// are written with 17 significant digits, so they read back bit for bit (docs/uncertainty.md,
// "Interrupted runs, shards and merge"). Its keys are listed once, for writing and reading
// (io/json_archive.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "study/shard_file_header.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// Identifies the analysis a file's swings belong to; two files can be combined (or one
/// resumed) only if all of these agree (study, study path, calcStudyInputsFingerprint and
/// version: ShardFileRun).
struct UncertaintyRunIdentity : ShardFileRun {
  std::string assumptionsFingerprint;  ///< calcAssumptionsFingerprint
  int samples = 0;                     ///< Monte Carlo samples asked
  std::uint64_t seed = 0;
  bool sensitivity = true;     ///< the one-at-a-time runs are part of the swings
  std::size_t swingCount = 0;  ///< swings of the whole analysis (UncertaintyPlan::swingCount)
};

/// One file: the identity, which slice of the swings it covers, and their times.
struct UncertaintySwingsFile {
  std::string path;  ///< where it was read from ("" if not read)
  UncertaintyRunIdentity run;
  bool sharded = false;             ///< written by `--shard`; false: a whole run's partial result
  int shardIndex = 0;               ///< K of `--shard K/N`, 0 <= K < N
  int shardCount = 1;               ///< N
  std::size_t first = 0, last = 0;  ///< the swings it covers, [first, last) in swing order
  /// Swing times for [first, last) (s; NaN where no swing ended or not run) and which ran.
  UncertaintySwingTimes times;  ///< indexed from `first`
  int samplesFinished = 0;      ///< Monte Carlo samples wholly inside the finished swings
  /// true while some swing of [first, last) has not run.
  bool isPartial() const { return times.countFinished() < last - first; }
};

/// Fingerprint of the assumption table as applied: keys, units, kinds and each participant's
/// range (exact values), and the plan's run layout (lowerings per run).
std::string calcAssumptionsFingerprint(const UncertaintyPlan& plan);

/// The identity of the analysis `plan` runs for `study`.
UncertaintyRunIdentity makeUncertaintyRunIdentity(const SweepStudy& study, const UncertaintyPlan& plan,
                                                  const std::string& version);

/// The JSON text of a file ("partial": true while swings are missing).
std::string formatUncertaintySwingsJson(const UncertaintySwingsFile& file);
/// Reads a file written by formatUncertaintySwingsJson. Throws InputError naming the file,
/// the key, what was expected and what was found.
UncertaintySwingsFile readUncertaintySwingsFile(const std::string& path);

/// Throws InputError if `found` (read from a file) belongs to another analysis than
/// `expected`: `FILE: KEY: expected E (what), found F`; `what` names the expected side
/// ("this run", "the first shard FILE").
void checkSameUncertaintyRun(const UncertaintyRunIdentity& expected, const UncertaintySwingsFile& found,
                             const std::string& what);

/// Puts a file's finished swings into the whole analysis's times (sized swingCount).
void copyFinishedSwings(const UncertaintySwingsFile& file, UncertaintySwingTimes& times);

/// Combines complete shard files into the swing times of the whole analysis. Throws
/// InputError naming the file and key if a file is not a shard, is partial, belongs to
/// another analysis than the first, has another shard count or a slice that does not match
/// its K, or repeats a shard, and naming the missing K if any shard is missing.
UncertaintySwingTimes mergeUncertaintyShards(const std::vector<UncertaintySwingsFile>& shards);

/// File names under the output folder: the whole run's partial result, and shard K of N's
/// (`uncertainty-shard-K-of-N.json`, K zero-padded to N's width).
std::string uncertaintyPartialFileName();
std::string uncertaintyShardFileName(int index, int shards);

}  // namespace swingsim
