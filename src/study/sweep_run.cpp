#include "study/sweep_run.h"

#include "sweep/measured_validation.h"
#include "sweep/terminal_impact.h"

namespace swingsim {

void completeSweepResults(const SweepStudy& study, SweepResults& results,
                          const std::vector<ParticipantCalibration>& calibrations, int jobs) {
  checkTerminalImpact(study, results, jobs);
  results.calibratedTo = study.calibrateTo;
  results.calibrations = calibrations;
  validateOnTable4(study, results);
}

UncertaintyOptions makeUncertaintyOptions(const SweepStudy& study) {
  UncertaintyOptions options;
  options.samples = study.uncertaintySamples;
  options.seed = static_cast<std::uint64_t>(study.uncertaintySeed);
  options.sensitivity = true;
  return options;
}

}  // namespace swingsim
