#include "study/diagnosis_size.h"

#include "study/run_estimate.h"

namespace swingsim {

std::uint64_t getDefaultMaxDiagnosisRows(PlantKind plant) {
  switch (plant) {
    case PlantKind::kSweep:
      return kDefaultMaxSweepDiagnosisRows;
    case PlantKind::kCylinder:
      return kDefaultMaxCylinderDiagnosisRows;
    default:
      return kDefaultMaxSwingDiagnosisRows;
  }
}

void announceDiagnosisSize(const std::string& name, const std::string& studyPath, PlantKind plant, std::uint64_t rows,
                           std::size_t records, const DiagnosisRowLimit& limit) {
  // Seconds per row of a whole diagnosis on one core, measured (docs/robustness.md, "Large
  // runs"): rough, as the number of fit steps depends on the data.
  // Swing: the 3-record demo, 828 rows, 8.1 s; sweep: Burkett's Table 4, 16 rows, 154 s (both
  // on a busy 2-core machine); bench: a guess, not measured.
  constexpr double kSecondsPerSweepRow = 10.0, kSecondsPerSwingRow = 0.01, kSecondsPerBenchRow = 1e-4;
  const bool sweep = plant == PlantKind::kSweep, cylinder = plant == PlantKind::kCylinder;
  const std::string what = sweep      ? "a measured sweep table"
                           : cylinder ? std::to_string(records) + " bench record(s)"
                                      : std::to_string(records) + " swing record(s), after any resample_s";
  const std::string shrink = sweep ? "give fewer rows (one per participant and lowering, averaged over trials)"
                                   : "resample the records more coarsely (resample_s) or give fewer or shorter ones";
  announceRunSize({"diagnose " + name, "the diagnosis", rows, "rows", what,
                   sweep      ? kSecondsPerSweepRow
                   : cylinder ? kSecondsPerBenchRow
                              : kSecondsPerSwingRow,
                   1},
                  limit.maxRows ? limit.maxRows : getDefaultMaxDiagnosisRows(plant), studyPath, shrink, "--max-rows");
}

}  // namespace swingsim
