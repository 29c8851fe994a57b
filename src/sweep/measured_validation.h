#pragma once
// Burkett 2004's measured swing times as a target (issue "swing fidelity", item 5):
// calibrate each participant's hip time scale to Table 3 (model or measured column) before
// a sweep, then score the sweep against Table 4's measured prosthetic swing times, beside
// Burkett's own model, with a leave-one-participant-out check of the calibration.
#include <vector>

#include "sweep/sweep.h"

namespace swingsim {

/// Calibrates the hip time scale of every Burkett participant of `study` to
/// study.calibrateTo (Table 3's model or measured column) and stores it in the study's
/// participants (in memory; the files are not changed). A target no time scale reaches
/// (P2's measured 0.385 s) leaves that participant's stored scale and is reported.
/// Non-Burkett participants are skipped with a note. Returns one entry per participant.
std::vector<ParticipantCalibration> calibrateSweepParticipants(SweepStudy& study);

/// Fills results.table4: per Burkett participant, Table 4's measured times beside ours (from
/// the sweep's points) and Burkett's model, their RMS errors and the shortening with
/// lowering. If the study was calibrated (results.calibrations), also the leave-one-out
/// prediction: the participant's time scale replaced by the mean of the other calibrated
/// participants' scales (is the calibration something a new participant could use?).
void validateOnTable4(const SweepStudy& study, SweepResults& results);

}  // namespace swingsim
