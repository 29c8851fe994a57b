#include "report/diagnosis_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "io/json_writer.h"
#include "core/output_files.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

constexpr double kZ99 = 2.5758293035489004;  // two-sided 99 % normal quantile
constexpr int kResidualBins = 12;            // equal-count bins for the binned residual
constexpr double kAcfSeconds = 0.5;          // autocorrelation shown up to this lag, s

template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

ErrorMetrics pooled(const CylinderComparison& c, bool training) {
  std::vector<double> m, p;
  for (const auto& r : c.records) {
    if (r.training != training) continue;
    m.insert(m.end(), r.data->force.begin(), r.data->force.end());
    p.insert(p.end(), r.predicted.begin(), r.predicted.end());
  }
  return m.empty() ? ErrorMetrics{} : calcErrorMetrics(m, p);
}

void metricsJson(JsonWriter& w, const ErrorMetrics& m) {
  w.beginObject().field("rmse", m.rmse).field("r2", m.r2).field("me", m.maxError).endObject();
}

void summaryJson(JsonWriter& w, const CylinderComparison& c) {
  w.beginObject().key("train");
  metricsJson(w, pooled(c, true));
  w.key("validation").beginObject();
  for (const auto& r : c.records) {
    if (r.training) continue;
    w.key(r.data->stem);
    metricsJson(w, r.overall);
  }
  w.endObject().endObject();
}

const std::string kPhaseColors[] = {"#D55E00", "#009E73", "#56B4E9", "#CC79A7", "#E69F00"};

}  // namespace

std::string formatComparisonTable(const CylinderComparison& c) {
  std::string out;
  for (const auto& r : c.records) {
    out += fmt("%s (%s): ME %.1f N, RMSE %.1f N, R^2 %.1f %%, mean residual %+.1f N, %zu samples\n",
               r.data->stem.c_str(), r.training ? "train" : "validate", r.overall.maxError, r.overall.rmse,
               100 * r.overall.r2, r.overall.bias, r.overall.count);
    out += fmt("  %-28s %8s %8s %8s %10s %10s\n", "phase", "ME N", "RMSE N", "bias N", "sq.err %", "samples %");
    for (std::size_t ph = 0; ph < c.phaseNames.size(); ++ph) {
      const auto& m = r.perPhase[ph];
      if (m.count == 0) {
        out += fmt("  %-28s %8s %8s %8s %10.1f %10.1f\n", c.phaseNames[ph].c_str(), "-", "-", "-", 0.0, 0.0);
        continue;
      }
      out += fmt("  %-28s %8.1f %8.1f %+8.1f %10.1f %10.1f\n", c.phaseNames[ph].c_str(), m.maxError, m.rmse, m.bias,
                 100 * r.phaseShare[ph], 100 * r.sampleShare[ph]);
    }
  }
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

std::string renderResidualSvg(const RecordComparison& r, const std::vector<std::string>& phaseNames, double plotSeconds,
                              const std::string& title) {
  const BenchData& d = *r.data;
  ResidualPlotData in;
  in.time = d.time;
  in.residual = r.residual;
  in.phase = r.phase;
  in.phaseNames = phaseNames;
  in.plotSeconds = plotSeconds;
  in.timeTitle = "residual vs time (first " + formatNumber(plotSeconds) + " s), phases shaded";
  in.residualLabel = "measured - model (N)";
  in.meanLabel = "mean residual (N)";
  std::vector<double> mm, vv;
  for (double x : d.position) mm.push_back(1e3 * x);
  for (double x : d.velocity) vv.push_back(1e3 * x);
  in.variables = {{mm, "piston position (mm)", ""}, {vv, "piston velocity (mm/s)", ""},
                  {r.acceleration, "piston acceleration (m/s^2)", ""}};
  return renderResidualPanels(in, title);
}

std::vector<std::string> writeResidualPlots(const std::string& outDir, const std::string& prefix,
                                            const CylinderComparison& c, double plotSeconds) {
  std::vector<std::string> paths;
  for (const auto& r : c.records) {
    const std::string path = outDir + "/" + prefix + "-" + r.data->stem + "-residual.svg";
    writeFileAtomic(path, renderResidualSvg(r, c.phaseNames, plotSeconds,
                                            prefix + ": " + r.data->stem + (r.training ? " (train)" : " (validate)") +
                                                fmt(", RMSE %.1f N", r.overall.rmse)));
    paths.push_back(path);
  }
  return paths;
}

std::string formatComparisonJson(const std::string& model, const CylinderComparison& c) {
  JsonWriter w;
  w.beginObject().field("model", model).key("files").beginObject();
  for (const auto& r : c.records) {
    w.key(r.data->stem).beginObject().field("training", r.training).field("me", r.overall.maxError);
    w.field("rmse", r.overall.rmse).field("r2", r.overall.r2).key("phases").beginObject();
    for (std::size_t ph = 0; ph < c.phaseNames.size(); ++ph)
      w.key(c.phaseNames[ph]).beginObject().field("rmse", r.perPhase[ph].rmse)
          .field("share_of_squared_error", r.phaseShare[ph]).field("share_of_samples", r.sampleShare[ph]).endObject();
    w.endObject().endObject();
  }
  w.endObject().endObject();
  return w.str() + "\n";
}

std::string formatCandidateRanking(const std::vector<const EffectScore*>& candidates, const std::string& unit,
                                   const char* rmseFormat) {
  std::string out = fmt("  %-27s %8s %7s %9s %9s %9s  %-24s %s\n", "candidate", ("train " + unit).c_str(), "n_eff", "LR",
                        "p (Bonf.)", "dBIC", ("validation RMSE " + unit).c_str(), "verdict");
  for (const EffectScore* cp : candidates) {
    const EffectScore& c = *cp;
    if (!c.notApplicable.empty()) {
      out += fmt("  %-27s not scored: %s\n", c.effect.c_str(), c.notApplicable.c_str());
      continue;
    }
    std::string val;
    for (double v : c.validationRmse) val += fmt(rmseFormat, v) + " ";
    std::string verdict = c.accepted ? "ACCEPTED" : "rejected:";
    if (!c.accepted) {
      if (!c.significant) verdict += " not significant;";
      if (!c.bicImproves) verdict += " BIC worse;";
      if (!c.validationImproves) verdict += " validation did not fall enough;";
      if (!c.physical) verdict += " wrong sign;";
    }
    out += fmt("  %-27s %8s %7.0f %9.1f %9.2g %9.1f  %-24s %s\n", c.effect.c_str(), fmt(rmseFormat, c.trainRmse).c_str(),
               c.effectiveSamples, c.likelihoodRatio, c.pAdjusted, c.deltaBic, val.c_str(), verdict.c_str());
  }
  return out;
}

std::string formatAcceptedEffect(const EffectScore& c, const std::string& sentence) {
  std::string out = "  " + c.effect + ": " + sentence + "\n";
  for (const auto& p : c.parameters)
    out += fmt("    %-24s %12.5g  (95 %% CI %.5g .. %.5g)\n", p.name.c_str(), p.value, p.lower, p.upper);
  return out + "    acted most in: " + c.where + "\n    sign: " + c.physicalNote + "\n";
}

void writeCandidateJson(JsonWriter& w, const EffectScore& c, int step, const std::vector<std::string>& stems) {
  w.beginObject().field("effect", c.effect).field("step", step).field("accepted", c.accepted);
  if (!c.notApplicable.empty()) {
    w.field("not_applicable", c.notApplicable).endObject();
    return;
  }
  w.key("validation_rmse").beginObject();
  for (std::size_t v = 0; v < stems.size() && v < c.validationRmse.size(); ++v) w.field(stems[v], c.validationRmse[v]);
  w.endObject().field("train_rmse", c.trainRmse).field("delta_bic", c.deltaBic);
  w.field("likelihood_ratio", c.likelihoodRatio).field("p_adjusted", c.pAdjusted);
  w.field("effective_samples", c.effectiveSamples).key("parameters").beginObject();
  for (const auto& p : c.parameters) w.field(p.name, p.value);
  w.endObject().key("confidence_intervals").beginObject();
  for (const auto& p : c.parameters) w.field(p.name, std::vector<double>{p.lower, p.upper});
  w.endObject().field("physical_sign", c.physical).field("where", c.where).endObject();
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

std::string formatDiagnosisText(const CylinderDiagnosis& dg, const CylinderComparison& before,
                                const CylinderComparison& after) {
  std::string out;
  std::vector<std::string> stems;
  for (const auto& r : before.records)
    if (!r.training) stems.push_back(r.data->stem);
  for (std::size_t s = 0; s < dg.steps.size(); ++s) {
    const auto& st = dg.steps[s];
    out += fmt("step %zu: current model train RMSE %.1f N", s + 1, st.currentTrainRmse);
    for (std::size_t v = 0; v < stems.size(); ++v) out += fmt(", %s %.1f N", stems[v].c_str(), st.currentValidationRmse[v]);
    out += "\n";
    std::vector<const EffectScore*> scores;
    for (const auto& c : st.candidates) scores.push_back(&c);
    out += formatCandidateRanking(scores, "N", "%.1f");
    out += formatStepOutcome(st.chosen >= 0 ? st.candidates[static_cast<std::size_t>(st.chosen)].effect : "", st.group);
  }
  out += "\naccepted effects, in order:\n";
  if (dg.accepted.empty()) out += "  none\n";
  for (const auto& c : dg.acceptedScores) out += formatAcceptedEffect(c, findCylinderEffect(c.effect).sentence);
  for (const auto& a : dg.ambiguityAdvice) out += "ambiguous: " + a + "\n";
  out += "\n              |   before: ME N  RMSE N  R^2 %  |   after: ME N  RMSE N  R^2 %\n";
  for (std::size_t i = 0; i < before.records.size(); ++i) {
    const auto& b = before.records[i];
    const auto& a = after.records[i];
    out += fmt("%-8s %-5s |   %10.1f %7.1f %6.1f  |   %9.1f %7.1f %6.1f\n", b.data->stem.c_str(),
               b.training ? "train" : "valid", b.overall.maxError, b.overall.rmse, 100 * b.overall.r2, a.overall.maxError,
               a.overall.rmse, 100 * a.overall.r2);
  }
  out += fmt("\nfinal training residual: Ljung-Box Q = %.1f over %d lags, p = %.3g, %d lags outside the 99 %% band: ",
             dg.finalWhiteness.q, dg.finalWhiteness.lags, dg.finalWhiteness.pValue, dg.finalWhiteness.lagsOutsideBand);
  out += dg.finalResidualWhite ? "consistent with white noise\n" : "NOT white\n";
  if (!dg.finalResidualWhite) {
    out += std::string(dg.accepted.empty() ? "No candidate effect passes the acceptance rule, but the residual is not white: "
                                           : "The residual is still not white: ") +
           "the model misses something the library does not name (or the data cannot support). " + dg.structureNote +
           ". No effect is claimed for it.\n";
  }
  return out;
}

std::string formatDiagnosisJson(const CylinderDiagnosis& dg, const CylinderComparison& before,
                                const CylinderComparison& after) {
  JsonWriter w;
  std::vector<std::string> stems;
  for (const auto& r : before.records)
    if (!r.training) stems.push_back(r.data->stem);
  w.beginObject().key("baseline");
  summaryJson(w, before);
  w.key("candidates").beginArray();
  for (std::size_t s = 0; s < dg.steps.size(); ++s) {
    for (const auto& c : dg.steps[s].candidates) {
      writeCandidateJson(w, c, static_cast<int>(s + 1), stems);
    }
  }
  w.endArray().field("accepted", dg.accepted).key("ambiguous").beginArray();
  for (const auto& g : dg.ambiguous) w.value(g);
  w.endArray().key("final");
  summaryJson(w, after);
  w.field("residual_white", dg.finalResidualWhite).field("structure", dg.structureNote).endObject();
  return w.str() + "\n";
}

}  // namespace swingsim
