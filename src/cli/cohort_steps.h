#pragma once
// `swingsim sweep COHORT.yaml` and `swingsim merge cohort-shard-*.json` for studies of kind
// cohort-sweep (docs/cohort.md): the whole run (resumable from cohort.partial.json), one
// shard of it (`--shard K/N`, resumable from its shard file), and the merge of the shards
// into the report and JSON one run writes.
#include <optional>
#include <string>
#include <vector>

namespace swingsim::cli {

/// What `swingsim sweep` was given for a cohort study.
struct CohortSweepArguments {
  std::string study;
  std::optional<std::string> out, json;
  int jobs = 0;  ///< worker threads, 0 = all cores
  bool sharded = false;
  int shardIndex = 0, shardCount = 1;  ///< `--shard K/N`
};

/// Runs the cohort study (or its shard). Returns the exit code.
int runCohortSweep(const CohortSweepArguments& a);

/// Merges cohort shard files into the report and --json of one run. Returns the exit code.
int runCohortMerge(const std::vector<std::string>& shardFiles, const std::optional<std::string>& out,
                   const std::optional<std::string>& json);

}  // namespace swingsim::cli
