#pragma once
// The record-agreement rule of `swingsim diagnose` (docs/diagnosis.md, "A near miss
// cannot pass"): an effect that is in the data has one value in every record. The chosen candidate,
// already fitted on the pooled training records, is refitted on each record alone (training
// and held out); where its parameter's per-record values differ by more than their intervals
// allow (Cochran's heterogeneity test), it stands for a law of another shape that acts
// unequally across conditions (a near miss) and is not accepted.
#include <limits>
#include <string>
#include <vector>

#include "identify/diagnosis_engine.h"

namespace swingsim {

/// One parameter of the effect fitted on one record alone, with its 95 % interval.
struct RecordEstimate {
  std::string stem;
  double value = 0, lower = 0, upper = 0;
};

/// What the rule found for one candidate.
struct RecordAgreement {
  bool tested = false;  ///< false: the plant takes no part, or fewer than two records scored
  bool agrees = true;
  /// The least agreeing parameter, its heterogeneity p (Bonferroni over the effect's fitted
  /// parameters) and its per-record estimates.
  std::string parameter;
  double pAdjusted = std::numeric_limits<double>::quiet_NaN();
  double level = 0;  ///< the test's level: it differs where pAdjusted < level
  std::vector<RecordEstimate> estimates;
  /// One sentence for the report: why it failed, or how it held.
  std::string describe() const;
};

/// The rule for effect `id` of the pooled fit `pooled` at level `alpha`. A record whose
/// refit fails, or whose parameter has no finite positive standard error (held at a bound,
/// or not determined by that record), leaves that record out of that parameter's test.
RecordAgreement checkRecordAgreement(const DiagnosisPlant& plant, const PlantFit& pooled, EffectId id, double alpha);

}  // namespace swingsim
