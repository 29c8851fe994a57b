#include "report/cohort_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/text_format.h"
#include "io/json_file.h"
#include "report/svg_plot.h"

namespace swingsim {

namespace {

constexpr int kHistogramBins = 12;
constexpr double kMs = 1000;  // s -> ms in tables and figures

std::string numberOrDash(double v, const char* format) { return std::isfinite(v) ? fmt(format, v) : "-"; }

/// A histogram as a filled step outline over the finite values; `scale` converts units.
SvgPlot makeHistogram(const std::string& title, const std::string& xLabel, const std::vector<double>& values,
                      double scale, double binWidth) {
  SvgPlot plot(800, 340);
  plot.setTitle(title);
  plot.setXLabel(xLabel);
  plot.setYLabel("participants");
  std::vector<double> v;
  for (double x : values)
    if (std::isfinite(x)) v.push_back(x * scale);
  if (v.empty()) return plot;
  const double lo = std::floor(*std::min_element(v.begin(), v.end()) / binWidth - 0.5) * binWidth;
  const double hi = std::ceil(*std::max_element(v.begin(), v.end()) / binWidth + 0.5) * binWidth;
  const int bins = std::max(1, static_cast<int>(std::lround((hi - lo) / binWidth)));
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double x : v) counts[static_cast<std::size_t>(std::clamp(static_cast<int>((x - lo) / binWidth), 0, bins - 1))]++;
  std::vector<double> xs, zeros, ys;
  for (int b = 0; b < bins; ++b) {
    const double x0 = lo + b * binWidth, x1 = x0 + binWidth, c = counts[static_cast<std::size_t>(b)];
    xs.insert(xs.end(), {x0, x1});
    ys.insert(ys.end(), {c, c});
    zeros.insert(zeros.end(), {0.0, 0.0});
  }
  plot.addFill(xs, zeros, ys, "", svgPaletteColor(0), 0.45);
  plot.addLine(xs, ys, "", svgPaletteColor(0), 1.5);
  plot.setXRange(lo, hi);
  plot.setYRange(0, 1.1 * *std::max_element(ys.begin(), ys.end()) + 0.5);
  return plot;
}

double chooseBinWidth(const std::vector<double>& values, double scale, double minWidth) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : values)
    if (std::isfinite(x)) lo = std::min(lo, x * scale), hi = std::max(hi, x * scale);
  if (!(hi > lo)) return minWidth;
  return std::max(minWidth, (hi - lo) / kHistogramBins);
}

/// Spearman's rho of every predictor with its interval, one row each, strongest on top.
SvgPlot makePredictorFigure(const CohortSummary& s) {
  const std::size_t n = s.predictors.size();
  SvgPlot plot(800, 120 + 28 * static_cast<double>(n));
  plot.setTitle("What predicts the time gained by lowering the knee");
  plot.setXLabel("Spearman's rho with the time gained (dot), 95 % Fisher-z interval (bar)");
  std::vector<std::pair<double, std::string>> labels;
  for (std::size_t i = 0; i < n; ++i) {
    const CohortPredictor& p = s.predictors[i];
    const double y = static_cast<double>(n - i);
    labels.emplace_back(y, p.what);
    if (!std::isfinite(p.withGain.rho)) continue;
    if (std::isfinite(p.withGain.low))
      plot.addLine({p.withGain.low, p.withGain.high}, {y, y}, i == 0 ? "95 % interval" : "", svgPaletteColor(0), 6);
    plot.addPoints({p.withGain.rho}, {y}, i == 0 ? "rho" : "", svgPaletteColor(1), 4);
  }
  plot.addVLine(0.0, "", "#333333", false);
  plot.setXRange(-1, 1);
  plot.setYRange(0.4, static_cast<double>(n) + 0.6);
  plot.setYTickLabels(labels, 330);
  return plot;
}

SvgPlot makeScatter(const CohortPredictor& p, const CohortSummary& s) {
  SvgPlot plot(800, 360);
  plot.setTitle("Time gained against " + p.what + " (rho " + numberOrDash(p.withGain.rho, "%.2f") + ")");
  plot.setXLabel(p.what);
  plot.setYLabel("time gained by the fastest lowering (ms)");
  std::vector<double> gain;
  for (double g : s.timeGained) gain.push_back(g * kMs);
  plot.addPoints(p.values, gain, "", svgPaletteColor(2), 3);
  return plot;
}

std::string formatDistribution(const CohortDistribution& d) {
  if (d.kind == CohortDistribution::Kind::kUniform) return "uniform " + fmt("%g", d.min) + " .. " + fmt("%g", d.max);
  return "normal mean " + fmt("%g", d.mean) + ", sd " + fmt("%g", d.sd) + ", truncated to " + fmt("%g", d.min) +
         " .. " + fmt("%g", d.max);
}

// The participants whose lowering sweep stops before the grid's end: their leg runs out (the
// knee unit's COM would pass the ankle, or the shank its minimum length: calcMaxLowering).
std::string formatShortSweeps(const Cohort& cohort, const std::vector<CohortParticipantResult>& results) {
  constexpr int kListed = 10;
  constexpr double kGridTol = 1e-9;  // m: grid lowerings are rounded to 1e-6 m
  int count = 0;
  std::string listed;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& lowerings = results[i].sweep.lowerings;
    if (lowerings.empty() || lowerings.back() >= cohort.study.loweringMax - kGridTol) continue;
    if (++count <= kListed)
      listed += (listed.empty() ? "" : ", ") + cohort.study.participants[i].name + " at " +
                fmt("%g", lowerings.back() * kMs) + " mm";
  }
  if (count == 0) return "";
  return (count == 1 ? std::string("1 participant's sweep stops before ")
                     : fmt("%d participants' sweeps stop before ", count)) +
         fmt("%g", cohort.study.loweringMax * kMs) +
         " mm, where their leg runs out (the knee unit's centre of mass would pass the ankle, or the shank its least "
         "length): " +
         listed + (count > kListed ? ", ..." : "") + ".\n\n";
}

std::string formatMarkdown(const Cohort& cohort, const std::vector<CohortParticipantResult>& results,
                           const CohortSummary& s, const std::string& scatterFile) {
  std::string md = "# Cohort study " + cohort.study.name + "\n\n";
  if (!cohort.study.description.empty()) md += cohort.study.description + "\n\n";
  md += fmt("%d participants drawn with seed %llu from the distributions below; each starts from ", cohort.count,
            static_cast<unsigned long long>(cohort.seed)) +
        "`" + cohort.templatePath.substr(cohort.templatePath.find_last_of('/') + 1) +
        "` (knee model, initial pose, swing-end rule, hip-moment shape), its hip time scale calibrated to its drawn "
        "swing time, then its knee axis lowered in " +
        fmt("%g", cohort.study.loweringStep * kMs) + " mm steps up to " + fmt("%g", cohort.study.loweringMax * kMs) +
        " mm (or where its shank runs out). Sources and the leg model: "
        "docs/cohort.md.\n\n";
  md += "## Distributions\n\n| property | distribution | source |\n|---|---|---|\n";
  for (std::size_t k = 0; k < cohortProperties().size(); ++k)
    md += "| " + cohortProperties()[k].what + " | " + formatDistribution(cohort.distributions[k]) + " | " +
          cohort.distributions[k].source + " |\n";
  md += fmt("\n## Fastest lowering and time gained\n\n%d of %d participants calibrated", s.calibrated, s.participants);
  std::string failed;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (!results[i].calibrated) failed += (failed.empty() ? "" : ", ") + cohort.study.participants[i].name;
  md += failed.empty() ? ".\n\n"
                       : " (not calibrated, left out: " + failed +
                             "; their target swing time is outside what the "
                             "hip time scale reaches).\n\n";
  const Interval& l = s.fastestLoweringInterval;
  const Interval& g = s.timeGainedInterval;
  md += "| | median | 5 % | 95 % | participants |\n|---|---|---|---|---|\n";
  md += "| fastest lowering (mm) | " + numberOrDash(l.median * kMs, "%.0f") + " | " +
        numberOrDash(l.p05 * kMs, "%.0f") + " | " + numberOrDash(l.p95 * kMs, "%.0f") + " | " +
        std::to_string(l.count) + " |\n";
  md += "| time gained (ms) | " + numberOrDash(g.median * kMs, "%.1f") + " | " + numberOrDash(g.p05 * kMs, "%.1f") +
        " | " + numberOrDash(g.p95 * kMs, "%.1f") + " | " + std::to_string(g.count) + " |\n\n";
  int atMax = 0;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i].sweep.best >= 0 && results[i].sweep.best + 1 == static_cast<int>(results[i].sweep.lowerings.size()))
      ++atMax;
  md += fmt("%d participants are fastest at their largest lowering (the grid's end or where the shank runs out).\n\n",
            atMax);
  md += formatShortSweeps(cohort, results);
  md += "![fastest lowering](cohort-fastest-lowering.svg)\n\n![time gained](cohort-time-gained.svg)\n\n";
  md +=
      "## What predicts the gain\n\nSpearman's rank correlation of each property with the time gained, 95 % "
      "interval by Fisher's z with the standard error 1.06 / sqrt(n - 3) (Fieller, Hartley & Pearson 1957). "
      "Strongest first.\n\n| property | rho | 95 % interval | participants |\n|---|---|---|---|\n";
  for (const auto& p : s.predictors)
    md += "| " + p.what + " | " + numberOrDash(p.withGain.rho, "%+.2f") + " | " +
          numberOrDash(p.withGain.low, "%+.2f") + " .. " + numberOrDash(p.withGain.high, "%+.2f") + " | " +
          std::to_string(p.withGain.count) + " |\n";
  md += "\n![predictors](cohort-predictors.svg)\n\n![strongest predictor](" + scatterFile + ")\n\n";
  md += "Every participant's values and results: cohort.csv.\n";
  return md;
}

std::string formatCsv(const Cohort& cohort, const std::vector<CohortParticipantResult>& results,
                      const CohortSummary& s) {
  std::string csv = "participant";
  for (const auto& p : cohortProperties()) csv += "," + p.key;
  csv +=
      ",body_mass_kg,calibrated,hip_time_scale,standard_swing_time_s,fastest_lowering_m,fastest_swing_time_s,"
      "time_gained_s\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    csv += cohort.study.participants[i].name;
    for (double v : cohort.values[i]) csv += fmt(",%.17g", v);
    csv += fmt(",%.17g,%d", cohort.study.participants[i].bodyMass, r.calibrated ? 1 : 0);
    for (double v :
         {r.timeScale, r.calcStandardTime(), s.fastestLowering[i], r.sweep.calcFastestTime(), s.timeGained[i]})
      csv += std::isfinite(v) ? fmt(",%.17g", v) : std::string(",");
    csv += "\n";
  }
  return csv;
}

Json numberOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json formatInterval(const Interval& i) {
  return {{"median", numberOrNull(i.median)},
          {"p05", numberOrNull(i.p05)},
          {"p95", numberOrNull(i.p95)},
          {"count", i.count}};
}

}  // namespace

std::vector<std::pair<std::string, std::string>> makeCohortReport(const Cohort& cohort,
                                                                  const std::vector<CohortParticipantResult>& results,
                                                                  const CohortSummary& s) {
  std::vector<std::pair<std::string, std::string>> files;
  const std::string scatter = s.predictors.empty() ? "" : "cohort-gain-vs-" + s.predictors.front().key + ".svg";
  files.emplace_back("report.md", formatMarkdown(cohort, results, s, scatter));
  files.emplace_back("cohort.csv", formatCsv(cohort, results, s));
  files.emplace_back(
      "cohort-fastest-lowering.svg",
      makeHistogram("Fastest lowering over the cohort", "fastest lowering below the standard knee axis (mm)",
                    s.fastestLowering, kMs, cohort.study.loweringStep * kMs)
          .render());
  files.emplace_back("cohort-time-gained.svg", makeHistogram("Time gained by the fastest lowering over the cohort",
                                                             "standard-location minus fastest swing time (ms)",
                                                             s.timeGained, kMs, chooseBinWidth(s.timeGained, kMs, 0.5))
                                                   .render());
  files.emplace_back("cohort-predictors.svg", makePredictorFigure(s).render());
  if (!s.predictors.empty()) files.emplace_back(scatter, makeScatter(s.predictors.front(), s).render());
  return files;
}

std::string formatCohortSummary(const Cohort& cohort, const CohortSummary& s) {
  const Interval& l = s.fastestLoweringInterval;
  const Interval& g = s.timeGainedInterval;
  std::string out = fmt("cohort %s: %d participants (seed %llu), %d calibrated\n", cohort.study.name.c_str(),
                        cohort.count, static_cast<unsigned long long>(cohort.seed), s.calibrated);
  out += "  fastest lowering  median " + numberOrDash(l.median * kMs, "%.0f") +
         " mm (5-95 %: " + numberOrDash(l.p05 * kMs, "%.0f") + " .. " + numberOrDash(l.p95 * kMs, "%.0f") + " mm)\n";
  out += "  time gained       median " + numberOrDash(g.median * kMs, "%.1f") +
         " ms (5-95 %: " + numberOrDash(g.p05 * kMs, "%.1f") + " .. " + numberOrDash(g.p95 * kMs, "%.1f") + " ms)\n";
  for (std::size_t i = 0; i < std::min<std::size_t>(3, s.predictors.size()); ++i) {
    const auto& p = s.predictors[i];
    out += fmt("  predictor %zu       %s: rho %s (95 %%: %s .. %s)\n", i + 1, p.what.c_str(),
               numberOrDash(p.withGain.rho, "%+.2f").c_str(), numberOrDash(p.withGain.low, "%+.2f").c_str(),
               numberOrDash(p.withGain.high, "%+.2f").c_str());
  }
  return out;
}

std::string formatCohortJson(const Cohort& cohort, const std::vector<CohortParticipantResult>& results,
                             const CohortSummary& s) {
  Json j;
  j["study"] = cohort.study.name;
  j["participants"] = cohort.count;
  j["seed"] = cohort.seed;
  j["calibrated"] = s.calibrated;
  j["fastest_lowering_interval_m"] = formatInterval(s.fastestLoweringInterval);
  j["time_gained_interval_s"] = formatInterval(s.timeGainedInterval);
  Json predictors = Json::array();
  for (const auto& p : s.predictors)
    predictors.push_back({{"key", p.key},
                          {"rho", numberOrNull(p.withGain.rho)},
                          {"low", numberOrNull(p.withGain.low)},
                          {"high", numberOrNull(p.withGain.high)},
                          {"count", p.withGain.count}});
  j["predictors"] = predictors;
  Json rows = Json::array();
  for (std::size_t i = 0; i < results.size(); ++i) {
    Json row;
    row["participant"] = cohort.study.participants[i].name;
    Json drawn;
    for (std::size_t k = 0; k < cohortProperties().size(); ++k) drawn[cohortProperties()[k].key] = cohort.values[i][k];
    row["drawn"] = drawn;
    row["calibrated"] = results[i].calibrated;
    if (!results[i].calibrated) row["failure"] = results[i].failure;
    row["hip_time_scale"] = numberOrNull(results[i].timeScale);
    row["standard_swing_time_s"] = numberOrNull(results[i].calcStandardTime());
    row["fastest_lowering_m"] = numberOrNull(s.fastestLowering[i]);
    row["fastest_swing_time_s"] = numberOrNull(results[i].sweep.calcFastestTime());
    row["time_gained_s"] = numberOrNull(s.timeGained[i]);
    rows.push_back(row);
  }
  j["participants_results"] = rows;
  return formatJson(j);
}

}  // namespace swingsim
