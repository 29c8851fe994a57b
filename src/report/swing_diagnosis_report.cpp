#include "report/swing_diagnosis_report.h"

#include <algorithm>
#include <cstdio>

#include "io/json_writer.h"
#include "core/output_files.h"
#include "model/leg_parameters.h"
#include "report/diagnosis_report.h"

namespace swingsim {

namespace {

template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

void summaryJson(JsonWriter& w, const SwingComparison& c) {
  auto metrics = [&](const ErrorMetrics& m) {
    w.beginObject().field("rmse", m.rmse).field("r2", m.r2).field("me", m.maxError).endObject();
  };
  w.beginObject();
  for (const auto& r : c.records)
    if (r.training) {
      w.key("train");
      metrics(r.knee);
      break;
    }
  w.key("validation").beginObject();
  for (const auto& r : c.records) {
    if (r.training) continue;
    w.key(r.data->stem);
    metrics(r.knee);
  }
  w.endObject().endObject();
}

}  // namespace

std::string formatSwingComparisonTable(const SwingComparison& c) {
  std::string out;
  for (const auto& r : c.records) {
    out += fmt("%s (%s): knee ME %.2f deg, RMSE %.2f deg, R^2 %.2f %%, mean residual %+.2f deg; hip RMSE %.2f deg; %zu samples\n",
               r.data->stem.c_str(), r.training ? "train" : "validate", r.knee.maxError, r.knee.rmse, 100 * r.knee.r2,
               r.knee.bias, r.hip.rmse, r.knee.count);
    out += fmt("  %-24s %9s %9s %9s %10s %10s\n", "phase", "ME deg", "RMSE deg", "bias deg", "sq.err %", "samples %");
    for (std::size_t ph = 0; ph < c.phaseNames.size(); ++ph) {
      const auto& m = r.perPhase[ph];
      if (m.count == 0) {
        out += fmt("  %-24s %9s %9s %9s %10.1f %10.1f\n", c.phaseNames[ph].c_str(), "-", "-", "-", 0.0, 0.0);
        continue;
      }
      out += fmt("  %-24s %9.2f %9.2f %+9.2f %10.1f %10.1f\n", c.phaseNames[ph].c_str(), m.maxError, m.rmse, m.bias,
                 100 * r.phaseShare[ph], 100 * r.sampleShare[ph]);
    }
  }
  return out;
}

std::string renderSwingResidualSvg(const SwingRecordComparison& r, const std::vector<std::string>& phaseNames,
                                   const std::string& title) {
  const SwingRecord& d = *r.data;
  ResidualPlotData in;
  in.time = d.time;
  in.residual = r.kneeResidual;
  in.phase = r.phase;
  in.phaseNames = phaseNames;
  in.timeTitle = "knee residual vs time from toe-off (whole swing), swing phases shaded";
  in.residualLabel = "measured - model knee flexion (deg)";
  in.meanLabel = "mean knee residual (deg)";
  std::vector<double> knee, accel(r.kneeRate.size(), 0.0);
  // All three variables are the model's: binning on the measured (noisy) angle would sort the
  // measurement noise into the end bins near the stop and show a mean residual that is not
  // there. The acceleration is by central differences of the model rate (one-sided at the
  // ends); the measured angle is too noisy to differentiate twice.
  for (double x : r.predictedKnee) knee.push_back(x * kRadToDeg);
  const std::size_t n = std::min(r.kneeRate.size(), d.time.size());
  for (std::size_t i = 0; n > 1 && i < n; ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? n - 1 : i + 1;
    accel[i] = (r.kneeRate[hi] - r.kneeRate[lo]) / (d.time[hi] - d.time[lo]);
  }
  const std::string band = ", 99 % band (effective sample size)";
  in.variables = {{knee, "knee flexion, model (deg)", "mean knee residual vs model knee flexion" + band},
                  {r.kneeRate, "knee flexion rate, model (deg/s)", "mean knee residual vs model knee flexion rate" + band},
                  {accel, "knee angular acceleration, model (deg/s^2)",
                   "mean knee residual vs model knee acceleration" + band}};
  return renderResidualPanels(in, title);
}

std::vector<std::string> writeSwingResidualPlots(const std::string& outDir, const std::string& prefix,
                                                 const SwingComparison& c) {
  std::vector<std::string> paths;
  for (const auto& r : c.records) {
    const std::string path = outDir + "/" + prefix + "-" + r.data->stem + "-residual.svg";
    writeFileAtomic(path, renderSwingResidualSvg(r, c.phaseNames,
                                                 prefix + ": " + r.data->stem + (r.training ? " (train)" : " (validate)") +
                                                     fmt(", knee RMSE %.2f deg", r.knee.rmse)));
    paths.push_back(path);
  }
  return paths;
}

std::string formatSwingDiagnosisText(const SwingDiagnosis& dg, const SwingComparison& before,
                                     const SwingComparison& after) {
  std::string out = fmt("base model: knee model resistance scale refitted to %.4g (95 %% CI %.4g .. %.4g)\n",
                        dg.baseline.kneeModelScale, dg.baselineScaleLower, dg.baselineScaleUpper);
  std::vector<std::string> stems;
  for (const auto& r : before.records)
    if (!r.training) stems.push_back(r.data->stem);
  for (std::size_t s = 0; s < dg.steps.size(); ++s) {
    const auto& st = dg.steps[s];
    out += fmt("step %zu: current model train knee RMSE %.3f deg", s + 1, st.currentTrainRmse);
    for (std::size_t v = 0; v < stems.size(); ++v) out += fmt(", %s %.3f deg", stems[v].c_str(), st.currentValidationRmse[v]);
    out += "\n";
    std::vector<const EffectScore*> scores;
    for (const auto& c : st.candidates) scores.push_back(&c);
    out += formatCandidateRanking(scores, "deg", "%.3f");
    out += formatStepOutcome(st.chosen >= 0 ? st.candidates[static_cast<std::size_t>(st.chosen)].effect : "", st.group);
  }
  out += "\naccepted effects, in order:\n";
  if (dg.accepted.empty()) out += "  none\n";
  for (const auto& c : dg.acceptedScores) out += formatAcceptedEffect(c, findSwingEffect(c.effect).sentence);
  for (const auto& a : dg.ambiguityAdvice) out += "ambiguous: " + a + "\n";
  out += fmt("knee model resistance scale after: %.4g\n", dg.final.kneeModelScale);
  out += "\n               | before knee: ME deg RMSE deg  R^2 %  | after knee: ME deg RMSE deg  R^2 %\n";
  for (std::size_t i = 0; i < before.records.size() && i < after.records.size(); ++i) {
    const auto& b = before.records[i];
    const auto& a = after.records[i];
    out += fmt("%-8s %-5s |   %14.2f %8.3f %6.2f  |   %13.2f %8.3f %6.2f\n", b.data->stem.c_str(),
               b.training ? "train" : "valid", b.knee.maxError, b.knee.rmse, 100 * b.knee.r2, a.knee.maxError, a.knee.rmse,
               100 * a.knee.r2);
  }
  out += fmt("\nfinal training residual (knee and hip): Ljung-Box Q = %.1f over %d lags, p = %.3g, %d lags outside the 99 %% band: ",
             dg.finalWhiteness.q, dg.finalWhiteness.lags, dg.finalWhiteness.pValue, dg.finalWhiteness.lagsOutsideBand);
  out += dg.finalResidualWhite ? "consistent with white noise\n" : "NOT white\n";
  if (!dg.finalResidualWhite)
    out += std::string(dg.accepted.empty() ? "No candidate effect passes the acceptance rule, but the residual is not white: "
                                           : "The residual is still not white: ") +
           "the model misses something the library does not name (or the data cannot support). " + dg.structureNote +
           ". No effect is claimed for it.\n";
  return out;
}

std::string formatSwingDiagnosisJson(const SwingDiagnosis& dg, const SwingComparison& before,
                                     const SwingComparison& after) {
  JsonWriter w;
  std::vector<std::string> stems;
  for (const auto& r : before.records)
    if (!r.training) stems.push_back(r.data->stem);
  w.beginObject().field("unit", std::string("deg knee flexion")).key("baseline");
  summaryJson(w, before);
  w.key("candidates").beginArray();
  for (std::size_t s = 0; s < dg.steps.size(); ++s)
    for (const auto& c : dg.steps[s].candidates) writeCandidateJson(w, c, static_cast<int>(s + 1), stems);
  w.endArray().field("accepted", dg.accepted).key("ambiguous").beginArray();
  for (const auto& g : dg.ambiguous) w.value(g);
  w.endArray().key("final");
  summaryJson(w, after);
  w.field("knee_model_scale", dg.final.kneeModelScale).field("residual_white", dg.finalResidualWhite)
      .field("structure", dg.structureNote).endObject();
  return w.str() + "\n";
}

}  // namespace swingsim
