#include "report/diagnosis_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/text_format.h"
#include "report/diagnosis_coverage.h"
#include "report/overlay_plot.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

const double kZ99 = calcNormalQuantile(0.995);  // two-sided 99 % normal quantile
constexpr int kResidualBins = 12;               // equal-count bins for the binned residual
constexpr double kAcfSeconds = 0.5;             // autocorrelation shown up to this lag, s

// What the metric tables' columns mean, printed under each table.
const char* const kMetricLegend =
    "  ME: the largest |measured - model| (maximum absolute error); RMSE: root mean square of measured - model; "
    "R^2: 1 - residual / measured sum of squares about the mean\n";

// A number with the comparison's decimals.
std::string num(double v, int decimals) { return fmt("%.*f", decimals, v); }

ErrorMetrics pooled(const Comparison& c, bool training) {
  std::vector<double> m, p;
  for (const auto& r : c.records) {
    if (r.training != training) continue;
    m.insert(m.end(), r.measured.begin(), r.measured.end());
    p.insert(p.end(), r.predicted.begin(), r.predicted.end());
  }
  return m.empty() ? ErrorMetrics{} : calcErrorMetrics(m, p);
}

Json metricsJson(const ErrorMetrics& m) { return {{"rmse", m.rmse}, {"r2", m.r2}, {"me", m.maxError}}; }

Json summaryJson(const Comparison& c) {
  Json validation = Json::object();
  for (const auto& r : c.records)
    if (!r.training) validation[r.stem] = metricsJson(r.overall);
  return {{"train", metricsJson(pooled(c, true))}, {"validation", validation}};
}

Json parametersJson(const std::vector<EffectParameter>& parameters) {
  Json values = Json::object(), intervals = Json::object(), notes = Json::object();
  for (const auto& p : parameters) {
    values[p.name] = p.value;
    intervals[p.name] = {p.lower, p.upper};
    if (!p.intervalNote.empty()) notes[p.name] = p.intervalNote;
  }
  Json j = {{"values", values}, {"confidence_intervals", intervals}};
  if (!notes.empty()) j["interval_notes"] = notes;  // how an interval other than Wald's was found
  return j;
}

// The calibration study's measured coverage for each accepted effect it measured.
Json coverageJson(const std::vector<std::string>& accepted) {
  Json out = Json::object();
  for (const auto& a : accepted)
    if (const auto m = findMeasuredCoverage(a)) {
      // A row without seeds (the sweep cannot measure the effect) has no bias or SD: null.
      const auto orNull = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
      out[a] = {{"parameter", m->parameter},
                {"seeds", m->seeds},
                {"named_first", m->named},
                {"scored", m->scored},
                {"covered", m->covered},
                {"bias_percent", orNull(m->biasPercent)},
                {"sd_percent", orNull(m->sdPercent)},
                {"caveat", m->caveat}};
    }
  return out;
}

Json candidateJson(const CandidateScore& c, int step, const std::vector<std::string>& stems) {
  // "passes_rule": the candidate met every part of the acceptance rule; "added": it was the
  // one added to the model in its step (the best of those that passed).
  Json j = {{"effect", c.effect}, {"step", step}, {"passes_rule", c.accepted}, {"added", c.added}};
  if (!c.notApplicable.empty()) {
    j["not_applicable"] = c.notApplicable;
    return j;
  }
  Json validation = Json::object();
  for (std::size_t v = 0; v < stems.size() && v < c.validationRmse.size(); ++v)
    validation[stems[v]] = c.validationRmse[v];
  const Json params = parametersJson(c.parameters);
  j["validation_rmse"] = validation;
  // Cross-validated plants (the sweep): the pooled held-out RMSE the rule uses and each
  // fold's p (the rule needs every fold significant).
  if (std::isfinite(c.pooledValidationRmse)) j["pooled_validation_rmse"] = c.pooledValidationRmse;
  if (!c.foldPValues.empty()) j["fold_p_values"] = c.foldPValues;
  if (std::isfinite(c.allRowsPValue)) j["all_rows_p_value"] = c.allRowsPValue;
  j["train_rmse"] = c.trainRmse;
  j["delta_bic"] = c.deltaBic;
  j["likelihood_ratio"] = c.likelihoodRatio;
  j["p_adjusted"] = c.pAdjusted;
  j["effective_samples"] = c.effectiveSamples;
  j["parameters"] = params["values"];
  j["confidence_intervals"] = params["confidence_intervals"];
  // A candidate whose fit moves no residual has no interval (null) and is never accepted.
  j["informative"] = c.informative;
  if (!c.informative)
    for (const auto& p : c.parameters) j["confidence_intervals"][p.name] = nullptr;
  j["significant"] = c.significant;
  j["bic_improves"] = c.bicImproves;
  j["validation_improves"] = c.validationImproves;
  j["no_training_record_worse"] = c.noRecordWorse;
  if (!c.trainRecordRmse.empty()) {
    j["train_record_rmse"] = c.trainRecordRmse;
    j["current_train_record_rmse"] = c.currentTrainRecordRmse;
  }
  j["records_agree"] = c.recordsAgree;
  if (!c.agreement.empty()) j["record_agreement"] = c.agreement;
  j["physical_sign"] = c.physical;
  j["where"] = c.where;
  return j;
}

Json noiseJson(const Diagnosis& dg, const Comparison& before) {
  Json records = Json::object();
  for (std::size_t i = 0; i < before.records.size() && i < dg.recordNoise.size(); ++i)
    records[before.records[i].stem] = dg.recordNoise[i];
  return {{"source", dg.noiseSource}, {"pooled_estimate", dg.pooledNoise.sigma}, {"records", records}};
}

const std::string kPhaseColors[] = {"#D55E00", "#009E73", "#56B4E9", "#CC79A7", "#E69F00"};

}  // namespace

std::string formatComparisonTable(const Comparison& c) {
  const int d = c.decimals;
  const std::string u = c.unit;
  std::string out;
  for (const auto& r : c.records) {
    out += fmt("%s (%s): %s ME %s %s, RMSE %s %s, R^2 %.*f %%, mean residual %+.*f %s", r.stem.c_str(),
               r.training ? "train" : "validate", c.quantity.c_str(), num(r.overall.maxError, d).c_str(), u.c_str(),
               num(r.overall.rmse, d).c_str(), u.c_str(), d, 100 * r.overall.r2, d, r.overall.bias, u.c_str());
    if (!c.secondaryQuantity.empty())
      out += fmt("; %s RMSE %s %s", c.secondaryQuantity.c_str(), num(r.secondary.rmse, d).c_str(), u.c_str());
    out += fmt("; %zu samples\n", r.overall.count);
    out += fmt("  %-28s %9s %9s %9s %10s %10s\n", "phase", ("ME " + u).c_str(), ("RMSE " + u).c_str(),
               ("bias " + u).c_str(), "sq.err %", "samples %");
    for (std::size_t ph = 0; ph < c.phaseNames.size(); ++ph) {
      const auto& m = r.perPhase[ph];
      if (m.count == 0) {
        out += fmt("  %-28s %9s %9s %9s %10.1f %10.1f\n", c.phaseNames[ph].c_str(), "-", "-", "-", 0.0, 0.0);
        continue;
      }
      out += fmt("  %-28s %9.*f %9.*f %+9.*f %10.1f %10.1f\n", c.phaseNames[ph].c_str(), d, m.maxError, d, m.rmse, d,
                 m.bias, 100 * r.phaseShare[ph], 100 * r.sampleShare[ph]);
    }
  }
  if (!c.records.empty())
    out += std::string(kMetricLegend) +
           "  bias: mean of measured - model; sq.err %: the phase's share of the record's squared error\n";
  return out;
}

std::string renderResidualPanels(const ResidualPlotData& in, const std::string& title) {
  std::vector<SvgPlot> panels;
  const ResidualSegments seg = {in.residual};
  const double n = static_cast<double>(in.residual.size());
  const double ratio = calcEffectiveSampleSize(seg) / n;
  // 1. Residual vs time, phases shaded.
  {
    SvgPlot p(800, 300);
    p.setTitle(in.timeTitle);
    p.setXLabel("time (s)");
    p.setYLabel(in.residualLabel);
    const double t0 = in.time.front(), tEnd = t0 + in.plotSeconds;
    std::vector<double> t, e;
    std::size_t start = 0;
    for (std::size_t i = 0; i < in.time.size() && in.time[i] <= tEnd; ++i) {
      t.push_back(in.time[i]);
      e.push_back(in.residual[i]);
      const bool last = i + 1 == in.time.size() || in.time[i + 1] > tEnd || in.phase[i + 1] != in.phase[i];
      if (last) {
        const auto ph = static_cast<std::size_t>(in.phase[i]);
        p.addBand(in.time[start], in.time[i], in.phaseNames[ph], kPhaseColors[ph % 5]);
        start = i + 1;
      }
    }
    p.addLine(t, e, "residual", "#000000", 1.0);
    p.addHLine(0, "", "#555555");
    panels.push_back(p);
  }
  // 2-4. Binned mean residual with its 99 % band.
  for (const auto& var : in.variables) {
    const BinnedResidual b = calcBinnedResidual(var.values, in.residual, kResidualBins, ratio);
    SvgPlot p(800, 240);
    p.setTitle(var.title.empty() ? "binned mean residual vs " + var.label + ", 99 % band (effective sample size)"
                                 : var.title);
    p.setXLabel(var.label);
    p.setYLabel(in.meanLabel);
    std::vector<double> lo, hi;
    for (std::size_t i = 0; i < b.mean.size(); ++i) {
      lo.push_back(b.mean[i] - b.halfWidth[i]);
      hi.push_back(b.mean[i] + b.halfWidth[i]);
    }
    p.addLine(b.center, hi, "99 % band", "#0072B2", 1.0, true);
    p.addLine(b.center, lo, "", "#0072B2", 1.0, true);
    p.addLine(b.center, b.mean, "mean residual", "#D55E00", 2.0);
    p.addPoints(b.center, b.mean, "", "#D55E00");
    p.addHLine(0, "", "#555555", true, true);
    panels.push_back(p);
  }
  // 5. Autocorrelation with the 99 % band of white noise.
  {
    const double dt = (in.time.back() - in.time.front()) / std::max(1.0, n - 1);
    const int lags = std::max(1, std::min(static_cast<int>(kAcfSeconds / dt), static_cast<int>(n) - 2));
    const auto acf = calcAutocorrelation(seg, lags);
    std::vector<double> lagT;
    for (int k = 0; k <= lags; ++k) lagT.push_back(k * dt);
    SvgPlot p(800, 240);
    p.setTitle("residual autocorrelation (white noise stays inside the 99 % band)");
    p.setXLabel("lag (s)");
    p.setYLabel("autocorrelation (-)");
    const double band = kZ99 / std::sqrt(n);
    p.addHBand(-band, band, "99 % band", "#999999", 0.3);
    p.addLine(lagT, acf, "autocorrelation", "#000000", 1.5);
    p.setYRange(-1, 1);
    panels.push_back(p);
  }
  return renderStackedSvg(panels, title);
}

std::string renderResidualSvg(const RecordComparison& r, const Comparison& c, const std::string& title) {
  ResidualPlotData in;
  in.time = r.time;
  in.residual = r.residual;
  in.phase = r.phase;
  in.phaseNames = c.phaseNames;
  in.plotSeconds = c.plotSeconds;
  const bool whole = r.time.empty() || r.time.back() - r.time.front() <= c.plotSeconds;
  in.timeTitle = c.quantity + " residual vs time" +
                 (whole ? " (whole record)" : " (first " + formatNumber(c.plotSeconds) + " s)") + ", phases shaded";
  in.residualLabel = "measured - model " + c.quantity + " (" + c.unit + ")";
  in.meanLabel = "mean residual (" + c.unit + ")";
  in.variables = r.variables;
  return renderResidualPanels(in, title);
}

std::vector<std::string> writeResidualPlots(const std::string& outDir, const std::string& prefix, const Comparison& c,
                                            const HeldBackComparison* heldBack) {
  std::vector<std::string> paths;
  for (const auto& r : c.records) {
    const std::string path = outDir + "/" + prefix + "-" + makeSafeFileStem(r.stem) + "-residual.svg";
    writeFileAtomic(
        path, renderResidualSvg(r, c,
                                prefix + ": " + r.stem + (r.training ? " (train)" : " (validate)") + ", " + c.quantity +
                                    " RMSE " + num(r.overall.rmse, c.decimals) + " " + c.unit));
    paths.push_back(path);
  }
  for (const auto& p : writeOverlayPlots(outDir, prefix, c, heldBack)) paths.push_back(p);
  return paths;
}

Json makeComparisonJson(const std::string& model, const Comparison& c) {
  Json files = Json::object();
  for (const auto& r : c.records) {
    Json phases = Json::object();
    for (std::size_t ph = 0; ph < c.phaseNames.size(); ++ph)
      phases[c.phaseNames[ph]] = {{"rmse", r.perPhase[ph].rmse},
                                  {"share_of_squared_error", r.phaseShare[ph]},
                                  {"share_of_samples", r.sampleShare[ph]}};
    files[r.stem] = {{"training", r.training},
                     {"me", r.overall.maxError},
                     {"rmse", r.overall.rmse},
                     {"r2", r.overall.r2},
                     {"phases", phases}};
  }
  return {{"model", model}, {"quantity", c.quantity}, {"unit", c.unit}, {"files", files}};
}

std::string formatCandidateRanking(const std::vector<const EffectScore*>& candidates, const std::string& unit,
                                   int decimals) {
  std::string out = fmt("  %-27s %8s %7s %9s %9s %9s  %-24s %s\n", "candidate", ("train " + unit).c_str(), "n_eff",
                        "LR", "p (Bonf.)", "dBIC", ("validation RMSE " + unit).c_str(), "verdict");
  for (const EffectScore* cp : candidates) {
    const EffectScore& c = *cp;
    if (!c.notApplicable.empty()) {
      out += fmt("  %-27s not scored: %s\n", c.effect.c_str(), c.notApplicable.c_str());
      continue;
    }
    std::string val;
    for (double v : c.validationRmse) val += num(v, decimals + 1) + " ";
    std::string verdict = c.accepted ? "ACCEPTED" : "rejected:";
    if (!c.informative) {
      verdict += std::string(" ") + kNoInformation;
    } else if (!c.accepted) {
      if (!c.significant) verdict += " not significant;";
      // Cross-validated (the sweep): the rule's p is the least significant fold's. Where the
      // all-rows test is stronger, the left-out participant of that fold carries evidence the
      // others do not show.
      if (!c.significant && !c.foldPValues.empty() && std::isfinite(c.allRowsPValue) && c.allRowsPValue < c.pValue)
        verdict += " (its least significant fold p " + fmt("%.2g", c.pValue) + "; all participants' rows p " +
                   fmt("%.2g", c.allRowsPValue) + ", unadjusted);";
      if (!c.bicImproves) verdict += " BIC worse;";
      if (!c.validationImproves) verdict += " validation did not fall enough;";
      if (!c.noRecordWorse) verdict += " made a training record worse;";
      if (!c.recordsAgree) verdict += " its value differs between records;";
      if (!c.physical) verdict += " wrong sign;";
    }
    // A refit no better than the current model has LR 0; round-off may make it -1e-12 ("-0.0").
    out += fmt("  %-27s %8s %7.0f %9.1f %9.2g %9.1f  %-24s %s\n", c.effect.c_str(),
               num(c.trainRmse, decimals + 1).c_str(), c.effectiveSamples, std::max(0.0, c.likelihoodRatio),
               c.pAdjusted, c.deltaBic, val.c_str(), verdict.c_str());
  }
  return out;
}

std::string formatAcceptedEffect(const EffectScore& c, const std::string& sentence) {
  std::string out = "  " + c.effect + ": " + sentence + "\n";
  for (const auto& p : c.parameters)
    out += fmt("    %-24s %12.5g  (95 %% CI %.5g .. %.5g", p.name.c_str(), p.value, p.lower, p.upper) +
           (p.intervalNote.empty() ? "" : "; " + p.intervalNote) + ")\n";
  return out + "    acted most in: " + c.where + "\n    sign: " + c.physicalNote + "\n";
}

std::string formatStepOutcome(const std::string& chosen, const std::vector<std::string>& group) {
  if (chosen.empty()) return "  -> no candidate passes the acceptance rule; stop\n";
  std::string out = "  -> added " + chosen;
  if (group.size() > 1) {
    out += " (ambiguous with";
    for (std::size_t g = 1; g < group.size(); ++g) out += " " + group[g];
    out += ")";
  }
  return out + "\n";
}

std::string formatBaseParameter(const std::string& prefix, const std::string& verb, const EffectParameter& p) {
  return fmt("%s%s%s %.4g (95 %% CI %.4g .. %.4g", prefix.c_str(), p.name.c_str(), verb.c_str(), p.value, p.lower,
             p.upper) +
         (p.intervalNote.empty() ? "" : "; " + p.intervalNote) + ")\n";
}

std::string formatDiagnosisText(const Diagnosis& dg, const Comparison& before, const Comparison& after) {
  const int d = before.decimals;
  const std::string& u = before.unit;
  std::string out;
  for (const auto& p : dg.baselineParameters) out += formatBaseParameter("base model: ", " refitted to", p);
  std::vector<std::string> stems, trainStems;
  for (const auto& r : before.records) (r.training ? trainStems : stems).push_back(r.stem);
  // The step lines and the before/after table print the same quantities under the same
  // labels: the RMSE of every training sample pooled, and each held-out record's.
  std::string trainLabel;
  for (const auto& t : trainStems) trainLabel += (trainLabel.empty() ? "" : ", ") + t;
  trainLabel = trainStems.size() > 1 ? "train pooled (" + trainLabel + ")" : "train (" + trainLabel + ")";
  for (std::size_t s = 0; s < dg.steps.size(); ++s) {
    const auto& st = dg.steps[s];
    out += fmt("step %zu: current model, %s RMSE: %s %s %s", s + 1, before.quantity.c_str(), trainLabel.c_str(),
               num(st.currentTrainRmse, d + 1).c_str(), u.c_str());
    for (std::size_t v = 0; v < stems.size() && v < st.currentValidationRmse.size(); ++v)
      out += fmt(", %s %s %s", stems[v].c_str(), num(st.currentValidationRmse[v], d + 1).c_str(), u.c_str());
    out += "\n";
    std::vector<const EffectScore*> scores;
    for (const auto& c : st.candidates) scores.push_back(&c);
    out += formatCandidateRanking(scores, u, d);
    out += formatStepOutcome(st.chosen >= 0 ? st.candidates[static_cast<std::size_t>(st.chosen)].effect : "", st.group);
  }
  out += "\naccepted effects, in order:\n";
  if (dg.accepted.empty()) out += "  none\n";
  // The calibration study's line describes an effect of the library found alone in data it
  // explains; quoted for these data only when the final model explains them (a near miss that
  // leaves the data unexplained would borrow a whole-range effect's record).
  for (const auto& c : dg.acceptedScores)
    out += formatAcceptedEffect(c, describeEffect(c.id).sentence) +
           (dg.explained ? formatMeasuredCoverage(c.effect)
                         : (findMeasuredCoverage(c.effect)
                                ? "    interval check not quoted: the final model does not explain these "
                                  "data, the calibration study's condition\n"
                                : ""));
  for (const auto& a : dg.ambiguityAdvice) out += "ambiguous: " + a + "\n";
  for (const auto& c : dg.confounds) out += "confound: " + c + "\n";
  for (const auto& p : dg.finalParameters) out += formatBaseParameter("", " after:", p);
  out += fmt("\n%-16s | before: ME %-4s RMSE %-4s R^2 %%  | after: ME %-4s RMSE %-4s R^2 %%\n", before.quantity.c_str(),
             u.c_str(), u.c_str(), u.c_str(), u.c_str());
  for (std::size_t i = 0; i < before.records.size() && i < after.records.size(); ++i) {
    const auto& b = before.records[i];
    const auto& a = after.records[i];
    out += fmt("%-10s %-5s |   %10.*f %9.*f %6.1f  |   %9.*f %9.*f %6.1f\n", b.stem.c_str(),
               b.training ? "train" : "valid", d, b.overall.maxError, d + 1, b.overall.rmse, 100 * b.overall.r2, d,
               a.overall.maxError, d + 1, a.overall.rmse, 100 * a.overall.r2);
  }
  if (trainStems.size() > 1) {
    const ErrorMetrics b = pooled(before, true), a = pooled(after, true);
    out += fmt("%-16s |   %10.*f %9.*f %6.1f  |   %9.*f %9.*f %6.1f\n", "train pooled", d, b.maxError, d + 1, b.rmse,
               100 * b.r2, d, a.maxError, d + 1, a.rmse, 100 * a.r2);
  }
  out += kMetricLegend;
  const WhitenessTest& wt = dg.finalWhiteness;
  if (wt.computed)
    out += fmt(
        "\nfinal training residual: Ljung-Box Q = %.1f over %d lags, p = %.3g (white when p >= %.3g, the acceptance "
        "rule's alpha), %d lags outside the 99 %% band: %s\n",
        wt.q, wt.lags, wt.pValue, dg.whitenessLevel, wt.lagsOutsideBand,
        dg.finalResidualWhite ? "consistent with white noise" : "NOT white");
  else
    out += "\nfinal training residual: Ljung-Box test cannot tell (" + wt.note + "): not counted as white\n";
  if (wt.computed && !wt.note.empty()) out += "  (" + wt.note + ")\n";
  out += "measurement noise (" + dg.noiseSource + "):";
  for (std::size_t i = 0; i < before.records.size() && i < dg.recordNoise.size(); ++i)
    out += fmt(" %s %.*f %s", before.records[i].stem.c_str(), d + 1, dg.recordNoise[i], u.c_str());
  out += "\nverdict: " + dg.verdict + "\n";
  return out;
}

// null unless no candidate was significant (Diagnosis::power).
Json powerJson(const std::optional<PowerAdvice>& a) {
  if (!a) return nullptr;
  return {{"effect", a->effect},
          {"likelihood_ratio", a->likelihoodRatio},
          {"dof", a->dof},
          {"level", a->level},
          {"power", kPowerTarget},
          {"training_swings", a->recordsNow},
          {"swings_needed", a->lowersHeldOut ? a->recordsNeeded : 0},
          {"lowers_held_out_error", a->lowersHeldOut}};
}

Json makeDiagnosisJson(const Diagnosis& dg, const Comparison& before, const Comparison& after) {
  std::vector<std::string> stems;
  for (const auto& r : before.records)
    if (!r.training) stems.push_back(r.stem);
  Json candidates = Json::array();
  for (std::size_t s = 0; s < dg.steps.size(); ++s)
    for (const auto& c : dg.steps[s].candidates) candidates.push_back(candidateJson(c, static_cast<int>(s + 1), stems));
  Json out = {{"plant", plantName(dg.plant)},
              {"quantity", before.quantity},
              {"unit", before.unit},
              {"baseline", summaryJson(before)},
              {"baseline_parameters", parametersJson(dg.baselineParameters)},
              {"candidates", candidates},
              {"accepted", dg.accepted},
              {"ambiguous", dg.ambiguous},
              {"ambiguity_advice", dg.ambiguityAdvice},
              {"confounds", dg.confounds},
              {"final", summaryJson(after)},
              {"final_parameters", parametersJson(dg.finalParameters)},
              {"residual_white", dg.finalResidualWhite},
              {"residual_whiteness", dg.finalResidualWhite        ? "white"
                                     : dg.finalWhiteness.computed ? "not white"
                                                                  : "cannot tell"},
              {"residual_whiteness_note", dg.finalWhiteness.note},
              {"residual_whiteness_level", dg.whitenessLevel},
              {"noise", noiseJson(dg, before)},
              {"explained", dg.explained},
              {"verdict", dg.verdict},
              {"more_swings_for_power", powerJson(dg.power)},
              {"structure", dg.structureNote},
              {"missing", dg.missingNote},
              {"warnings", dg.warnings}};
  if (!dg.accepted.empty() && dg.explained) out["interval_coverage"] = coverageJson(dg.accepted);
  // The regions of the missing moment as numbers (the sentence is `missing`).
  if (dg.missing && !dg.explained) {
    Json regions = Json::array();
    for (const auto& r : dg.missing->regions)
      regions.push_back({{"extending", r.extending},
                         {"moment_Nm", r.moment},
                         {"bin_means_Nm", {r.low, r.high}},
                         {"knee_deg", {r.kneeLowDeg, r.kneeHighDeg}},
                         {"knee_rate_deg_s", {r.rateLowDegS, r.rateHighDegS}},
                         {"samples", r.samples}});
    out["missing_regions"] = regions;
  }
  if (std::isfinite(dg.baseline.pooledValidationRmse))
    out["pooled_validation_rmse"] = {{"baseline", dg.baseline.pooledValidationRmse},
                                     {"final", dg.final.pooledValidationRmse}};
  return out;
}

std::string formatHeldBackText(const HeldBackComparison& before, const HeldBackComparison& after) {
  std::string out =
      before.quantity + " against the measured one (never fitted): RMSE " + before.unit + ", Pearson correlation r\n";
  for (std::size_t i = 0; i < before.records.size() && i < after.records.size(); ++i) {
    const auto &b = before.records[i], &a = after.records[i];
    out += fmt("  %-10s %-5s  before: RMSE %6.2f  r %+.2f  | after: RMSE %6.2f  r %+.2f\n", b.stem.c_str(),
               b.training ? "train" : "valid", b.rmse, b.correlation, a.rmse, a.correlation);
  }
  out += fmt("  %-16s before: RMSE %6.2f  r %+.2f  | after: RMSE %6.2f  r %+.2f\n", "all records", before.rmse,
             before.correlation, after.rmse, after.correlation);
  return out;
}

namespace {

Json heldBackSideJson(const HeldBackComparison& c) {
  Json files = Json::object();
  for (const auto& r : c.records)
    files[r.stem] = {{"training", r.training}, {"rmse", r.rmse}, {"correlation", r.correlation}};
  return {{"rmse", c.rmse}, {"correlation", c.correlation}, {"files", files}};
}

}  // namespace

Json makeHeldBackJson(const HeldBackComparison& before, const HeldBackComparison& after) {
  return {{"quantity", before.quantity},
          {"unit", before.unit},
          {"note", "the measured column is never fitted: the model's " + before.quantity +
                       " along each record at its fitted toe-off state"},
          {"before", heldBackSideJson(before)},
          {"after", heldBackSideJson(after)}};
}

std::string renderHeldBackSvg(const HeldBackComparison& before, const HeldBackComparison& after,
                              const std::string& title) {
  std::vector<SvgPlot> panels;
  for (std::size_t i = 0; i < before.records.size() && i < after.records.size(); ++i) {
    const auto &b = before.records[i], &a = after.records[i];
    SvgPlot plot(800, 300);
    plot.setTitle(title + ": " + b.stem + (b.training ? " (training)" : " (held out)") +
                  fmt(", after: RMSE %.1f %s, r %+.2f", a.rmse, after.unit.c_str(), a.correlation));
    plot.setXLabel("time since toe-off (s)");
    plot.setYLabel(before.quantity + " (" + before.unit + ", + = flexion)");
    plot.addLine(b.time, b.measured, "measured (inverse dynamics)", "#000000", 2.0);
    plot.addLine(b.time, b.model, "model before", svgPaletteColor(1), 1.5, true);
    plot.addLine(a.time, a.model, "model after", svgPaletteColor(2), 1.5);
    plot.addHLine(0, "", "#999999");
    panels.push_back(plot);
  }
  return renderStackedSvg(panels);
}

Json makeDiagnoseJson(const Diagnosis& diagnosis, const Comparison& before, const Comparison& after,
                      const std::optional<HeldBackComparison>& heldBefore,
                      const std::optional<HeldBackComparison>& heldAfter) {
  Json json = makeDiagnosisJson(diagnosis, before, after);
  if (heldBefore && heldAfter) json["knee_moment_comparison"] = makeHeldBackJson(*heldBefore, *heldAfter);
  return json;
}

}  // namespace swingsim
