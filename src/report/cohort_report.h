#pragma once
// The report of a cohort study (docs/cohort.md): report.md with the distributions drawn and
// their sources, the distribution of the fastest lowering and of the time gained, and which
// participant properties predict the gain (Spearman's rho with 95 % Fisher-z intervals);
// its SVG figures; cohort.csv (one row per participant); and the --json document. Built
// only from the cohort and its results, so a merge of shards writes what one run does.
#include <string>
#include <utility>
#include <vector>

#include "sweep/cohort_run.h"

namespace swingsim {

/// report.md, cohort.csv and the figures, as (file name, contents).
std::vector<std::pair<std::string, std::string>> makeCohortReport(const Cohort& cohort,
                                                                  const std::vector<CohortParticipantResult>& results,
                                                                  const CohortSummary& summary);

/// The short summary printed on stdout.
std::string formatCohortSummary(const Cohort& cohort, const CohortSummary& summary);

/// The --json document: per participant its drawn values, calibration, fastest lowering and
/// time gained; the intervals; the predictors with rho and interval.
std::string formatCohortJson(const Cohort& cohort, const std::vector<CohortParticipantResult>& results,
                             const CohortSummary& summary);

}  // namespace swingsim
