#pragma once
// The participant results of a cohort study, or of a slice of it, as a JSON file
// (docs/cohort.md): what an interrupted `sweep COHORT.yaml` keeps (`cohort.partial.json`,
// resumed by the same command) and what `sweep COHORT.yaml --shard K/N` writes
// (`cohort-shard-K-of-N.json`, combined by `swingsim merge`), as the uncertainty analysis's
// swings files do (uncertainty_swings_file.h). The file names the run it belongs to (study,
// a fingerprint of every drawn participant and its target, count, seed, version), so a
// resume or a merge refuses results of another run. Numbers are written in the shortest form
// that reads back to the same double, so a merge reports what one run does. Its keys are
// listed once, for writing and reading (io/json_archive.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "study/shard_file_header.h"
#include "sweep/cohort_run.h"

namespace swingsim {

/// Identifies the run a file's results belong to; files combine only if all of these agree
/// (study, study path, calcStudyInputsFingerprint of the drawn study and version: ShardFileRun).
struct CohortRunIdentity : ShardFileRun {
  int participants = 0;
  std::uint64_t seed = 0;
};

struct CohortResultsFile {
  std::string path;  ///< where it was read from ("" if not read)
  CohortRunIdentity run;
  bool sharded = false;  ///< written by `--shard`; false: a whole run's partial result
  int shardIndex = 0, shardCount = 1;
  std::size_t first = 0, last = 0;               ///< the participants it covers, [first, last)
  std::vector<CohortParticipantResult> results;  ///< indexed from `first`
  std::size_t countFinished() const;
  bool isPartial() const { return countFinished() < last - first; }
};

/// The identity of a run of `cohort`.
CohortRunIdentity makeCohortRunIdentity(const Cohort& cohort, const std::string& version);

/// The JSON text of a file ("partial": true while participants are missing).
std::string formatCohortResultsJson(const CohortResultsFile& file);
/// True if the file at `path` begins as a cohort results file does (its "format" key, the
/// first this writer puts): merge's dispatch; the reader then checks it all.
bool isCohortResultsFile(const std::string& path);
/// Reads a file written by formatCohortResultsJson. Throws InputError naming the file, the
/// key, what was expected and what was found.
CohortResultsFile readCohortResultsFile(const std::string& path);

/// Throws InputError if `found` belongs to another run than `expected` (FILE: KEY: expected
/// E (what), found F).
void checkSameCohortRun(const CohortRunIdentity& expected, const CohortResultsFile& found, const std::string& what);

/// Combines complete shard files into every participant's result. Throws InputError naming
/// the file and key if a file is not a shard, is partial, belongs to another run than the
/// first, has another shard count or a slice that does not match its K, repeats a shard,
/// or (naming K) if a shard is missing.
std::vector<CohortParticipantResult> mergeCohortShards(const std::vector<CohortResultsFile>& shards);

/// File names under the output folder: a whole run's partial result, and shard K of N's.
std::string cohortPartialFileName();
std::string cohortShardFileName(int index, int shards);

}  // namespace swingsim
