#include "identify/diagnosis_engine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"
#include "identify/candidate_score.h"
#include "identify/record_agreement.h"
#include "numerics/profile_likelihood.h"

namespace swingsim {

namespace {

std::string fmtRatio(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string fmtPercent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

// Which physical bound ends a profile interval, with its value: ", one-sided: cut by its
// upper bound 20"; both: the records exclude no value of the physical range.
std::string describeBoundCut(const ProfileInterval& pi, const PlantFit::FreeParameter& free) {
  const std::string lower = "its lower bound " + fmtRatio(free.lower),
                    upper = "its upper bound " + fmtRatio(free.upper);
  if (pi.lowerAtBound && pi.upperAtBound)
    return ", cut by " + lower + " and " + upper + ": the whole physical range, these records exclude no value of it";
  if (pi.lowerAtBound) return ", one-sided: cut by " + lower;
  if (pi.upperAtBound) return ", one-sided: cut by " + upper;
  return "";
}

// Refits per side of a profile interval after the bracket is found: each is a full refit
// (a swing simulation per record per iteration); 8 halvings pin the end to 1/256 of the last
// bracket step, well inside what a 95 % interval on 1-5 effective samples means.
constexpr int kProfileBisections = 8;

// A base parameter at or within one (inflated) standard error of a physical bound gets a
// profile-likelihood interval (numerics/profile_likelihood.h), one-sided where the bound cuts
// it: the Wald interval would cross the bound (knee scale 0.05, CI -2.3 .. 2.4).
void setProfileInterval(const DiagnosisPlant& plant, const PlantFit& fit, const PlantFit::FreeParameter& free,
                        double se, double nEff, EffectParameter& p) {
  const bool nearBound = free.value - free.lower <= se || free.upper - free.value <= se;
  if (!nearBound || !(se > 0) || !std::isfinite(se) || !(nEff > 0)) return;
  bool unsupported = false;
  const auto rssAt = [&](double v) {
    const std::optional<double> rss = plant.calcHeldParameterRss(*fit.model, free.name, v);
    if (!rss) {
      unsupported = true;
      throw RunError("the plant cannot hold " + free.name);
    }
    return *rss;
  };
  // Steps from a quarter of the standard error: the bracket doubles from there. A value
  // where the model cannot run counts as outside the interval.
  const ProfileInterval pi =
      calcProfileInterval(rssAt, free.value, fit.rss, nEff, free.lower, free.upper, 0.25 * se, kProfileBisections);
  if (unsupported) {
    p.intervalNote = "on or within one standard error of its bound; Wald interval (this plant cannot profile it)";
    return;
  }
  p.lower = pi.lower;
  p.upper = pi.upper;
  p.intervalNote = "profile likelihood (" + std::to_string(pi.evaluations) + " refits)";
  p.intervalNote += describeBoundCut(pi, free);
}

std::vector<EffectParameter> baseIntervals(const DiagnosisPlant& plant, const PlantFit& fit) {
  const double nEff = calcEffectiveSampleSize(fit.likelihoodResidual);
  const double inflate = calcStandardErrorInflation(static_cast<double>(fit.samples), nEff);
  std::vector<EffectParameter> out;
  for (const auto& free : fit.baseParameters) {
    EffectParameter p{free.name, free.value, free.value, free.value, ""};
    setNormalInterval(p, free.standardError * inflate);
    setProfileInterval(plant, fit, free, free.standardError * inflate, nEff, p);
    out.push_back(p);
  }
  return out;
}

std::vector<EffectId> resolveEffects(PlantKind plant, const std::vector<std::string>& requested) {
  // The library's names, and a user's effects the study registered (identify/user_swing_effect.h).
  std::vector<std::string> known = effectNames(plant);
  for (const auto& n : requested) {
    const EffectDescriptor* d = findEffect(plant, n);
    if (d && isUserEffect(d->id)) known.push_back(n);
  }
  const std::vector<std::string> names = resolveCandidates(requested, known);
  std::vector<EffectId> ids;
  for (const auto& n : names) ids.push_back(findEffect(plant, n)->id);
  return ids;
}

// How many records like the training ones would give the closest candidate of the last step
// kPowerTarget power; nullopt if a candidate was significant (the sample size was not the
// limit) or none carries information.
std::optional<PowerAdvice> adviseRecordsForPower(const Diagnosis& out, const EffectSelectionSettings& settings,
                                                 const std::vector<std::string>& heldOutStems) {
  if (out.steps.empty() || out.steps.back().chosen >= 0) return std::nullopt;
  int applicable = 0;
  for (const auto& c : out.steps.back().candidates) {
    if (!c.notApplicable.empty()) continue;
    ++applicable;
    if (c.significant) return std::nullopt;
  }
  const CandidateScore* closest = findClosestCandidate(out.steps.back());
  if (!closest) return std::nullopt;
  PowerAdvice a;
  a.effect = closest->effect;
  a.likelihoodRatio = closest->likelihoodRatio;
  a.dof = std::max(1, closest->dof);
  a.level = settings.alpha / applicable;
  a.recordsNow = static_cast<int>(out.final.trainResidual.size());
  const DiagnosisStep& last = out.steps.back();
  for (std::size_t v = 0; v < closest->validationRmse.size() && v < last.currentValidationRmse.size(); ++v)
    if (!(closest->validationRmse[v] < last.currentValidationRmse[v])) {
      a.lowersHeldOut = false;
      a.heldOutNote += (a.heldOutNote.empty() ? "" : ", ") + fmtRatio(last.currentValidationRmse[v]) + " to " +
                       fmtRatio(closest->validationRmse[v]) + " on " +
                       (v < heldOutStems.size() ? heldOutStems[v] : "held-out record " + std::to_string(v + 1));
    }
  a.records = out.plant == PlantKind::kSweep      ? "participants"
              : out.plant == PlantKind::kCylinder ? "bench records"
                                                  : "swings";
  // The fitted effect's LR is the estimate of its noncentrality on these records.
  a.recordsNeeded = calcRecordsForPower(a.likelihoodRatio / std::max(1, a.recordsNow), a.dof, a.level, kPowerTarget);
  return a;
}

// The power advice for the closest candidate, which the sentence before has named.
std::string describePowerAdvice(const PowerAdvice& a) {
  const std::string at = " at the acceptance rule's level (alpha " + fmtRatio(a.level) + " after Bonferroni)";
  if (!a.lowersHeldOut)
    return " The closest does not lower the held-out error (RMSE " + a.heldOutNote + "): more " + a.records +
           " like these would not make it the missing effect.";
  if (a.recordsNeeded == 0)
    return " No candidate is significant, and the closest has no likelihood gain: more " + a.records +
           " like these would not make it so.";
  if (a.recordsNeeded <= a.recordsNow)
    return " The closest already has " + fmtPercent(100 * kPowerTarget) + " % power" + at +
           " on these records at its fitted size.";
  return " The effective sample size is too small to accept any effect: at its fitted size the closest would need " +
         std::to_string(a.recordsNeeded - a.recordsNow) + " more " + a.records + " like these (" +
         std::to_string(a.recordsNeeded) + " in all, " + std::to_string(a.recordsNow) + " now) for " +
         fmtPercent(100 * kPowerTarget) + " % power" + at + ".";
}

// "name value (95 % CI lower .. upper[; how])" for each parameter of a candidate.
std::string describeCandidateParameters(const CandidateScore& c) {
  std::string out;
  for (const auto& p : c.parameters)
    out += std::string(out.empty() ? "" : ", ") + p.name + " " + fmtRatio(p.value) + " (95 % CI " + fmtRatio(p.lower) +
           " .. " + fmtRatio(p.upper) + (p.intervalNote.empty() ? "" : "; " + p.intervalNote) + ")";
  return out;
}

// What was tried on top of the final model, and the closest candidate, named once.
std::string describeTried(const DiagnosisStep& step, const std::string& unit) {
  std::string tried, silent;
  for (const auto& c : step.candidates) {
    if (!c.notApplicable.empty()) continue;
    std::string& list = c.informative ? tried : silent;
    list += (list.empty() ? "" : ", ") + c.effect;
  }
  if (tried.empty() && silent.empty()) return "";
  std::string out =
      " Tried on top of the final model: " + (tried.empty() ? std::string("none with information") : tried) +
      (silent.empty() ? "" : "; " + std::string(kNoInformation) + ": " + silent) + ".";
  const CandidateScore* closest = findClosestCandidate(step);
  if (!closest) return out;
  double worst = 0;
  for (double v : closest->validationRmse) worst = std::max(worst, v);
  return out + " The closest (largest likelihood ratio on the training records) is " + closest->effect + " (LR " +
         fmtRatio(closest->likelihoodRatio) + "; " + describeCandidateParameters(*closest) +
         "); it leaves a held-out error of " + fmtRatio(worst) + " " + unit + " (largest over the held-out records)." +
         (closest->recordsAgree ? ""
                                : " Refitted on each record alone, its " + closest->agreement +
                                      ": it stands for a law of another shape.");
}

// The verdict: is what remains measurement noise? Noise per record from the study or the
// data; every held-out RMSE within the ratio of its record's noise, and a white residual.
void judgeExplained(const DiagnosisPlant& plant, const EffectSelectionSettings& settings, Diagnosis& out) {
  const std::vector<NoiseEstimate> estimates = plant.estimateRecordNoise();
  out.pooledNoise = poolNoise(estimates);
  out.noiseSource = settings.measurementNoise > 0 ? "set in the study" : "estimated from the data";
  for (const auto& e : estimates)
    out.recordNoise.push_back(settings.measurementNoise > 0 ? settings.measurementNoise : e.sigma);
  const std::vector<std::string> stems = plant.validationStems();
  const std::size_t firstValidation = out.recordNoise.size() - stems.size();
  std::string worstStem;
  double worstRatio = 0, worstLimit = settings.explainedNoiseRatio, worstExcess = 0;
  for (std::size_t v = 0; v < stems.size() && v < out.final.validationRmse.size(); ++v) {
    const double noise = out.recordNoise[firstValidation + v];
    double ratio = noise > 0 ? out.final.validationRmse[v] / noise : std::numeric_limits<double>::infinity();
    if (std::isnan(ratio)) ratio = std::numeric_limits<double>::infinity();  // a NaN error never passes
    // A record of few samples (the sweep's 2-4 rows a participant): the RMS of k noise
    // samples alone exceeds 1.2 x their SD often; the limit is then the 99 % point of that
    // RMS, sqrt(chi^2_0.99(k) / k). Records of 60 samples or more keep the study's ratio.
    const double k = static_cast<double>(estimates[firstValidation + v].samples);
    const double limit =
        std::max(settings.explainedNoiseRatio, k > 0 ? std::sqrt(calcChiSquaredQuantile(0.99, k) / k) : 0.0);
    if (ratio / limit > worstExcess || worstStem.empty()) {
      worstExcess = ratio / limit;
      worstRatio = ratio;
      worstLimit = limit;
      worstStem = stems[v];
    }
  }
  const bool atNoise = worstExcess <= 1.0;
  out.explained = atNoise && out.finalResidualWhite;
  if (out.explained) {
    out.verdict = "explained: every held-out error is within " + fmtRatio(settings.explainedNoiseRatio) +
                  " x the measurement noise" +
                  (worstLimit > settings.explainedNoiseRatio
                       ? ", or the 99 % point of the RMS of a record's few samples of noise,"
                       : "") +
                  " (worst " + worstStem + ", " + fmtRatio(worstRatio) + " x" +
                  (worstLimit > settings.explainedNoiseRatio ? " of a limit " + fmtRatio(worstLimit) + " x" : "") +
                  ") and the final residual is white";
    return;
  }
  // Where the remaining error sits, in phases and in the state space.
  const double nEffRatio =
      calcEffectiveSampleSize(out.final.likelihoodResidual) / static_cast<double>(out.final.samples);
  Comparison training = plant.compare(*out.final.model);
  training.records.erase(std::remove_if(training.records.begin(), training.records.end(),
                                        [](const RecordComparison& r) { return !r.training; }),
                         training.records.end());
  out.structureNote = describeResidualStructure(training, nEffRatio);
  out.missing = plant.calcMissing(*out.final.model);
  if (!out.missing) out.missingForce = plant.calcMissingForce(*out.final.model);
  out.missingNote = out.missing        ? describeMissingMoment(*out.missing)
                    : out.missingForce ? describeMissingForce(out.missingForce->regions)
                                       : "";
  out.verdict = "NOT explained: ";
  if (!atNoise)
    out.verdict += "the held-out error on " + worstStem + " is " + fmtRatio(worstRatio) + " x the measurement noise (" +
                   std::string(settings.measurementNoise > 0 ? "set in the study" : "estimated from the data") +
                   "; limit " + fmtRatio(worstLimit) + " x)";
  if (!atNoise && !out.finalResidualWhite) out.verdict += ", and ";
  if (!out.finalResidualWhite)
    out.verdict += out.finalWhiteness.computed
                       ? "the final residual is not white"
                       : "whether the final residual is white cannot be told (" + out.finalWhiteness.note + ")";
  out.verdict += ". What remains: " + (out.missingNote.empty() ? "" : out.missingNote + "; ") + out.structureNote + ".";
  if (!out.steps.empty()) out.verdict += describeTried(out.steps.back(), training.unit);
  out.power = adviseRecordsForPower(out, settings, plant.validationStems());
  if (out.power) out.verdict += describePowerAdvice(*out.power);
  out.verdict +=
      " The library has no effect that explains it; nothing is claimed for it and no model is saved as solved.";
}

}  // namespace

namespace {

// "" unless a parameter of `added` correlates beyond kConfoundLimit with a parameter of
// another effect in `fit` (withBase: or of the base model's own, such as the swing's knee
// model scale); else a sentence naming both and what would separate them.
std::string describeConfound(const PlantFit& fit, EffectId added, bool withBase) {
  const EffectDescriptor& a = describeEffect(added);
  const auto& names = fit.parameterNames;
  auto effectOf = [](const std::string& parameter) { return parameter.substr(0, parameter.find('.')); };
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (effectOf(names[i]) != a.name) continue;
    for (std::size_t j = 0; j < names.size(); ++j) {
      const bool base = names[j].find('.') == std::string::npos;
      if (effectOf(names[j]) == a.name || base != withBase) continue;
      const double r = fit.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      if (!(std::abs(r) > kConfoundLimit)) continue;
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3f", r);
      if (base)
        return a.name + ": its " + names[i] + " moves with the base model's " + names[j] + " (correlation " + buf +
               " of the fitted parameters): the split between them is uncertain. What would separate them: " +
               a.separatedBy + ".";
      const EffectDescriptor* b = findEffect(a.plant, effectOf(names[j]));
      return a.name + " was not added: its " + names[i] + " moves with " + names[j] + " (correlation " + buf +
             " of the fitted parameters), so these data cannot tell " + a.name + " from " +
             (b ? b->name : effectOf(names[j])) + ". What would separate them: " + a.separatedBy +
             (b ? "; for " + b->name + ": " + b->separatedBy : std::string()) + ".";
    }
  }
  return "";
}

// Scores every candidate of step `stepNo` on top of `current` into `step` (their best fits
// into `best`), reporting progress; returns how many were applicable.
int scoreCandidates(const DiagnosisPlant& plant, const PlantFit& current, const std::vector<EffectId>& ids,
                    const EffectSelectionSettings& settings, const DiagnosisProgress& progress, int stepNo,
                    DiagnosisStep& step, std::vector<PlantFit>& best) {
  int applicable = 0;
  const int total = static_cast<int>(ids.size());
  if (progress) progress(stepNo, 0, total);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    step.candidates.push_back(scoreCandidate(plant, current, ids[i], settings, &best[i]));
    if (step.candidates.back().notApplicable.empty()) ++applicable;
    if (progress) progress(stepNo, static_cast<int>(i) + 1, total);
  }
  return applicable;
}

// The acceptance rule's choice, then the record-agreement rule on the chosen candidate only
// (a refit per record): one that fails it is rejected and the rule chooses again among the
// rest. Its level is the likelihood-ratio test's, Bonferroni over the `applicable`
// candidates scored: one family-wise decision per step. Returns the index chosen, or -1.
int chooseAgreeingCandidate(const DiagnosisPlant& plant, const std::vector<PlantFit>& best, double alpha,
                            int applicable, const std::vector<EffectScore*>& scores, DiagnosisStep& step) {
  int chosen = applyAcceptanceRule(scores, alpha);
  while (chosen >= 0) {
    CandidateScore& c = step.candidates[static_cast<std::size_t>(chosen)];
    const RecordAgreement agreement =
        checkRecordAgreement(plant, best[static_cast<std::size_t>(chosen)], c.id, alpha / std::max(1, applicable));
    c.agreement = agreement.describe();
    if (agreement.agrees) break;
    c.recordsAgree = false;
    chosen = applyAcceptanceRule(scores, alpha);
  }
  return chosen;
}

}  // namespace

const CandidateScore* findClosestCandidate(const DiagnosisStep& step) {
  const CandidateScore* closest = nullptr;
  for (const auto& c : step.candidates)
    if (c.notApplicable.empty() && c.informative && (!closest || c.likelihoodRatio > closest->likelihoodRatio))
      closest = &c;
  return closest;
}

Diagnosis runDiagnosis(const DiagnosisPlant& plant, const EffectSelectionSettings& settings,
                       const DiagnosisProgress& progress) {
  if (plant.validationStems().empty())
    throw InputError("diagnose: the acceptance rule needs at least one validation file (validate:)");
  const std::vector<EffectId> ids = resolveEffects(plant.kind(), settings.candidates);
  std::vector<std::string> names;
  for (EffectId id : ids) names.push_back(describeEffect(id).name);

  Diagnosis out;
  out.plant = plant.kind();
  out.warnings = plant.warnings();
  PlantFit current = plant.fit(*plant.baseModel());
  out.baseline = current;
  out.baselineParameters = baseIntervals(plant, current);
  out.baselineWhiteness =
      calcWhitenessTest(plant.whitenessResidual(current.likelihoodResidual), settings.whitenessLags);

  for (int stepNo = 0; stepNo < settings.maxEffects; ++stepNo) {
    DiagnosisStep step;
    step.currentTrainRmse = current.trainRmse;
    step.currentValidationRmse = current.validationRmse;
    std::vector<PlantFit> best(ids.size());
    const int applicable = scoreCandidates(plant, current, ids, settings, progress, stepNo, step, best);
    std::vector<EffectScore*> scores;
    for (auto& c : step.candidates) scores.push_back(&c);
    step.chosen = applicable == 0 ? -1 : chooseAgreeingCandidate(plant, best, settings.alpha, applicable, scores, step);
    if (step.chosen < 0) {
      out.steps.push_back(step);
      break;
    }
    const auto chosen = static_cast<std::size_t>(step.chosen);
    step.candidates[chosen].added = true;
    step.group = findAmbiguityGroup(scores, names, chosen, settings.alpha, [&](std::size_t j) -> std::optional<double> {
      PlantFit joint;
      try {
        joint = plant.fit(*plant.combine(*best[j].model, *best[chosen].model, ids[chosen]));
      } catch (const RunError&) {
        return std::nullopt;
      }
      return calcLrTest(best[j].rss, joint.rss, joint.likelihoodResidual,
                        std::max(1, describeEffect(ids[chosen]).degreesOfFreedom()))
          .p;
    });
    // A confound: the chosen effect's parameter moves in lockstep (|r| > kConfoundLimit) with
    // one already in the model. The data cannot tell them apart, so it is not stacked on top;
    // the report names the pair and the measurement that would separate them.
    if (const std::string withBase = describeConfound(best[chosen], ids[chosen], true); !withBase.empty())
      out.warnings.push_back(withBase);
    if (const std::string confound = describeConfound(best[chosen], ids[chosen], false); !confound.empty()) {
      step.candidates[chosen].added = false;
      step.chosen = -1;
      out.confounds.push_back(confound);
      out.steps.push_back(step);
      break;
    }
    current = plant.refitAccepted(best[chosen], ids[chosen]);
    out.accepted.push_back(names[chosen]);
    out.acceptedScores.push_back(step.candidates[chosen]);
    recordAmbiguity(
        step.group, [&](const std::string& e) { return findEffect(plant.kind(), e)->separatedBy; }, out.ambiguous,
        out.ambiguityAdvice);
    out.steps.push_back(step);
  }
  out.final = current;
  // What the final fit says of itself (stopped at its budget, a parameter on its physical
  // bound, a constant the training data do not determine) is part of the result.
  for (const std::string& note : current.notes)
    if (std::find(out.warnings.begin(), out.warnings.end(), note) == out.warnings.end())
      out.warnings.push_back("final fit: " + note);
  out.finalParameters = baseIntervals(plant, current);
  out.finalWhiteness = calcWhitenessTest(plant.whitenessResidual(current.likelihoodResidual), settings.whitenessLags);
  // A whiteness test that cannot be computed is "cannot tell", never a pass.
  out.whitenessLevel = settings.alpha;
  out.finalResidualWhite = judgeWhiteness(out.finalWhiteness, out.whitenessLevel) == Whiteness::kWhite;
  judgeExplained(plant, settings, out);
  return out;
}

BaselineComparison compareBaseline(const DiagnosisPlant& plant, int whitenessLags) {
  BaselineComparison out;
  out.fit = plant.fit(*plant.baseModel());
  out.parameters = baseIntervals(plant, out.fit);
  out.comparison = plant.compare(*out.fit.model);
  out.whiteness = calcWhitenessTest(plant.whitenessResidual(out.fit.likelihoodResidual), whitenessLags);
  return out;
}

}  // namespace swingsim
