#pragma once
// A cohort study's run (kind cohort-sweep, docs/cohort.md), from the study to its written
// outputs, for `swingsim sweep COHORT.yaml` and `swingsim merge cohort-shard-*.json`: the
// whole run (resumable from cohort.partial.json), one shard of it (`--shard K/N`, resumable
// from its shard file), and the merge of the shards into the report and JSON one run writes.
// The caller's side (terminal, Ctrl-C) is a SweepRunControl, as for a knee-axis sweep.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "study/sweep_run.h"

namespace swingsim {

/// What `swingsim sweep` was given for a cohort study.
struct CohortSweepArguments {
  std::string study;
  std::optional<std::string> out, json;
  int jobs = 0;  ///< worker threads, 0 = all cores
  bool sharded = false;
  int shardIndex = 0, shardCount = 1;                ///< `--shard K/N`
  std::uint64_t maxSwings = kDefaultMaxSweepSwings;  ///< `--max-swings`: the most swings this run (or shard) may have
};

/// Runs the cohort study (or its shard). Returns the exit code.
int runCohortSweep(const CohortSweepArguments& a, const SweepRunControl& control);

/// Merges cohort shard files into the report and --json of one run. Returns the exit code.
int runCohortMerge(const std::vector<std::string>& shardFiles, const std::optional<std::string>& out,
                   const std::optional<std::string>& json, const SweepRunControl& control);

}  // namespace swingsim
