#include "identify/record_agreement.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/text_format.h"
#include "identify/candidate_score.h"
#include "numerics/residual_analysis.h"

namespace swingsim {

namespace {

const double kZ95 = calcNormalQuantile(0.975);

// Cochran's Q of estimates with standard errors: sum w (x - mean_w)^2, w = 1 / se^2, and its
// chi^2(m - 1) tail; NaN with fewer than two.
double calcHeterogeneityP(const std::vector<double>& values, const std::vector<double>& errors) {
  if (values.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double sw = 0, swx = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double w = 1.0 / (errors[i] * errors[i]);
    sw += w;
    swx += w * values[i];
  }
  const double mean = swx / sw;
  double q = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    q += (values[i] - mean) * (values[i] - mean) / (errors[i] * errors[i]);
  return calcChiSquaredSurvival(q, static_cast<double>(values.size() - 1));
}

}  // namespace

std::string RecordAgreement::describe() const {
  if (!tested) return "";
  std::string out = parameter + (agrees ? " agrees between records" : " differs between records") +
                    " (heterogeneity p " + fmt("%.2g", pAdjusted) + ", level " + fmt("%.2g", level) + "):";
  for (std::size_t i = 0; i < estimates.size(); ++i)
    out += fmt(" %s %.4g (%.4g .. %.4g)", estimates[i].stem.c_str(), estimates[i].value, estimates[i].lower,
               estimates[i].upper) +
           (i + 1 < estimates.size() ? ";" : "");
  return out;
}

RecordAgreement checkRecordAgreement(const DiagnosisPlant& plant, const PlantFit& pooled, EffectId id, double alpha) {
  RecordAgreement out;
  out.level = alpha;
  const std::vector<std::string> stems = plant.recordStems();
  const int fitted = describeEffect(id).fittedParameters;
  if (stems.size() < 2 || fitted <= 0) return out;
  // Per record: the effect's fitted values and their inflated standard errors.
  std::vector<std::vector<double>> values(stems.size()), errors(stems.size());
  for (std::size_t r = 0; r < stems.size(); ++r) {
    const auto one = plant.withOnlyRecord(r);
    if (!one) return out;
    try {
      const PlantFit f = one->fit(*pooled.model);
      values[r] = one->effectValues(*f.model, id);
      if (const auto* se = findErrors(f, id)) {
        const double inflate =
            calcStandardErrorInflation(static_cast<double>(f.samples), calcEffectiveSampleSize(f.likelihoodResidual));
        for (double e : *se) errors[r].push_back(e * inflate);
      }
    } catch (const RunError&) {
      values[r].clear();
    }
  }
  const std::vector<std::string> names = describeEffect(id).parameters;
  for (int k = 0; k < fitted; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    std::vector<double> x, se;
    std::vector<RecordEstimate> estimates;
    for (std::size_t r = 0; r < stems.size(); ++r) {
      if (ku >= values[r].size() || ku >= errors[r].size()) continue;
      const double e = errors[r][ku];
      if (!(e > 0) || !std::isfinite(e) || !std::isfinite(values[r][ku])) continue;
      x.push_back(values[r][ku]);
      se.push_back(e);
      estimates.push_back({stems[r], values[r][ku], values[r][ku] - kZ95 * e, values[r][ku] + kZ95 * e});
    }
    const double p = calcHeterogeneityP(x, se);
    if (!std::isfinite(p)) continue;
    const double adjusted = std::min(1.0, p * fitted);
    if (!out.tested || adjusted < out.pAdjusted) {
      out.tested = true;
      out.pAdjusted = adjusted;
      out.parameter = ku < names.size() ? names[ku] : "parameter " + std::to_string(k);
      out.estimates = estimates;
    }
  }
  out.agrees = !out.tested || out.pAdjusted >= alpha;
  return out;
}

}  // namespace swingsim
