#include "sweep/measured_validation.h"

#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "numerics/metrics.h"
#include "sweep/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Swing time (s) of participant p at `lowering` with its hip time scale set to `scale`; NaN
// if no swing ends there.
double swingTimeWith(const SweepStudy& study, Participant p, double scale, double lowering) {
  p.hipMoment.timeScale = scale;
  const SwingSetup setup = makeSwingSetup(p, findStudyKneeModel(study, p), lowering);
  SwingOptions options = study.swing;
  options.recordTrajectory = false;
  try {
    if (lowering > calcMaxLowering(p) + 1e-9) return kNaN;
    return simulateSwing(setup, options).swingTime;
  } catch (const std::exception&) {
    return kNaN;
  }
}

}  // namespace

std::vector<ParticipantCalibration> calibrateSweepParticipants(SweepStudy& study) {
  std::vector<ParticipantCalibration> out;
  if (study.calibrateTo == CalibrationTarget::kStored) return out;
  for (Participant& p : study.participants) {
    ParticipantCalibration c;
    c.participant = p.name;
    c.timeScale = p.hipMoment.timeScale;
    const PublishedParticipant* pub = findPublished(p.name);
    if (pub == nullptr) {
      c.failure = "not a Burkett 2004 participant: no Table 3 target; the stored time scale is used";
      out.push_back(c);
      continue;
    }
    c.targetTime = table3Target(*pub, study.calibrateTo);
    const SwingSetup setup = makeSwingSetup(p, findStudyKneeModel(study, p));
    try {
      const CalibrationResult r = calibrateHipTimeScale(setup, c.targetTime, study.swing);
      c.timeScale = r.timeScale;
      c.ok = true;
      p.hipMoment.timeScale = r.timeScale;
    } catch (const RunError& e) {
      std::string why = e.what();
      if (why.rfind(p.name + ": ", 0) == 0) why = why.substr(p.name.size() + 2);  // the report names the participant
      c.failure = why + "; the stored time scale " + formatNumber(p.hipMoment.timeScale) + " is used";
    }
    out.push_back(c);
  }
  return out;
}

void validateOnTable4(const SweepStudy& study, SweepResults& results) {
  results.table4.clear();
  for (std::size_t i = 0; i < study.participants.size() && i < results.participants.size(); ++i) {
    const Participant& p = study.participants[i];
    const PublishedParticipant* pub = findPublished(p.name);
    if (pub == nullptr) continue;
    Table4Validation v;
    v.participant = p.name;
    // The leave-one-out scale: the mean of the other participants' calibrated scales.
    double looScale = kNaN;
    bool ownOk = false;
    {
      double sum = 0;
      int n = 0;
      for (const auto& c : results.calibrations) {
        if (c.participant == p.name) ownOk = c.ok;
        if (c.participant != p.name && c.ok) {
          sum += c.timeScale;
          ++n;
        }
      }
      if (n > 0) looScale = sum / n;
    }
    v.calibrated = ownOk;
    std::vector<double> ours, model, loo;
    for (const auto& row : pub->table4) {
      Table4Row r;
      r.lowering = row.lowering;
      r.measured = row.measuredProsthetic;
      r.model = row.model;
      r.ours = kNaN;
      for (const auto& pt : results.participants[i].points)
        if (std::fabs(pt.lowering - row.lowering) < 1e-9 && pt.ok) r.ours = pt.result.swingTime;
      r.oursLeaveOneOut = ownOk && !std::isnan(looScale) ? swingTimeWith(study, p, looScale, row.lowering) : kNaN;
      // The standard location is Table 3 (the calibration target), not validation.
      if (row.lowering > 0) {
        if (!std::isnan(r.ours)) ours.push_back(r.ours - r.measured);
        model.push_back(r.model - r.measured);
        if (!std::isnan(r.oursLeaveOneOut)) loo.push_back(r.oursLeaveOneOut - r.measured);
      }
      v.rows.push_back(r);
    }
    v.rmseOurs = calcRms(ours);
    v.rmseModel = calcRms(model);
    v.rmseLeaveOneOut = calcRms(loo);
    // Shortening to the largest lowering where ours is known too.
    v.shorteningMeasured = v.shorteningOurs = v.shorteningModel = kNaN;
    if (!v.rows.empty() && !std::isnan(v.rows.front().ours)) {
      for (auto it = v.rows.rbegin(); it != v.rows.rend(); ++it) {
        if (it->lowering <= 0 || std::isnan(it->ours)) continue;
        v.shorteningMeasured = v.rows.front().measured - it->measured;
        v.shorteningOurs = v.rows.front().ours - it->ours;
        v.shorteningModel = v.rows.front().model - it->model;
        break;
      }
    }
    results.table4.push_back(std::move(v));
  }
}

}  // namespace swingsim
