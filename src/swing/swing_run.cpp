#include "swing/swing_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "leg/toe_off_state.h"

namespace swingsim {

using namespace SimTK;

namespace {

const SwingSetup& checkSetup(const SwingSetup& setup) {
  if (setup.knee == nullptr) throw InputError(setup.participant.path + ": no knee model");
  return setup;
}

std::optional<ThighMotion> makeThighMotion(const Participant& p) {
  if (p.drive != SwingDrive::kThighKinematics) return std::nullopt;
  return ThighMotion(p.thighKinematics);
}

// The measured thigh drive: the swing must end before the measurement does.
// A measured pelvis moves the hip (under the measured thigh drive only).
std::optional<HipPath> makeHipPath(const Participant& p, const std::optional<ThighMotion>& thighMotion) {
  if (!thighMotion || !HipPath::hasPelvis(p.thighKinematics)) return std::nullopt;
  return HipPath(p.thighKinematics, p.hipOffsetInPelvis, p.path);
}

double calcTimeLimit(const Participant& p, const std::optional<ThighMotion>& thighMotion) {
  return thighMotion ? std::min(p.swingEnd.timeLimit, thighMotion->getEndTime()) : p.swingEnd.timeLimit;
}

}  // namespace

SwingRun::SwingRun(const SwingSetup& setup, const SwingOptions& options)
    : setup_(checkSetup(setup)),
      options_(options),
      p_(setup.participant),
      rule_(p_.swingEnd),
      geometry_(calcLegGeometry(p_, setup.lowering, setup.added)),
      thighMotion_(makeThighMotion(p_)),
      hipPath_(makeHipPath(p_, thighMotion_)),
      leg_(geometry_, *setup.knee, p_.hipMoment, p_.hipRange, calcHipHeight(p_), options.trackImpactEnergy,
           thighMotion_ ? &*thighMotion_ : nullptr, hipPath_ ? &*hipPath_ : nullptr),
      timeLimit_(calcTimeLimit(p_, thighMotion_)),
      hipHeight_(calcHipHeight(p_)),
      log_(rule_.settleDwell),
      climb_(*setup.knee),
      errors_(setup, options, leg_, timeLimit_),
      budget_(options),
      dwell_(options, options.integrator == SwingIntegrator::kDormandPrince, rule_.zoneOfStability),
      thighFailure_(setup, options, options.integrator == SwingIntegrator::kDormandPrince) {
  if (options.simbodyEvents && options.integrator == SwingIntegrator::kDormandPrince)
    throw std::invalid_argument("simulateSwing: Simbody's event handlers need one of Simbody's integrators");
  MultibodySystem& system = leg_.updSystem();
  if (options.simbodyEvents) addSwingEventHandlers(system, leg_, log_, rule_, options.eventWindow);
  State initial = leg_.makeInitialState(calcToeOffState(p_, thighMotion_ ? &*thighMotion_ : nullptr));
  const int numMobilities = initial.getNU();
  if (options.integrator == SwingIntegrator::kDormandPrince) {
    // End steps on the hip moment's kinks; the thigh spline is smooth (C4). The stepper takes
    // the initial state over (a State copy costs about 4 % of a swing).
    auto dp =
        std::make_unique<DormandPrinceStepper>(system, std::move(initial), options.accuracy,
                                               thighMotion_ ? std::vector<double>{} : p_.hipMoment.calcBreakpoints());
    dormandPrince_ = dp.get();
    // The knee's levels: inside the zone, the stop.
    std::vector<double> levels{rule_.zoneOfStability - kLooseDwellMargin};
    if (const JointStop* stop = climb_.getStop())
      if (stop->params().lower < levels.back()) levels.push_back(stop->params().lower);
    dp->setKneeLevels(leg_.getKneeCoordinateIndex(), std::move(levels));
    stepper_ = std::move(dp);
  } else {
    stepper_ = std::make_unique<SimbodyStepper>(system, initial, options, timeLimit_);
  }
  earlyEnd_.emplace(setup, options, climb_, dormandPrince_ != nullptr, numMobilities);
}

void SwingRun::startTrajectory() {
  const bool trackEnergy = options_.trackImpactEnergy;
  previous_ = readStepEnd(leg_, stepper_->getState(), trackEnergy);
  if (const JointStop* stop = climb_.getStop()) {
    std::vector<std::string> causes;
    if (trackEnergy) {
      for (int i = 0; i < std::min(leg_.numKneeWorkParts(), kMaxWorkCauses - 1); ++i)
        causes.push_back(leg_.getKneeWorkPartName(i));
      if (!thighMotion_) causes.push_back("hip drive");
    }
    impacts_.emplace(stop->params().lower, std::move(causes));
  }
  // Room for a typical swing plus its settle dwell, so samples rarely reallocate.
  constexpr double kTypicalDuration = 0.8;  // s
  SwingTrajectory& tr = result_.trajectory;
  const std::size_t capacity =
      static_cast<std::size_t>(std::min(timeLimit_, kTypicalDuration) / options_.sampleInterval) + 2;
  for (auto* v : tr.columns()) v->reserve(capacity);
  // The first sample, at toe-off.
  appendSample(tr, geometry_, hipHeight_, 0.0, previous_.hip, previous_.knee, previous_.hipRate, previous_.kneeRate,
               previous_.hipMoment, previous_.kneeMoment);
  nextSample_ = options_.sampleInterval;
  thighPeak_ = previous_.hip;
}

bool SwingRun::takeStep() {
  bool more;
  try {
    more = stepper_->step(timeLimit_);
  } catch (const std::exception& e) {
    throw errors_.integratorFailed(stepper_->getState(), e);
  }
  const State& s = stepper_->getState();
  const int realizations = stepper_->getNumRealizations();
  const RunBudget::Spent spent = budget_.calcSpent(realizations);
  if (spent != RunBudget::Spent::kNone) throw errors_.overBudget(spent, realizations, s);
  return more;
}

void SwingRun::recordStep(const StepEnd& now, const State& s) {
  if (!std::isfinite(now.hip) || !std::isfinite(now.knee)) throw errors_.diverged(s);
  if (const auto passed = findKneeRisingAbove(previous_, now, kKneeFlexionLimit))
    throw errors_.kneeLeftRange(s, *passed);
  if (!options_.simbodyEvents) handleStepEvents(previous_, now, rule_, log_);
  log_.confirmUntil(now.t);
  if (impacts_) impacts_->onStep(previous_, now);
  if (now.t > previous_.t)
    appendSamples(previous_, now, nextSample_, options_.sampleInterval, geometry_, hipHeight_, result_.trajectory);
  // The hip stop is soft (Hunt-Crossley): a thigh far past it means the inputs are wrong,
  // and a swing "ending" out there would look like a result.
  constexpr double kHipRangeSlack = 2 * kDegToRad;  // rad; plausible hip moments press the stop far less
  if (!thighMotion_ &&
      (now.hip < p_.hipRange.minFlexion - kHipRangeSlack || now.hip > p_.hipRange.maxFlexion + kHipRangeSlack))
    throw errors_.hipLeftRange(s);
  thighPeak_ = std::max(thighPeak_, now.hip);
  if (leg_.hasSocket()) {
    if (!result_.socketPeak) result_.socketPeak.emplace();
    SocketDeflection& peak = *result_.socketPeak;
    peak.piston = std::max(peak.piston, std::abs(now.socket.piston));
    peak.rotation = std::max(peak.rotation, std::abs(now.socket.rotation));
  }
}

void SwingRun::redoLooseDwell(StepEnd& now) {
  const DwellCheckpoint& checkpoint = dwell_.redo(*dormandPrince_);
  log_ = checkpoint.log;
  impacts_ = checkpoint.impacts;
  now = checkpoint.previous;
  for (auto* v : result_.trajectory.columns()) v->resize(checkpoint.samples);
  if (!result_.trajectory.socket.empty()) result_.trajectory.socket.resize(checkpoint.samples);
  nextSample_ = checkpoint.nextSample;
}

TrialEnd SwingRun::calcTrialEnd(const StepEnd& now) const {
  TrialEnd e;
  e.time = now.t;
  e.kneeFlexion = now.knee;
  e.thighFlexion = now.hip;
  e.thighPeak = thighPeak_;
  e.thighTarget = rule_.thighTargetFlexion;
  e.zoneOfStability = rule_.zoneOfStability;
  e.settleDwell = rule_.settleDwell;
  // In the order the swing end rule needs them.
  if (!log_.thighReached) {
    e.unmet = "thigh_target";
  } else if (!log_.peakSeen) {
    e.unmet = "knee_peak";
  } else if (!log_.candidate) {
    e.unmet = "knee_zone";
  } else {
    e.unmet = "settle_dwell";
    e.dwellDone = now.t - log_.candidateTime;
  }
  return e;
}

bool SwingRun::stopsUnended(const StepEnd& now, const State& s, bool more) {
  if (log_.ended) return false;
  const bool cannotEnd = thighFailure_.cannotEnd();
  const bool atLimit = now.t >= timeLimit_ - 1e-12 || !more;
  // A measured trial cut (at heel contact) before the swing ended: a result, not an error.
  const bool trialEnded = atLimit && thighMotion_ && timeLimit_ < rule_.timeLimit;
  if (trialEnded) result_.trialEnd = calcTrialEnd(now);
  if ((atLimit || cannotEnd) && !options_.requireSwingEnd) return true;
  if (cannotEnd)
    throw errors_.cannotEnd(s, thighFailure_.getFinalHipMoment(), thighFailure_.getConstantFrom(),
                            thighFailure_.getShortfall());
  if (trialEnded) return true;
  if (atLimit) throw errors_.didNotEnd(s, log_);
  return false;
}

SwingResult SwingRun::run() {
  log_.add("toe_off", 0.0);
  startTrajectory();
  while (true) {
    const bool more = takeStep();
    const State& s = stepper_->getState();
    StepEnd now = readStepEnd(leg_, s, options_.trackImpactEnergy);
    recordStep(now, s);
    if (dwell_.mustRedo(previous_, now, log_)) redoLooseDwell(now);
    previous_ = now;
    if (log_.candidate && log_.candidateTime != candidateTime_) {
      // The realizations up to the step of the (latest) entry into the zone.
      candidateTime_ = log_.candidateTime;
      result_.realizationsToEnd = stepper_->getNumRealizations();
    }
    if (earlyEnd_->isDecided(now, s, leg_, log_)) log_.endAtCandidate();
    if (log_.ended) {
      result_.endDecidedTime = now.t;
      break;
    }
    // The knee has entered the zone: integrate the dwell loosely from here, keeping what is
    // needed to come back.
    if (dwell_.shouldLoosen(log_))
      dwell_.loosen({log_.candidateTime, log_, impacts_, now, result_.trajectory.size(), nextSample_}, *dormandPrince_);
    thighFailure_.check(now, s, leg_, log_.thighReached);
    if (stopsUnended(now, s, more) || !more) break;
  }
  return finish();
}

SwingResult SwingRun::finish() {
  // Lowest ankle or toe from peak knee flexion (mid-swing) to the swing end; before the
  // peak the foot is still leaving the ground it pushed off from, so without a peak there
  // is no clearance.
  const SwingTrajectory& tr = result_.trajectory;
  std::optional<double> minClearance;
  for (std::size_t k = 0; log_.peak && k < tr.size(); ++k) {
    if (tr.time[k] >= log_.peak->time && tr.time[k] <= (log_.ended ? log_.endTime : previous_.t))
      minClearance = std::min({minClearance.value_or(tr.ankleY[k]), tr.ankleY[k], tr.toeY[k]});
  }
  SwingResult result = std::move(result_);
  if (!options_.recordTrajectory) result.trajectory = SwingTrajectory{};
  result.swingTime = log_.ended ? log_.endTime : std::numeric_limits<double>::quiet_NaN();
  result.peakKneeFlexion = log_.peak;
  result.bounces = log_.bounces;
  result.bounce = log_.bounces > 0;
  result.bounceHeight = log_.bounceHeight;
  if (impacts_) result.impacts = impacts_->finish(previous_);
  std::stable_sort(log_.events.begin(), log_.events.end(),
                   [](const SwingEvent& x, const SwingEvent& y) { return x.time < y.time; });
  result.minToeClearance = minClearance;
  result.events = log_.events;
  result.steps = stepper_->getNumSteps();
  result.realizations = stepper_->getNumRealizations();
  result.looseDwellRetries = dwell_.getRetries();
  return result;
}

}  // namespace swingsim
