#include "identify/effect_selection.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace swingsim {

namespace {
// Two-sided 95 % normal quantile, for parameter confidence intervals.
const double kZ95 = calcNormalQuantile(0.975);  // two-sided 95 % normal quantile
}  // namespace

LrTest calcLrTest(double rssSmaller, double rssBigger, const ResidualSegments& biggerResidual, int dof) {
  LrTest t;
  t.nEff = calcEffectiveSampleSize(biggerResidual);
  t.lr = t.nEff * std::log(rssSmaller / std::max(rssBigger, 1e-300));
  t.p = calcChiSquaredSurvival(t.lr, dof);
  t.deltaBic = -t.lr + dof * std::log(t.nEff);
  return t;
}

void applyTestAndValidation(EffectScore& c, const LrTest& t, int dof, const std::vector<double>& currentValidationRmse,
                            const EffectSelectionSettings& settings, double currentPooledValidationRmse) {
  c.dof = dof;
  c.effectiveSamples = t.nEff;
  c.likelihoodRatio = t.lr;
  c.pValue = t.p;
  c.deltaBic = t.deltaBic;
  c.bicImproves = c.deltaBic < 0;
  if (std::isfinite(currentPooledValidationRmse) || std::isfinite(c.pooledValidationRmse)) {
    c.validationImproves =
        c.pooledValidationRmse <= currentPooledValidationRmse * (1.0 - settings.minValidationImprovement);
    return;
  }
  c.validationImproves = !currentValidationRmse.empty() && c.validationRmse.size() == currentValidationRmse.size();
  for (std::size_t v = 0; v < c.validationRmse.size() && v < currentValidationRmse.size(); ++v) {
    if (!(c.validationRmse[v] <= currentValidationRmse[v] * (1.0 - settings.minValidationImprovement)))
      c.validationImproves = false;
  }
}

void applyRecordRule(EffectScore& c, const ResidualSegments& currentTrain, const ResidualSegments& candidateTrain,
                     int dof, double alpha) {
  c.noRecordWorse = true;
  c.trainRecordRmse.clear();
  c.currentTrainRecordRmse.clear();
  c.trainRecordWorsening.clear();
  if (candidateTrain.size() != currentTrain.size()) return;
  const auto sumSquares = [](const std::vector<double>& r) {
    double s = 0;
    for (double v : r) s += v * v;
    return s;
  };
  const double limit = calcChiSquaredQuantile(1.0 - alpha, std::max(1, dof));
  for (std::size_t r = 0; r < candidateTrain.size(); ++r) {
    const double rssCandidate = sumSquares(candidateTrain[r]), rssCurrent = sumSquares(currentTrain[r]);
    const double n = static_cast<double>(candidateTrain[r].size());
    c.trainRecordRmse.push_back(n > 0 ? std::sqrt(rssCandidate / n) : 0.0);
    c.currentTrainRecordRmse.push_back(currentTrain[r].empty() ? 0.0 : std::sqrt(rssCurrent / currentTrain[r].size()));
    const double worsening = candidateTrain[r].empty() || !(rssCurrent > 0)
                                 ? 0.0
                                 : calcEffectiveSampleSize({candidateTrain[r]}) * std::log(rssCandidate / rssCurrent);
    c.trainRecordWorsening.push_back(worsening);
    // One record: the pooled test is the record's own, and the rule says nothing more.
    if (candidateTrain.size() > 1 && !(worsening <= limit)) c.noRecordWorse = false;
  }
}

double calcStandardErrorInflation(double samples, double effectiveSamples) {
  return std::sqrt(samples / std::max(1.0, effectiveSamples));
}

void setNormalInterval(EffectParameter& p, double standardError) {
  p.lower = p.value - kZ95 * standardError;
  p.upper = p.value + kZ95 * standardError;
}

int applyAcceptanceRule(std::vector<EffectScore*> scores, double alpha) {
  int applicable = 0;
  for (const auto* c : scores)
    if (c->notApplicable.empty()) ++applicable;
  int chosen = -1;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    EffectScore& c = *scores[i];
    if (!c.notApplicable.empty()) continue;
    // Bonferroni; a p, BIC or held-out error that is not finite never passes.
    c.pAdjusted = std::isfinite(c.pValue) ? std::min(1.0, c.pValue * applicable) : 1.0;
    c.significant = std::isfinite(c.pValue) && c.pAdjusted < alpha;
    c.bicImproves = c.bicImproves && std::isfinite(c.deltaBic);
    c.accepted = c.informative && c.significant && c.bicImproves && c.validationImproves && c.noRecordWorse &&
                 c.recordsAgree && c.physical;
    if (c.accepted && (chosen < 0 || c.deltaBic < scores[static_cast<std::size_t>(chosen)]->deltaBic))
      chosen = static_cast<int>(i);
  }
  return chosen;
}

std::vector<std::string> findAmbiguityGroup(const std::vector<EffectScore*>& scores,
                                            const std::vector<std::string>& names, std::size_t chosen, double alpha,
                                            const std::function<std::optional<double>(std::size_t)>& pAddingChosenTo) {
  std::vector<std::string> group{names[chosen]};
  for (std::size_t j = 0; j < names.size(); ++j) {
    if (j == chosen || !scores[j]->accepted) continue;
    const std::optional<double> p = pAddingChosenTo(j);
    if (p && *p >= alpha) group.push_back(names[j]);
  }
  return group;
}

void recordAmbiguity(const std::vector<std::string>& group,
                     const std::function<std::string(const std::string&)>& separatedBy,
                     std::vector<std::vector<std::string>>& ambiguous, std::vector<std::string>& advice) {
  if (group.size() < 2) return;
  ambiguous.push_back(group);
  std::vector<std::string> texts;
  for (const auto& g : group) texts.push_back(separatedBy(g));
  advice.push_back(formatAmbiguityAdvice(group, texts));
}

std::string formatAmbiguityAdvice(const std::vector<std::string>& group, const std::vector<std::string>& separatedBy) {
  std::string advice = "the data cannot tell ";
  for (std::size_t g = 0; g < group.size(); ++g)
    advice += (g ? (g + 1 == group.size() ? " from " : ", ") : "") + group[g];
  advice += " apart; to separate them add";
  for (std::size_t g = 0; g < group.size() && g < separatedBy.size(); ++g)
    advice += std::string(g ? ";" : "") + " for " + group[g] + ": " + separatedBy[g];
  return advice;
}

std::vector<std::string> resolveCandidates(const std::vector<std::string>& requested,
                                           const std::vector<std::string>& library) {
  for (const auto& n : requested) {
    if (std::find(library.begin(), library.end(), n) != library.end()) continue;
    std::string all;
    for (const auto& l : library) all += (all.empty() ? "" : ", ") + l;
    throw InputError("candidates: unknown effect '" + n + "' (known: " + all + ")");
  }
  return requested.empty() ? library : requested;
}

}  // namespace swingsim
