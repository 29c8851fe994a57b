#include "identify/sweep_plant.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "core/input_error.h"
#include "numerics/bounded_least_squares.h"
#include "numerics/metrics.h"
#include "sweep/sweep_uncertainty.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMs = 1000.0;               // ms per s: the compared quantity is in ms
constexpr double kPhaseSplitLowering = 0.1;  // m: the two "phases" of a sweep, near and far

// The phase of a row at `lowering` (m): 0 up to kPhaseSplitLowering, 1 beyond (phaseNames).
int loweringPhase(double lowering) { return lowering > kPhaseSplitLowering ? 1 : 0; }

// Calibration of a time scale inside a fit: 1 us, far below a row's standard error (10-25 ms)
// and below what a difference step of a shared value moves the swing time (0.1-1 ms).
constexpr double kCalibrationTolerance = 1e-6;  // s

// Effects with a continuously fitted value (not the COM rule's choice), in model order.
std::vector<std::size_t> fittedEffects(const SweepModelParams& p) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < p.effects.size(); ++k)
    if (describeEffect(p.effects[k].first).fittedParameters > 0) out.push_back(k);
  return out;
}

}  // namespace

SweepPlant::SweepPlant(const SweepStudy& study, const std::vector<MeasuredSwingTime>& rows,
                       const std::string& measuredPath, double defaultStandardError, int jobs)
    : measuredPath_(measuredPath), jobs_(jobs) {
  std::vector<bool> hasStandard;
  participants_ = assignSweepRows(study, rows, measuredPath, defaultStandardError, hasStandard, notes_);
  for (std::size_t i = 0; i < participants_.size(); ++i) {
    SweepParticipantRows& p = participants_[i];
    const std::string& name = p.nominal.participant.name;
    whitenSweepRows(p, hasStandard[i]);
    if (!hasStandard[i] && p.lowered.empty()) {
      p.inModel = false;
      p.outside = "not measured (no row in " + measuredPath + ")";
    } else if (!hasStandard[i]) {
      throw InputError(measuredPath + ": participant " + name +
                       ": expected a row at lowering_m 0 (the standard "
                       "location its hip time scale is calibrated to) (got rows only at lowered axes)");
    } else if (p.lowered.empty()) {
      p.inModel = false;
      p.outside = "no lowered row to compare";
    } else {
      // Inside the model when some time scale in the calibration range reaches its
      // standard-location time and the calibrated base model ends a swing at every row.
      try {
        const SwingSetup setup = makeSwingSetup(p.nominal.participant,
                                                std::make_shared<const KneeLawSum>(makeSweepVariantKnee(p.nominal)), 0);
        const CalibrationResult cal = calibrateHipTimeScale(setup, p.standard.swingTime, p.nominal.swing);
        (void)predict(i, SweepModelParams{}, cal.timeScale);
      } catch (const RunError& e) {
        p.inModel = false;
        p.outside = e.what();
      }
    }
    if (p.inModel) {
      inModel_.push_back(i);
    } else {
      notes_.push_back(name + " is outside the model and takes no part in the fits or folds: " + p.outside);
    }
  }
  if (inModel_.size() < 2) {
    std::string why;
    for (const auto& note : notes_) why += (why.empty() ? ": " : "; ") + note;
    throw RunError(
        "diagnose: the sweep plant needs at least two participants inside the model (leave one participant "
        "out trains on the others); " +
        std::to_string(inModel_.size()) + " of " + std::to_string(participants_.size()) + " are" + why);
  }
}

SweepPlant::Prediction SweepPlant::predict(std::size_t i, const SweepModelParams& params, double startScale,
                                           const std::vector<double>* lowerings) const {
  const SweepParticipantRows& rows = participants_[i];
  const SweepVariant v = applySweepEffects(rows.nominal, params);
  std::shared_ptr<const KneeLawSum> knee;
  try {
    knee = std::make_shared<const KneeLawSum>(makeSweepVariantKnee(v));
  } catch (const std::invalid_argument& e) {
    throw RunError(v.participant.name + ": the shared values make an unusable knee law: " + e.what());
  }
  CalibrationOptions options;
  options.timeTolerance = kCalibrationTolerance;
  const SwingSetup standard = makeSwingSetup(calcSweepSwingParticipant(v, params, 0), knee, 0);
  const CalibrationResult cal =
      calibrateHipTimeScaleNear(standard, rows.standard.swingTime, startScale, v.swing, options);
  Prediction out;
  out.timeScale = cal.timeScale;
  out.swingTimePerScale = cal.swingTimePerScale;
  SweepVariant calibrated = v;
  calibrated.participant.hipMoment.timeScale = cal.timeScale;
  SwingOptions swing = v.swing;
  swing.recordTrajectory = false;
  std::vector<double> rowLowerings;
  for (const auto& row : rows.lowered) rowLowerings.push_back(row.lowering);
  for (double d : lowerings ? *lowerings : rowLowerings) {
    const SwingSetup setup = makeSwingSetup(calcSweepSwingParticipant(calibrated, params, d), knee, d);
    double t = kNaN;
    try {
      t = simulateSwing(setup, swing).swingTime;
    } catch (const RunError&) {
    }
    if (!std::isfinite(t) && !lowerings)
      throw RunError(v.participant.name + ": no swing end at " + formatNumber(d * kMs) + " mm with these values");
    out.times.push_back(t);
  }
  return out;
}

std::vector<double> SweepPlant::predictSwingTimes(std::size_t i, const SweepModelParams& params,
                                                  const std::vector<double>& lowerings, double* timeScale) const {
  const Prediction p = predict(i, params, participants_[i].nominal.participant.hipMoment.timeScale, &lowerings);
  if (timeScale) *timeScale = p.timeScale;
  return p.times;
}

std::vector<SweepPlant::Prediction> SweepPlant::predictAll(const std::vector<std::size_t>& subset,
                                                           const SweepModelParams& params) const {
  std::vector<Prediction> out(subset.size());
  std::vector<std::string> errors(subset.size());
  runParallelJobs(static_cast<int>(subset.size()), jobs_, [&](int k) {
    const std::size_t i = subset[static_cast<std::size_t>(k)];
    // Start each calibration from the model's last scale for this participant.
    double start = participants_[i].nominal.participant.hipMoment.timeScale;
    const auto pos = std::find(inModel_.begin(), inModel_.end(), i) - inModel_.begin();
    if (static_cast<std::size_t>(pos) < params.timeScales.size())
      start = params.timeScales[static_cast<std::size_t>(pos)];
    try {
      out[static_cast<std::size_t>(k)] = predict(i, params, start);
    } catch (const std::exception& e) {
      errors[static_cast<std::size_t>(k)] = e.what();
    }
  });
  for (const auto& e : errors)
    if (!e.empty()) throw RunError(e);
  return out;
}

std::vector<double> SweepPlant::standardized(std::size_t i, const Prediction& p) const {
  const SweepParticipantRows& rows = participants_[i];
  Eigen::VectorXd r(static_cast<Eigen::Index>(rows.lowered.size()));
  for (std::size_t k = 0; k < rows.lowered.size(); ++k)
    r[static_cast<Eigen::Index>(k)] = rows.lowered[k].swingTime - p.times[k];
  const Eigen::VectorXd z = rows.whitening * r;
  return std::vector<double>(z.data(), z.data() + z.size());
}

SweepPlant::SubsetFit SweepPlant::fitSubset(const SweepModelParams& model,
                                            const std::vector<std::size_t>& subset) const {
  SubsetFit out;
  out.params = model;
  const std::vector<std::size_t> free = fittedEffects(model);
  if (free.empty()) {
    out.predictions = predictAll(subset, model);
    return out;
  }
  std::vector<BoundedParameter> parameters;
  for (std::size_t k : free) {
    const SweepEffectLaw& law = findSweepEffectLaw(model.effects[k].first);
    BoundedParameter b;
    b.name = describeEffect(law.id()).name;
    b.start = std::clamp(model.effects[k].second, law.lower, law.upper);
    b.lower = law.lower;
    b.upper = law.upper;
    b.logScale = law.logScale;
    b.typical = law.upper - law.lower;
    parameters.push_back(b);
  }
  const auto withValues = [&](const Eigen::VectorXd& x) {
    SweepModelParams p = model;
    for (std::size_t j = 0; j < free.size(); ++j) p.effects[free[j]].second = x[static_cast<Eigen::Index>(j)];
    return p;
  };
  const auto residual = [&](const Eigen::VectorXd& x) {
    const SweepModelParams p = withValues(x);
    const std::vector<Prediction> pred = predictAll(subset, p);
    std::vector<double> r;
    for (std::size_t s = 0; s < subset.size(); ++s) {
      const auto z = standardized(subset[s], pred[s]);
      r.insert(r.end(), z.begin(), z.end());
    }
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())));
  };
  BoundedFitSettings settings;
  // Steps of 0.1 % of a value's range move a swing time by 0.05-1 ms, far above the 1 us
  // calibration tolerance; central differences, since a swing time is smooth but not
  // quadratic in most values.
  settings.differenceStep = 1e-3;
  settings.centralDifferences = true;
  settings.maxIterations = 25;
  settings.functionTolerance = 1e-6;
  settings.parameterTolerance = 1e-5;
  const BoundedFitResult fit = solveBoundedLeastSquares(residual, parameters, settings);
  out.params = withValues(fit.x);
  out.predictions = predictAll(subset, out.params);
  out.covariance = fit.covariance;
  if (!fit.converged) out.notes.push_back("the shared values' fit stopped before converging (" + fit.stopReason + ")");
  for (std::size_t j = 0; j < free.size(); ++j)
    if (j < fit.atBound.size() && fit.atBound[j])
      out.notes.push_back(parameters[j].name + " on its physical bound (" +
                          formatNumber(fit.x[static_cast<Eigen::Index>(j)]) + ")");
  return out;
}

PlantModelPtr SweepPlant::baseModel() const { return std::make_shared<SweepModel>(SweepModelParams{}); }

PlantFit SweepPlant::fit(const PlantModel& model) const {
  const SubsetFit full = fitSubset(sweepParams(model), inModel_);
  SweepModelParams fitted = full.params;
  fitted.timeScales.clear();
  for (const auto& p : full.predictions) fitted.timeScales.push_back(p.timeScale);
  PlantFit out;
  out.notes = full.notes;
  double squares = 0;
  std::size_t count = 0;
  for (std::size_t s = 0; s < inModel_.size(); ++s) {
    const std::size_t i = inModel_[s];
    const auto z = standardized(i, full.predictions[s]);
    out.likelihoodResidual.push_back(z);
    std::vector<double> ms;
    std::vector<int> phase;
    for (std::size_t k = 0; k < z.size(); ++k) {
      out.rss += z[k] * z[k];
      ms.push_back((participants_[i].lowered[k].swingTime - full.predictions[s].times[k]) * kMs);
      phase.push_back(loweringPhase(participants_[i].lowered[k].lowering));
      squares += ms.back() * ms.back();
      ++count;
    }
    out.trainResidual.push_back(ms);
    out.trainPhase.push_back(phase);
    // The time scale's standard error from the standard row's: se_T / (dT / d scale).
    const double se = participants_[i].standardRowError / full.predictions[s].swingTimePerScale;
    PlantFit::FreeParameter tau;
    tau.name = "hip_time_scale_" + participants_[i].nominal.participant.name;
    tau.value = full.predictions[s].timeScale;
    tau.standardError = std::isfinite(se) ? std::fabs(se) : 0.0;
    tau.lower = CalibrationOptions{}.minScale;
    tau.upper = CalibrationOptions{}.maxScale;
    out.baseParameters.push_back(tau);
  }
  out.samples = count;
  out.trainRmse = count ? std::sqrt(squares / static_cast<double>(count)) : 0.0;
  // The shared values' standard errors and correlations (reported units).
  const std::vector<std::size_t> free = fittedEffects(fitted);
  for (std::size_t j = 0; j < free.size(); ++j) {
    const EffectId id = fitted.effects[free[j]].first;
    const auto jj = static_cast<Eigen::Index>(j);
    const double se = full.covariance.rows() > jj ? std::sqrt(std::max(0.0, full.covariance(jj, jj))) : kNaN;
    out.effectErrors.push_back({id, {se}});
    out.effectBounds.push_back({id, {{findSweepEffectLaw(id).lower, findSweepEffectLaw(id).upper}}});
    out.parameterNames.push_back(describeEffect(id).name + "." + describeEffect(id).parameters[0]);
  }
  out.correlation =
      Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(free.size()), static_cast<Eigen::Index>(free.size()));
  if (full.covariance.rows() == static_cast<Eigen::Index>(free.size()))
    for (Eigen::Index a = 0; a < full.covariance.rows(); ++a)
      for (Eigen::Index b = 0; b < full.covariance.cols(); ++b)
        if (a != b)
          out.correlation(a, b) = full.covariance(a, b) / std::sqrt(full.covariance(a, a) * full.covariance(b, b));
  addHeldOutFolds(full, free, fitted, sweepParams(model), out);
  out.model = std::make_shared<SweepModel>(fitted);
  return out;
}

double SweepPlant::calcSubsetRss(const std::vector<std::size_t>& subset,
                                 const std::vector<Prediction>& predictions) const {
  double rss = 0;
  for (std::size_t o = 0; o < subset.size() && o < predictions.size(); ++o)
    for (double z : standardized(subset[o], predictions[o])) rss += z * z;
  return rss;
}

SweepPlant::SubsetFit SweepPlant::fitFold(const SweepModelParams& fitted, const SweepModelParams& start,
                                          const std::vector<std::size_t>& others) const {
  // A swing time is far from quadratic in a shared value at large lowerings (on a calibration
  // table, P1's 200 mm row fell from 469 to 385 ms over hip_tempo_lowering -0.2 .. -0.1 and
  // P3's turned back up inside it; docs/diagnosis.md), so the fold's fit from the full fit's
  // values can stay in a local minimum worse than where the candidate started (for a
  // candidate added at its neutral value: the model without it, which it nests). Then it is
  // fitted again from there.
  SubsetFit fold = fitSubset(fitted, others);
  const std::vector<std::size_t> free = fittedEffects(start);
  bool sameStart = true;
  for (std::size_t k : free)
    if (start.effects[k].second != fitted.effects[k].second) sameStart = false;
  if (sameStart) return fold;
  const double foldRss = calcSubsetRss(others, fold.predictions);
  try {
    if (!(calcSubsetRss(others, predictAll(others, start)) < foldRss)) return fold;
    SubsetFit again = fitSubset(start, others);
    if (calcSubsetRss(others, again.predictions) < foldRss) return again;
  } catch (const RunError&) {
    // A swing without an end at the start's values: the fit from the full values stands.
  }
  return fold;
}

void SweepPlant::addHeldOutFolds(const SubsetFit& full, const std::vector<std::size_t>& free, SweepModelParams& fitted,
                                 const SweepModelParams& start, PlantFit& out) const {
  // Leave one participant out: each fold fits the shared values on the others' rows; the
  // held-out participant is calibrated on its own standard row and predicted.
  double heldSquares = 0;
  std::size_t heldCount = 0;
  for (std::size_t s = 0; s < inModel_.size(); ++s) {
    std::vector<std::size_t> others;
    for (std::size_t o = 0; o < inModel_.size(); ++o)
      if (o != s) others.push_back(inModel_[o]);
    SubsetFit fold;
    if (free.empty()) {
      fold.params = fitted;
      for (std::size_t o = 0; o < inModel_.size(); ++o)
        if (o != s) fold.predictions.push_back(full.predictions[o]);
    } else {
      fold = fitFold(fitted, start, others);
    }
    ResidualSegments segments;
    double rss = 0;
    for (std::size_t o = 0; o < others.size(); ++o) {
      segments.push_back(standardized(others[o], fold.predictions[o]));
      for (double z : segments.back()) rss += z * z;
    }
    out.foldRss.push_back(rss);
    out.foldResidual.push_back(segments);
    const std::string& name = participants_[inModel_[s]].nominal.participant.name;
    std::vector<double> errors;
    try {
      const Prediction held = free.empty() ? full.predictions[s] : predictAll({inModel_[s]}, fold.params)[0];
      for (std::size_t k = 0; k < held.times.size(); ++k)
        errors.push_back((participants_[inModel_[s]].lowered[k].swingTime - held.times[k]) * kMs);
    } catch (const RunError& e) {
      // The others' values leave this participant unpredictable: an infinite held-out error,
      // which no acceptance can pass.
      errors.assign(participants_[inModel_[s]].lowered.size(), std::numeric_limits<double>::infinity());
      out.notes.push_back(name + " held out: the values fitted without " + name + " cannot predict it (" + e.what() +
                          ")");
    }
    for (double e : errors) heldSquares += e * e;
    heldCount += errors.size();
    out.validationRmse.push_back(calcRms(errors));
    std::vector<double> values;
    for (const auto& e : fold.params.effects) values.push_back(e.second);
    fitted.heldOutValues.push_back(values);
    for (const auto& n : fold.notes) out.notes.push_back("without " + name + ": " + n);
  }
  out.pooledValidationRmse = heldCount ? std::sqrt(heldSquares / static_cast<double>(heldCount)) : kNaN;
}

std::string SweepPlant::checkApplicable(const PlantModel& model, EffectId effect) const {
  if (describeEffect(effect).plant != PlantKind::kSweep) return "not a sweep effect";
  if (sweepParams(model).has(effect)) return "already in the model";
  const SweepEffectLaw& law = findSweepEffectLaw(effect);
  if (law.assumption.empty()) return "";
  const SweepAssumption& a = findSweepAssumption(law.assumption);
  for (std::size_t i : inModel_) {
    const SweepVariant& v = participants_[i].nominal;
    if (!a.calcRange(v).applicable)
      return v.participant.name + " has no " + a.name + " (a tabulated hip moment has no half-sine shape)";
    if (effect == EffectId::kComRuleProportional && a.read(v) >= 0.5)
      return v.participant.name + " already uses the proportional COM rule";
    if (law.relative && !(a.read(v) > 0)) return v.participant.name + "'s " + a.name + " is 0: nothing to scale";
  }
  return "";
}

PlantModelPtr SweepPlant::addEffect(const PlantModel& model, EffectId effect, double gridValue) const {
  SweepModelParams p = sweepParams(model);
  const SweepEffectLaw& law = findSweepEffectLaw(effect);
  double start = 0;
  if (!describeEffect(effect).grid.empty()) {
    start = gridValue;
  } else if (law.relative) {
    start = 1.0;
  } else if (!law.assumption.empty()) {
    // The mean of the participants' own values: the shared value starts where they are.
    const SweepAssumption& a = findSweepAssumption(law.assumption);
    for (std::size_t i : inModel_) start += a.read(participants_[i].nominal) / static_cast<double>(inModel_.size());
  }
  p.effects.push_back({effect, std::clamp(start, law.lower, law.upper)});
  return std::make_shared<SweepModel>(p);
}

PlantModelPtr SweepPlant::combine(const PlantModel& a, const PlantModel& b, EffectId effectOfB) const {
  SweepModelParams p = sweepParams(a);
  if (!p.has(effectOfB)) p.effects.push_back({effectOfB, sweepParams(b).value(effectOfB)});
  return std::make_shared<SweepModel>(p);
}

std::vector<double> SweepPlant::effectValues(const PlantModel& model, EffectId effect) const {
  return {sweepParams(model).value(effect)};
}

bool SweepPlant::checkPhysical(const PlantModel& model, EffectId effect, std::string& note) const {
  const SweepEffectLaw& law = findSweepEffectLaw(effect);
  const double v = sweepParams(model).value(effect);
  note = "any value in its physical range " + formatNumber(law.lower) + " .. " + formatNumber(law.upper) + " (" +
         law.rangeSource + "): " + formatNumber(v);
  return v >= law.lower && v <= law.upper;
}

std::vector<std::string> SweepPlant::phaseNames(const PlantModel&) const {
  return {"lowered up to 100 mm", "lowered beyond 100 mm"};
}

Comparison SweepPlant::compare(const PlantModel& model) const {
  const SweepModelParams& p = sweepParams(model);
  Comparison c;
  c.quantity = "swing time";
  c.unit = "ms";
  c.phaseNames = phaseNames(model);
  c.decimals = 1;
  const std::vector<Prediction> full = predictAll(inModel_, p);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t s = 0; s < inModel_.size(); ++s) {
      const SweepParticipantRows& rows = participants_[inModel_[s]];
      Prediction pred = full[s];
      if (pass == 1 && s < p.heldOutValues.size()) {
        SweepModelParams held = p;
        for (std::size_t k = 0; k < held.effects.size() && k < p.heldOutValues[s].size(); ++k)
          held.effects[k].second = p.heldOutValues[s][k];
        pred = predictAll({inModel_[s]}, held)[0];
      }
      RecordComparison r;
      r.stem = rows.nominal.participant.name + (pass == 1 ? "-held-out" : "");
      r.training = pass == 0;
      StateVariable lowering{"knee-axis lowering (mm)", "", {}};
      for (std::size_t k = 0; k < rows.lowered.size(); ++k) {
        r.time.push_back(rows.lowered[k].lowering);
        r.measured.push_back(rows.lowered[k].swingTime * kMs);
        r.predicted.push_back(pred.times[k] * kMs);
        r.phase.push_back(loweringPhase(rows.lowered[k].lowering));
        lowering.values.push_back(rows.lowered[k].lowering * kMs);
      }
      r.variables.push_back(lowering);
      finishRecordComparison(r, c.phaseNames.size());
      c.records.push_back(r);
    }
  return c;
}

ResidualSegments SweepPlant::whitenessResidual(const ResidualSegments& likelihoodResidual) const {
  ResidualSegments joined(1);
  for (const auto& segment : likelihoodResidual) joined[0].insert(joined[0].end(), segment.begin(), segment.end());
  return joined;
}

std::vector<std::string> SweepPlant::validationStems() const {
  std::vector<std::string> out;
  for (std::size_t i : inModel_) out.push_back(participants_[i].nominal.participant.name);
  return out;
}

std::vector<NoiseEstimate> SweepPlant::estimateRecordNoise() const {
  std::vector<NoiseEstimate> out;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i : inModel_) {
      const auto& e = participants_[i].standardErrors;
      out.push_back(
          {calcRms(e) * kMs, static_cast<std::size_t>(std::max(1.0, std::floor(participants_[i].effectiveRows)))});
    }
  return out;
}

}  // namespace swingsim
