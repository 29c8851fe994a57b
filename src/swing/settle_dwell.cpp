#include "swing/settle_dwell.h"

#include <algorithm>
#include <utility>

namespace swingsim {

SettleDwell::SettleDwell(const SwingOptions& options, bool canLoosen, double zoneOfStability)
    : accuracy_(options.accuracy),
      looseAccuracy_(std::min(options.accuracy * options.dwellAccuracyFactor, kLoosestDwellAccuracy)),
      zone_(zoneOfStability),
      // The impact bookkeeping wants full accuracy.
      allowed_(canLoosen && !options.trackImpactEnergy && looseAccuracy_ > options.accuracy) {}

bool SettleDwell::mustRedo(const StepEnd& previous, const StepEnd& now, const SwingLog& log) const {
  if (!loose_) return false;
  // The knee back near the zone's edge (or out of it): a bounce may decide the swing end.
  // (The knee enters the zone falling: only where it rises again does the edge matter.)
  const double edge = zone_ - kLooseDwellMargin;
  bool nearEdge = now.kneeRate > 0 && now.knee > edge;
  if (previous.kneeRate > 0 && now.kneeRate < 0) {
    const double h = now.t - previous.t;
    const double top = findRoot(
        [&](double x) { return calcHermite(previous.kneeRate, previous.kneeAcc, now.kneeRate, now.kneeAcc, h, x); }, h);
    nearEdge = nearEdge || calcHermite(previous.knee, previous.kneeRate, now.knee, now.kneeRate, h, top) > edge;
  }
  return nearEdge || !log.candidate;
}

const DwellCheckpoint& SettleDwell::redo(DormandPrinceStepper& stepper) {
  stepper.restoreCheckpoint(accuracy_);
  tightenedFor_ = checkpoint_.candidateTime;
  loose_ = false;
  ++retries_;
  return checkpoint_;
}

bool SettleDwell::shouldLoosen(const SwingLog& log) const {
  return allowed_ && !loose_ && log.candidate && log.candidateTime != tightenedFor_ &&
         log.candidateTime != checkpoint_.candidateTime;
}

void SettleDwell::loosen(DwellCheckpoint checkpoint, DormandPrinceStepper& stepper) {
  checkpoint_ = std::move(checkpoint);
  stepper.saveCheckpoint();
  stepper.loosen(looseAccuracy_);
  loose_ = true;
}

}  // namespace swingsim
