#pragma once
// The steps of a knee-axis sweep run that are not about the terminal (no progress bar, no
// Ctrl-C handling), shared by `swingsim sweep`/`merge` and the Python module: the checks
// after the plain sweep, and the uncertainty analysis's options from the study.
#include <vector>

#include "sweep/measured_validation.h"
#include "sweep/sweep.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

/// After the plain sweep: Burkett's bounce and interior optimum (terminal impact check, with
/// `jobs` worker threads, 0 = all cores), the calibration the sweep ran with, and the Table 4
/// validation, all stored in `results`.
void completeSweepResults(const SweepStudy& study, SweepResults& results,
                          const std::vector<ParticipantCalibration>& calibrations, int jobs);

/// The uncertainty analysis's options from the study (samples, seed, with the sensitivity).
UncertaintyOptions makeUncertaintyOptions(const SweepStudy& study);

}  // namespace swingsim
