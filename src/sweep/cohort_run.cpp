#include "sweep/cohort_run.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "sweep/sweep_assumptions.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double swingTimeOrNaN(const SwingSetup& setup, const SwingOptions& options) {
  try {
    return simulateSwing(setup, options).swingTime;
  } catch (const std::exception&) {
    return kNaN;  // no swing end at this lowering: it cannot be the fastest
  }
}

CohortPredictor makePredictor(const std::string& key, const std::string& what, std::vector<double> values,
                              const std::vector<double>& gain) {
  CohortPredictor p;
  p.key = key;
  p.what = what;
  p.values = std::move(values);
  p.withGain = calcSpearman(p.values, gain);
  return p;
}

}  // namespace

double Cohort::targetSwingTime(std::size_t participant) const {
  return values[participant][findCohortProperty("swing_time_s")];
}

void drawCohortParticipants(Cohort& cohort, const Participant& templ) {
  cohort.values = drawCohort(cohort.distributions, cohort.count, cohort.seed);
  cohort.study.participants.clear();
  for (std::size_t i = 0; i < cohort.values.size(); ++i) {
    Participant p = makeCohortParticipant(templ, cohort.values[i], cohortParticipantName(i, cohort.values.size()));
    p.path = cohort.study.path;
    // The source names the draw and the calibration target, so fingerprints of the
    // participants cover every drawn value.
    char target[64];
    std::snprintf(target, sizeof target, "%.17g", cohort.targetSwingTime(i));
    p.source = "cohort " + cohort.study.name + ", seed " + std::to_string(cohort.seed) + ", participant " +
               std::to_string(i + 1) + " of " + std::to_string(cohort.count) + ", swing time target " + target + " s";
    cohort.study.participants.push_back(std::move(p));
  }
}

double CohortParticipantResult::calcStandardTime() const {
  return !sweep.lowerings.empty() && sweep.lowerings.front() == 0 ? sweep.swingTimes.front() : kNaN;
}

double CohortParticipantResult::calcTimeGained() const { return calcStandardTime() - sweep.calcFastestTime(); }

CohortParticipantResult runCohortParticipant(const Cohort& cohort, std::size_t index) {
  const SweepStudy& study = cohort.study;
  Participant p = study.participants[index];
  const KneeModel& model = findStudyKneeModel(study, p);
  CohortParticipantResult r;
  r.ran = true;
  r.timeScale = kNaN;
  try {
    const CalibrationResult c =
        calibrateHipTimeScale(makeSwingSetup(p, model), cohort.targetSwingTime(index), study.swing);
    r.timeScale = c.timeScale;
    r.calibrationSwings = c.swings;
    r.calibrated = true;
  } catch (const std::exception& e) {  // a target no time scale reaches, or a failed swing
    r.failure = e.what();
    r.calibrationSwings = CalibrationOptions{}.scanPoints;  // the scan that found it ran in full
    return r;
  }
  p.hipMoment.timeScale = r.timeScale;
  SwingOptions options = study.swing;
  options.recordTrajectory = false;
  r.sweep.lowerings = sweepGridLowerings(study, p);
  for (double d : r.sweep.lowerings) r.sweep.swingTimes.push_back(swingTimeOrNaN(makeSwingSetup(p, model, d), options));
  pickBest(r.sweep);
  return r;
}

bool runCohortParticipants(const Cohort& cohort, std::size_t first, std::size_t last,
                           std::vector<CohortParticipantResult>& results, int jobs, const CohortRunControl& control) {
  std::vector<std::size_t> todo;
  for (std::size_t i = first; i < last; ++i)
    if (!results[i].ran) todo.push_back(i);
  volatile bool stop = false;
  std::atomic<long> finished{0};
  auto runOne = [&](int k) {
    const std::size_t i = todo[static_cast<std::size_t>(k)];
    results[i] = runCohortParticipant(cohort, i);
    if (control.stopAfterParticipants >= 0 && ++finished >= control.stopAfterParticipants) stop = true;
  };
  auto progress = [&](int done, int total) {
    if (control.stopFlag && *control.stopFlag) stop = true;
    if (control.progress) control.progress(done, total);
  };
  if (control.stopAfterParticipants == 0) stop = true;
  runParallelJobs(static_cast<int>(todo.size()), jobs, runOne, progress, &stop);
  for (std::size_t i = first; i < last; ++i)
    if (!results[i].ran) return false;
  return true;
}

CohortSummary summarizeCohort(const Cohort& cohort, const std::vector<CohortParticipantResult>& results) {
  CohortSummary s;
  s.participants = cohort.count;
  std::vector<double> timeScales;
  for (const auto& r : results) {
    s.calibrated += r.calibrated ? 1 : 0;
    s.fastestLowering.push_back(r.sweep.calcFastestLowering());
    s.timeGained.push_back(r.calcTimeGained());
    timeScales.push_back(r.calibrated ? r.timeScale : kNaN);
  }
  s.fastestLoweringInterval = calcInterval(s.fastestLowering);
  s.timeGainedInterval = calcInterval(s.timeGained);

  const auto& table = cohortProperties();
  for (std::size_t k = 0; k < table.size(); ++k) {
    std::vector<double> v;
    for (const auto& row : cohort.values) v.push_back(row[k]);
    s.predictors.push_back(makePredictor(table[k].key, table[k].what, v, s.timeGained));
  }
  std::vector<double> body, thigh, shank, foot, inertia;
  for (const Participant& p : cohort.study.participants) {
    body.push_back(p.bodyMass);
    thigh.push_back(p.thigh.mass);
    shank.push_back(p.shank.mass);
    foot.push_back(p.foot.mass);
    inertia.push_back(calcBelowKneeInertia(p, 0));
  }
  s.predictors.push_back(makePredictor("body_mass_kg", "body mass (kg)", body, s.timeGained));
  s.predictors.push_back(makePredictor("thigh_link_mass_kg", "thigh link mass (kg)", thigh, s.timeGained));
  s.predictors.push_back(makePredictor("shank_link_mass_kg", "shank link mass (kg)", shank, s.timeGained));
  s.predictors.push_back(makePredictor("foot_link_mass_kg", "foot link mass (kg)", foot, s.timeGained));
  s.predictors.push_back(
      makePredictor("below_knee_inertia_kgm2", "shank + foot inertia about the knee (kg m^2)", inertia, s.timeGained));
  s.predictors.push_back(makePredictor("hip_time_scale", "calibrated hip time scale", timeScales, s.timeGained));
  std::stable_sort(s.predictors.begin(), s.predictors.end(), [](const CohortPredictor& a, const CohortPredictor& b) {
    const double x = std::isnan(a.withGain.rho) ? -1 : std::fabs(a.withGain.rho);
    const double y = std::isnan(b.withGain.rho) ? -1 : std::fabs(b.withGain.rho);
    return x > y;
  });
  return s;
}

}  // namespace swingsim
