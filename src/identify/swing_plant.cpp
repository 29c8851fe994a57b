// The swing plant: its refits (the model's free parameters and every record's toe-off pose),
// its comparisons and its checks. The model along a record is identify/swing_model.h, the
// candidate effects identify/swing_effects.h.
#include "identify/swing_plant.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>

#include "core/input_error.h"
#include "core/units.h"
#include "identify/missing_moment.h"
#include "leg/toe_off_state.h"
#include "numerics/bounded_least_squares.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim {

namespace {

std::string fmt(double v, const char* f = "%.3g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

const SwingModelParams& swingParams(const PlantModel& model) { return plantModelParams<SwingModelParams>(model); }

namespace {

// ---- The free parameters as one vector ------------------------------------------------
// The knee model's scale, then every present effect's values in record order.
struct Slot {
  std::optional<EffectId> effect;  // none: the base model's knee scale
  BoundedParameter bounds;         // start value filled in by the fit
  double reportScale;              // slot value times this = reported value (rad/s -> deg/s)
  std::function<double&(SwingModelParams&)> ref;
};

std::vector<Slot> slotsOf(const SwingEffects& e) {
  std::vector<Slot> s;
  // The knee model's scale: positive, within 20x down and up (log-scaled).
  s.push_back({std::nullopt, {"", 1.0, 0.05, 20.0, true, 1.0}, 1.0, [](SwingModelParams& p) -> double& {
                 return p.kneeModelScale;
               }});
  for (const SwingEffectRecord* record : presentSwingEffectRecords(e))
    for (const auto& slot : record->slots)
      s.push_back({record->id(), slot.bounds, slot.reportScale,
                   [value = slot.value](SwingModelParams& p) -> double& { return value(p.effects); }});
  return s;
}

// The toe-off pose of a record: within 0.5 rad of its first measured sample.
BoundedParameter poseParameter(double measured) { return {"", measured, measured - 0.5, measured + 0.5, false, 0.1}; }

std::vector<int> phasesOf(const std::vector<double>& knee, double zone) {
  std::vector<int> ph(knee.size(), 0);
  const std::size_t peak = static_cast<std::size_t>(std::max_element(knee.begin(), knee.end()) - knee.begin());
  int current = 0;
  for (std::size_t i = 0; i < knee.size(); ++i) {
    if (i > peak && current == 0) current = 1;
    if (current == 1 && knee[i] < zone) current = 2;
    ph[i] = current;
  }
  return ph;
}

// Budgets of the swing refits: generous against the 5-15 iterations a fit takes here, so a
// model that cannot run or a record in the wrong unit stops with a message, not never.
BoundedFitSettings poseFitSettings() {
  BoundedFitSettings s;
  s.maxIterations = 40;
  s.maxSeconds = 60.0;
  s.computeCovariance = false;
  return s;
}
BoundedFitSettings modelFitSettings() {
  BoundedFitSettings s;
  s.maxIterations = 60;
  s.maxSeconds = 300.0;
  return s;
}

// The knee's toe-off rate under the thigh drive: within 20 rad/s of the measured knee's
// first difference (Winter's toe-off knee moves at 6.7 rad/s).
/// The record's knee at toe-off as a measured-thigh swing starts from it (leg/toe_off_state.h).
MeasuredKneeStart measuredKneeStart(const SwingRecord& r) {
  return calcMeasuredKneeStart(r.path, r.time, r.kneeFlexion);
}

BoundedParameter kneeRateParameter(const SwingRecord& r) {
  const double measured = measuredKneeStart(r).kneeFlexionRate;
  return {"", measured, measured - 20.0, measured + 20.0, false, 1.0};
}

double kneeRmse(const SwingRecord& r, const SwingPrediction& p) {
  double s = 0;
  for (std::size_t i = 0; i < r.time.size(); ++i) s += std::pow((r.kneeFlexion[i] - p.kneeFlexion[i]) * kRadToDeg, 2);
  return std::sqrt(s / static_cast<double>(r.time.size()));
}

// The training residuals of a fit, record by record: the knee's (reported, with phases from
// the fitted model's knee) and the likelihood's knee and hip segments; the samples and the
// training RMSE of the knee.
void addTrainingResiduals(const std::vector<SwingRecord>& train, std::size_t rowsPerSample, double zone,
                          const BoundedFitResult& lm, PlantFit& s) {
  double kneeRss = 0;
  std::size_t kneeSamples = 0;
  Eigen::Index row = 0;
  for (std::size_t f = 0; f < train.size(); ++f) {
    std::vector<double> knee, hip;
    for (std::size_t i = 0; i < train[f].time.size(); ++i) {
      knee.push_back(lm.residual[row++]);
      if (rowsPerSample == 2) hip.push_back(lm.residual[row++]);
      kneeRss += knee.back() * knee.back();
    }
    kneeSamples += knee.size();
    s.samples += knee.size() + hip.size();
    // Phases from the fitted model's knee (measured minus residual).
    std::vector<double> modelKnee;
    for (std::size_t i = 0; i < knee.size(); ++i) modelKnee.push_back(train[f].kneeFlexion[i] - knee[i] * kDegToRad);
    s.trainPhase.push_back(phasesOf(modelKnee, zone));
    s.trainResidual.push_back(knee);
    s.likelihoodResidual.push_back(knee);
    if (!hip.empty()) s.likelihoodResidual.push_back(hip);
  }
  s.trainRmse = std::sqrt(kneeRss / static_cast<double>(kneeSamples));
}

// Every free parameter: its standard error (from the fit's covariance, s^2 (J'J)^+), its
// name for the confound check, and a note if it sits on its physical bound. The per-record
// poses after the slots are nuisance parameters and left out.
void addSlotParameters(const std::vector<Slot>& slots, const BoundedFitResult& lm, double kneeModelScale, PlantFit& s) {
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const double se = lm.standardErrors[static_cast<Eigen::Index>(k)] * slots[k].reportScale;
    if (!slots[k].effect) {
      s.baseParameters.push_back(
          {"knee_model_scale", kneeModelScale, se, slots[k].bounds.lower, slots[k].bounds.upper});
      s.parameterNames.push_back("knee_model_scale");
      continue;
    }
    auto it = std::find_if(s.effectErrors.begin(), s.effectErrors.end(),
                           [&](const auto& entry) { return entry.first == *slots[k].effect; });
    if (it == s.effectErrors.end()) {
      it = s.effectErrors.insert(s.effectErrors.end(), {*slots[k].effect, {}});
      s.effectBounds.push_back({*slots[k].effect, {}});
    }
    const auto& d = describeEffect(*slots[k].effect);
    const std::string name = d.name + "." + d.parameters[it->second.size()];  // the effect's parameters in order
    it->second.push_back(se);
    s.effectBounds[static_cast<std::size_t>(it - s.effectErrors.begin())].second.push_back(
        {slots[k].bounds.lower * slots[k].reportScale, slots[k].bounds.upper * slots[k].reportScale});
    s.parameterNames.push_back(name);
    if (lm.atBound[k])
      s.notes.push_back(name + " sits on its physical bound (" +
                        fmt(lm.x[static_cast<Eigen::Index>(k)] * slots[k].reportScale) + ")");
  }
}

}  // namespace

SwingPlant::SwingPlant(SwingBase base, std::vector<SwingRecord> train, std::vector<SwingRecord> validate,
                       double tolerance)
    : base_(std::move(base)), train_(std::move(train)), validate_(std::move(validate)), tolerance_(tolerance) {
  if (train_.empty()) throw InputError("diagnose: no training file (train:)");
  if (base_.drive == SwingDrive::kThighKinematics && base_.participant.socket)
    base_.notes.push_back(
        "the participant has a compliant socket (socket:) and the measured thigh drives the swing, which prescribes "
        "the residual "
        "limb's angle; a lab's thigh markers sit on the socket, so the records' thigh is the socket's and its "
        "rotation is counted twice (docs/socket.md; drive the swing by the hip moment, or leave socket: out)");
  if (base_.drive == SwingDrive::kThighKinematics)
    for (std::size_t i = 0; i < train_.size() + validate_.size(); ++i) {
      const SwingRecord& r = record(i);
      const ThighKinematics kinematics = thighKinematicsOf(r, base_.movingHip);
      thighs_.emplace_back(kinematics);
      hips_.push_back(hipPathOf(base_, kinematics));
    }
}

std::vector<BoundedParameter> SwingPlant::poseParameters(std::size_t i) const {
  const SwingRecord& r = record(i);
  // The fit starts where a measured-thigh simulation does: the record's knee at toe-off.
  if (base_.drive == SwingDrive::kThighKinematics)
    return {kneeRateParameter(r), poseParameter(measuredKneeStart(r).kneeFlexion)};
  return {poseParameter(r.hipFlexion.front()), poseParameter(r.kneeFlexion.front())};
}

void SwingPlant::appendResiduals(const SwingRecord& r, const SwingPrediction& p, Eigen::VectorXd& res,
                                 Eigen::Index& row) const {
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    res[row++] = (r.kneeFlexion[i] - p.kneeFlexion[i]) * kRadToDeg;
    if (rowsPerSample() == 2) res[row++] = (r.hipFlexion[i] - p.hipFlexion[i]) * kRadToDeg;
  }
}

SwingPlant::PoseFit SwingPlant::fitPose(const SwingModelParams& params, std::size_t index) const {
  const SwingRecord& r = record(index);
  const ThighMotion* thigh = thighOf(index);
  ResidualFunction f = [&](const Eigen::VectorXd& x) {
    const SwingPrediction p = predictSwing(base_, params, r, x[0], x[1], tolerance_, thigh, hipOf(index));
    Eigen::VectorXd res(static_cast<Eigen::Index>(rowsPerSample() * r.time.size()));
    Eigen::Index row = 0;
    appendResiduals(r, p, res, row);
    return res;
  };
  const BoundedFitResult lm = solveBoundedLeastSquares(f, poseParameters(index), poseFitSettings());
  PoseFit out;
  out.first = lm.x[0];
  out.knee = lm.x[1];
  out.prediction = predictSwing(base_, params, r, out.first, out.knee, tolerance_, thigh, hipOf(index));
  return out;
}

PlantModelPtr SwingPlant::baseModel() const { return std::make_shared<SwingModel>(SwingModelParams{}); }

namespace {

// A user's effect just switched on (every value at its start) is fitted from two more starts,
// at 10 % and 50 % of each parameter's range: an effect that acts only in part of the state
// (a cushion near extension) can hold a local minimum at zero, where a small value moves the
// swing's ending the wrong way (measured on the independent generator's cushion,
// tests/identify/user_swing_effect_test.cpp). The library's records are fitted from their start.
std::vector<SwingModelParams> moreUserStarts(const SwingModelParams& params) {
  std::vector<SwingModelParams> out;
  for (const SwingEffectRecord* r : presentSwingEffectRecords(params.effects)) {
    if (!isUserEffect(r->id())) continue;
    SwingEffects e = params.effects;
    bool fresh = true;
    for (const auto& slot : r->slots) fresh = fresh && slot.value(e) == slot.bounds.start;
    if (!fresh) continue;
    for (double share : {0.1, 0.5}) {
      SwingModelParams p = params;
      for (const auto& slot : r->slots)
        slot.value(p.effects) = slot.bounds.lower + share * (slot.bounds.upper - slot.bounds.lower);
      out.push_back(p);
    }
  }
  return out;
}

}  // namespace

PlantFit SwingPlant::fit(const PlantModel& model) const {
  PlantFit best = fitWith(model, std::nullopt);
  for (const SwingModelParams& start : moreUserStarts(swingParams(model))) {
    try {
      PlantFit f = fitWith(SwingModel(start), std::nullopt);
      if (f.rss < best.rss) best = std::move(f);
    } catch (const RunError&) {
      // the model cannot run from this start: the fit from the user's start stands
    }
  }
  return best;
}

std::optional<double> SwingPlant::calcHeldParameterRss(const PlantModel& fitted, const std::string& parameter,
                                                       double value) const {
  if (parameter != "knee_model_scale") return std::nullopt;
  return fitWith(fitted, value).rss;
}

PlantFit SwingPlant::fitWith(const PlantModel& model, std::optional<double> heldScale) const {
  SwingModelParams start = swingParams(model);
  std::vector<Slot> slots = slotsOf(start.effects);
  if (heldScale) {  // the knee scale's slot (the first) leaves the free parameters
    start.kneeModelScale = *heldScale;
    slots.erase(slots.begin());
  }
  const Eigen::Index g = static_cast<Eigen::Index>(slots.size());
  std::vector<BoundedParameter> free;
  SwingModelParams p0 = start;
  for (const Slot& slot : slots) {
    BoundedParameter b = slot.bounds;
    b.start = slot.ref(p0);
    free.push_back(b);
  }
  for (std::size_t f = 0; f < train_.size(); ++f)
    for (const BoundedParameter& b : poseParameters(f)) free.push_back(b);
  auto paramsAt = [&](const Eigen::VectorXd& x) {
    SwingModelParams p = start;
    for (Eigen::Index k = 0; k < g; ++k) slots[static_cast<std::size_t>(k)].ref(p) = x[k];
    return p;
  };
  std::size_t rows = 0;
  for (const auto& r : train_) rows += rowsPerSample() * r.time.size();
  ResidualFunction fn = [&](const Eigen::VectorXd& x) {
    const SwingModelParams p = paramsAt(x);
    Eigen::VectorXd res(static_cast<Eigen::Index>(rows));
    Eigen::Index row = 0;
    for (std::size_t f = 0; f < train_.size(); ++f) {
      const auto& r = train_[f];
      const SwingPrediction pr =
          predictSwing(base_, p, r, x[g + 2 * static_cast<Eigen::Index>(f)],
                       x[g + 2 * static_cast<Eigen::Index>(f) + 1], tolerance_, thighOf(f), hipOf(f));
      appendResiduals(r, pr, res, row);
    }
    return res;
  };
  const BoundedFitResult lm = solveBoundedLeastSquares(fn, free, modelFitSettings());
  PlantFit s;
  if (!lm.converged)
    s.notes.push_back("the swing fit stopped before converging after " + std::to_string(lm.iterations) +
                      " iterations (" + lm.stopReason + ")");
  const SwingModelParams fitted = paramsAt(lm.x);
  s.model = std::make_shared<SwingModel>(fitted);
  s.rss = lm.cost;
  addTrainingResiduals(train_, rowsPerSample(), base_.participant.swingEnd.zoneOfStability, lm, s);
  s.correlation = lm.correlation().topLeftCorner(g, g);
  addSlotParameters(slots, lm, fitted.kneeModelScale, s);
  if (!heldScale)  // a profile point needs the training RSS only
    for (std::size_t v = 0; v < validate_.size(); ++v)
      s.validationRmse.push_back(kneeRmse(validate_[v], fitPose(fitted, train_.size() + v).prediction));
  return s;
}

std::string SwingPlant::checkApplicable(const PlantModel& model, EffectId effect) const {
  const SwingEffectRecord& r = findSwingEffectRecord(effect);
  if (swingParams(model).effects.has(effect)) return "already in the model";
  if (base_.drive == SwingDrive::kThighKinematics) return r.notUnderThighDrive;
  return "";
}

PlantModelPtr SwingPlant::addEffect(const PlantModel& model, EffectId effect, double gridValue) const {
  return std::make_shared<SwingModel>(addSwingEffect(swingParams(model), effect, gridValue));
}

PlantModelPtr SwingPlant::combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const {
  SwingModelParams p = swingParams(a);
  p.effects = copySwingEffect(p.effects, swingParams(b).effects, effectOfB);
  return std::make_shared<SwingModel>(p);
}

std::vector<double> SwingPlant::effectValues(const PlantModel& model, EffectId effect) const {
  return swingEffectValues(swingParams(model).effects, effect);
}

bool SwingPlant::checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const {
  return findSwingEffectRecord(effect).isPhysical(swingParams(model).effects, note);
}

Comparison SwingPlant::compare(const PlantModel& model) const {
  const SwingModelParams& params = swingParams(model);
  Comparison out;
  out.quantity = "knee flexion";
  out.unit = "deg";
  out.secondaryQuantity = "hip flexion";
  out.decimals = 2;
  out.phaseNames = swingPhaseNames();
  auto run = [&](std::size_t index) {
    const SwingRecord& r = record(index);
    RecordComparison rc;
    rc.stem = r.stem;
    rc.training = index < train_.size();
    rc.time = r.time;
    const PoseFit pf = fitPose(params, index);
    std::vector<double> measuredHip, predictedHip, knee, rate;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      rc.measured.push_back(r.kneeFlexion[i] * kRadToDeg);
      rc.predicted.push_back(pf.prediction.kneeFlexion[i] * kRadToDeg);
      measuredHip.push_back(r.hipFlexion[i] * kRadToDeg);
      predictedHip.push_back(pf.prediction.hipFlexion[i] * kRadToDeg);
    }
    rc.phase = phasesOf(pf.prediction.kneeFlexion, base_.participant.swingEnd.zoneOfStability);
    rc.secondary = calcErrorMetrics(measuredHip, predictedHip);
    rc.secondaryMeasured = measuredHip;
    rc.secondaryPredicted = predictedHip;
    // The variables are the model's: binning on the measured (noisy) angle would sort the
    // measurement noise into the end bins near the stop and show a mean residual that is not
    // there. The acceleration is by central differences of the model rate (one-sided at the
    // ends); the measured angle is too noisy to differentiate twice.
    for (double v : pf.prediction.kneeFlexionRate) rate.push_back(v * kRadToDeg);
    std::vector<double> accel(rate.size(), 0.0);
    const std::size_t n = std::min(rate.size(), r.time.size());
    for (std::size_t i = 0; n > 1 && i < n; ++i) {
      const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? n - 1 : i + 1;
      accel[i] = (rate[hi] - rate[lo]) / (r.time[hi] - r.time[lo]);
    }
    const std::string band = ", 99 % band (effective sample size)";
    rc.variables = {
        {"knee flexion, model (deg)", "mean knee residual vs model knee flexion" + band, rc.predicted},
        {"knee flexion rate, model (deg/s)", "mean knee residual vs model knee flexion rate" + band, rate},
        {"knee angular acceleration, model (deg/s^2)", "mean knee residual vs model knee acceleration" + band, accel}};
    finishRecordComparison(rc, out.phaseNames.size());
    out.records.push_back(std::move(rc));
  };
  for (std::size_t i = 0; i < train_.size() + validate_.size(); ++i) run(i);
  return out;
}

std::vector<std::string> SwingPlant::validationStems() const {
  std::vector<std::string> stems;
  for (const auto& r : validate_) stems.push_back(r.stem);
  return stems;
}

std::vector<std::string> SwingPlant::recordStems() const {
  std::vector<std::string> stems;
  for (std::size_t i = 0; i < train_.size() + validate_.size(); ++i) stems.push_back(record(i).stem);
  return stems;
}

std::unique_ptr<DiagnosisPlant> SwingPlant::withOnlyRecord(std::size_t index) const {
  if (index >= train_.size() + validate_.size()) return nullptr;
  return std::make_unique<SwingPlant>(base_, std::vector<SwingRecord>{record(index)}, std::vector<SwingRecord>{},
                                      tolerance_);
}

std::string SwingPlant::verify(const PlantModel& model) const {
  const SwingModelParams& params = swingParams(model);
  const Participant participant = applyParticipantEffects(base_.participant, params.effects);
  const auto law = std::make_shared<const KneeLawSum>(makeSwingKneeLaw(base_, params));
  double worst = 0;
  for (std::size_t index = 0; index < train_.size() + validate_.size(); ++index) {
    const SwingRecord& r = record(index);
    const PoseFit pose = fitPose(params, index);
    SwingSetup setup = makeSwingSetup(participant, law);
    setup.participant.initial.kneeFlexion = pose.knee;
    setup.participant.initial.kneeStart = KneeStart::kInitial;  // the fitted pose, not the record's
    if (base_.drive == SwingDrive::kThighKinematics) {
      setup.participant.drive = SwingDrive::kThighKinematics;
      setup.participant.thighKinematics = thighKinematicsOf(r, base_.movingHip);
      setup.participant.initial.kneeFlexionRate = pose.first;
    } else {
      setup.participant.hipMoment = {};
      setup.participant.hipMoment.kind = HipMomentProfile::Kind::kTable;
      setup.participant.hipMoment.times = r.time;
      setup.participant.hipMoment.moments = applyHipDriveEffects(params.effects, r.hipMoment);
      setup.participant.initial.hipFlexion = pose.first;
    }
    // Along the record: the swing need not end inside it (a trial cut at heel contact).
    SwingOptions options = makeSimbodyIntegratorOptions();
    options.requireSwingEnd = false;
    SwingTrajectory tr;
    try {
      tr = simulateSwing(setup, options).trajectory;
    } catch (const RunError& e) {
      return std::string("Simbody check of the final model: not run to the end of ") + r.stem + " (" + e.what() + ")";
    }
    std::size_t j = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
      const double t = r.time[i];
      while (j + 1 < tr.size() && tr.time[j + 1] < t) ++j;
      if (j + 1 >= tr.size()) break;
      const double a = (t - tr.time[j]) / (tr.time[j + 1] - tr.time[j]);
      const double knee = tr.kneeFlexion[j] + a * (tr.kneeFlexion[j + 1] - tr.kneeFlexion[j]);
      worst = std::max(worst, std::abs(knee - pose.prediction.kneeFlexion[i]) * kRadToDeg);
    }
  }
  return "Simbody check of the final model (simulateSwing vs the reference integrator used for the refits): "
         "max knee difference " +
         fmt(worst, "%.2g") + " deg";
}

std::optional<HeldBackComparison> SwingPlant::compareHeldBack(const PlantModel& model) const {
  HeldBackComparison c;
  c.quantity = "knee moment";
  c.unit = "N m";
  for (std::size_t index = 0; index < train_.size() + validate_.size(); ++index) {
    const SwingRecord& r = record(index);
    if (r.kneeMoment.empty()) continue;
    const PoseFit pose = fitPose(swingParams(model), index);
    HeldBackComparison::Record rc;
    rc.stem = r.stem;
    rc.training = index < train_.size();
    // NaN: where the inverse dynamics does not reach; compared where it exists.
    for (std::size_t k = 0; k < r.time.size() && k < pose.prediction.kneeMoment.size(); ++k) {
      if (std::isnan(r.kneeMoment[k])) continue;
      rc.time.push_back(r.time[k]);
      rc.measured.push_back(r.kneeMoment[k]);
      rc.model.push_back(pose.prediction.kneeMoment[k]);
    }
    if (rc.measured.empty()) continue;
    c.records.push_back(std::move(rc));
  }
  if (c.records.empty()) return std::nullopt;
  finishHeldBackComparison(c);
  return c;
}

std::vector<NoiseEstimate> SwingPlant::estimateRecordNoise() const {
  std::vector<NoiseEstimate> out;
  for (const auto* records : {&train_, &validate_})
    for (const auto& r : *records) {
      std::vector<double> kneeDeg;
      for (double v : r.kneeFlexion) kneeDeg.push_back(v * kRadToDeg);
      out.push_back(estimateNoise(r.time, kneeDeg));
    }
  return out;
}

std::optional<MissingMoment> SwingPlant::calcMissing(const PlantModel& model) const {
  const SwingModelParams& params = swingParams(model);
  std::vector<SwingRecord> records;
  std::vector<SwingPrediction> references;
  MissingMoment failed;
  for (std::size_t i = 0; i < train_.size() + validate_.size(); ++i) {
    records.push_back(record(i));
    try {
      references.push_back(fitPose(params, i).prediction);
    } catch (const RunError& e) {
      failed.note = "not computed: the model does not run along " + record(i).stem + " (" + e.what() + ")";
      return failed;
    }
  }
  try {
    return calcMissingMoment(base_, params, records, references);
  } catch (const std::exception& e) {  // a user's expression not finite at a measured state
    failed.note = std::string("not computed: ") + e.what();
    return failed;
  }
}

}  // namespace swingsim
