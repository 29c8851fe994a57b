#include "report/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "io/csv_table.h"
#include "core/input_error.h"
#include "core/text_format.h"
#include "core/output_files.h"
#include "io/json_file.h"
#include "numerics/metrics.h"
#include "report/svg_plot.h"
#include "report/swing_json.h"
#include "sweep/burkett_published.h"

namespace swingsim {

namespace {

constexpr double kSameLowering = 1e-6;  // m: lowerings closer than this are the same row
const double kNaN = std::numeric_limits<double>::quiet_NaN();

const SweepPoint* pointAt(const ParticipantSweep& ps, double lowering) {
  for (const auto& pt : ps.points)
    if (std::fabs(pt.lowering - lowering) < kSameLowering) return &pt;
  return nullptr;
}

const Participant* participantNamed(const SweepStudy& study, const std::string& name) {
  for (const auto& p : study.participants)
    if (p.name == name) return &p;
  return nullptr;
}

std::string shortFailure(const SweepPoint& pt) {
  if (pt.failure.find("thigh never reached") != std::string::npos) return "no end: thigh short of target";
  if (pt.failure.find("never came back") != std::string::npos) return "no end: knee stays flexed";
  if (!pt.ran) return "not run (interrupted)";
  return "failed";
}

const ParticipantUncertainty* uncertaintyOf(const UncertaintyResults* u, const std::string& name) {
  if (!u) return nullptr;
  for (const auto& pu : u->participants)
    if (pu.name == name) return &pu;
  return nullptr;
}

const SweepAssumption* assumptionKeyed(const std::string& key) {
  for (const auto& a : sweepAssumptions())
    if (a.key == key) return &a;
  return nullptr;
}

// An assumption's value as a reader wants it: the reading's name for a two-way choice.
std::string formatAssumptionValue(const std::string& key, double v) {
  const SweepAssumption* a = assumptionKeyed(key);
  if (a && a->discrete) return a->choices[v >= 0.5 ? 1 : 0];
  return fmt("%.4g", v);
}

// " N m" after a value; nothing for a choice or a dimensionless value (unit "1").
std::string unitSuffix(const std::string& unit) { return unit == "choice" || unit == "1" ? "" : " " + unit; }

std::string formatLoweringOrNone(double v) { return std::isfinite(v) ? fmt("%.3f", v) : "no end"; }

}  // namespace

std::string formatUncertaintyTables(const UncertaintyResults& u) {
  std::string out = "\nHow sure is the optimum: " + std::to_string(u.samples) + " Monte Carlo samples, seed " +
                    std::to_string(u.seed) + " (assumptions and ranges: docs/uncertainty.md)\n";
  out += "  participant  nominal_m  fastest_median_m  fastest_p05_m  fastest_p95_m  time_median_s  time_p05_s  "
         "time_p95_s  no_swing_end\n";
  for (const auto& pu : u.participants) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-11s  %9s  %16.3f  %13.3f  %13.3f  %13.4f  %10.4f  %10.4f  %12d\n",
                  pu.name.c_str(), formatLoweringOrNone(pu.nominal.calcFastestLowering()).c_str(),
                  pu.fastestLowering.median, pu.fastestLowering.p05, pu.fastestLowering.p95, pu.fastestTime.median,
                  pu.fastestTime.p05, pu.fastestTime.p95, pu.samplesWithoutSwingEnd);
    out += line;
  }
  for (const auto& pu : u.participants) {
    if (pu.sensitivity.empty()) continue;
    out += "  " + pu.name + ", largest one-at-a-time effects on the fastest lowering:";
    for (std::size_t k = 0; k < pu.sensitivity.size() && k < 3; ++k) {
      const SensitivityRow& r = pu.sensitivity[k];
      out += std::string(k ? ";" : "") + " " + r.assumption + " " + formatAssumptionValue(r.assumption, r.lowValue) +
             " -> " + formatLoweringOrNone(r.low.calcFastestLowering()) + " m, " +
             formatAssumptionValue(r.assumption, r.highValue) + " -> " +
             formatLoweringOrNone(r.high.calcFastestLowering()) + " m";
    }
    out += "\n";
  }
  return out;
}

std::string formatSweepTables(const SweepStudy& study, const SweepResults& results) {
  std::string out;
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = findPublished(ps.name);
    const Participant* participant = participantNamed(study, ps.name);
    const bool strikeAlarm = participant == nullptr || participant->toeClearance.alarmHolds();
    out += "\n" + ps.name + " — swing time vs knee-axis lowering (study " + study.name + ")\n";
    if (!ps.capNote.empty()) out += "  note: " + ps.capNote + "\n";
    if (!strikeAlarm)
      out += "  toe clearance relative to standing hip height (running, hip rise not given: no strike alarm)\n";
    out += "  lowering_m  swing_time_s  peak_knee_deg  bounce  toe_clearance_m  paper_model_s  paper_measured_s\n";
    for (std::size_t k = 0; k < ps.points.size(); ++k) {
      const SweepPoint& pt = ps.points[k];
      std::string paperModel = "", paperMeasured = "";
      if (pub) {
        for (const auto& row : pub->table4)
          if (std::fabs(row.lowering - pt.lowering) < kSameLowering) {
            paperModel = fmt("%.3f", row.model);
            paperMeasured = fmt("%.3f", row.measuredProsthetic);
          }
      }
      char line[256];
      if (pt.ok) {
        std::snprintf(line, sizeof line, "  %10.3f  %12.4f  %13.1f  %6s  %15.3f  %13s  %16s%s%s\n", pt.lowering,
                      pt.result.swingTime, pt.result.peakKneeFlexion * kRadToDeg, pt.result.bounce ? "yes" : "no",
                      pt.result.minToeClearance, paperModel.c_str(), paperMeasured.c_str(),
                      static_cast<int>(k) == ps.best ? "  <- fastest" : "",
                      pt.result.minToeClearance < 0 && strikeAlarm ? "  (toe strikes)" : "");
      } else {
        std::snprintf(line, sizeof line, "  %10.3f  %-44s  %13s  %16s\n", pt.lowering, shortFailure(pt).c_str(),
                      paperModel.c_str(), paperMeasured.c_str());
      }
      out += line;
    }
    if (ps.best >= 0) {
      const SweepPoint& b = ps.points[static_cast<std::size_t>(ps.best)];
      out += "  fastest: " + fmt("%.3f", b.lowering) + " m, " + fmt("%.4f", b.result.swingTime) + " s";
      if (pub) out += " (Burkett's model: " + fmt("%.3f", pub->predictedBestLowering) + " m)";
      out += "\n";
    }
    if (ps.bestWithMass >= 0) {
      const SweepPoint& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
      out += "  fastest with added shank mass: lowering " + fmt("%.3f", b.lowering) + " m + " + fmt("%.2f", b.added.mass) +
             " kg at " + fmt("%.3f", b.added.distanceBelowKnee) + " m below the knee: " + fmt("%.4f", b.result.swingTime) +
             " s\n";
    }
  }
  return out;
}

namespace {

Json intervalJson(const Interval& i) { return {{"median", i.median}, {"p05", i.p05}, {"p95", i.p95}}; }

Json sensitivityJson(const ParticipantUncertainty& pu) {
  Json rows = Json::array();
  for (const auto& r : pu.sensitivity) {
    Json row = {{"assumption", r.assumption}, {"unit", r.unit}, {"low_value", r.lowValue}, {"high_value", r.highValue},
                {"fastest_lowering_low_m", r.low.calcFastestLowering()},
                {"fastest_lowering_high_m", r.high.calcFastestLowering()}, {"time_low_s", r.low.calcFastestTime()},
                {"time_high_s", r.high.calcFastestTime()}};
    if (const SweepAssumption* a = assumptionKeyed(r.assumption); a && a->discrete) {
      row["low_choice"] = formatAssumptionValue(r.assumption, r.lowValue);
      row["high_choice"] = formatAssumptionValue(r.assumption, r.highValue);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::string formatSweepJson(const SweepResults& results, const UncertaintyResults* uncertainty) {
  Json participants = Json::array();
  for (const auto& ps : results.participants) {
    std::vector<double> lowering, swing, peak, clearance, bounceHeight;
    std::vector<bool> bounce, ok;
    std::vector<int> bounces;
    for (const auto& pt : ps.points) {
      lowering.push_back(pt.lowering);
      swing.push_back(pt.ok ? pt.result.swingTime : kNaN);
      peak.push_back(pt.ok ? pt.result.peakKneeFlexion * kRadToDeg : kNaN);
      clearance.push_back(pt.ok ? pt.result.minToeClearance : kNaN);
      bounce.push_back(pt.ok && pt.result.bounce);
      bounces.push_back(pt.ok ? pt.result.bounces : 0);
      bounceHeight.push_back(pt.ok && pt.result.bounce ? pt.result.bounceHeight * kRadToDeg : kNaN);
      ok.push_back(pt.ok);
    }
    Json j = {{"name", ps.name}, {"lowering_m", lowering}, {"swing_time_s", swing}, {"peak_knee_flexion_deg", peak},
              {"bounce", bounce}, {"bounces", bounces}, {"bounce_height_deg", bounceHeight}, {"swing_ended", ok},
              {"min_toe_clearance_m", clearance}};
    for (const auto& v : results.table4) {
      if (v.participant != ps.name) continue;
      Json rows = Json::array();
      for (const auto& r : v.rows)
        rows.push_back({{"lowering_m", r.lowering}, {"measured_s", r.measured}, {"burkett_model_s", r.model},
                        {"ours_s", r.ours}, {"ours_leave_one_out_s", r.oursLeaveOneOut}});
      j["table4_validation"] = {{"calibrated_to", calibrationTargetKey(results.calibratedTo)},
                                {"calibrated", v.calibrated},
                                {"rows", rows},
                                {"rmse_ours_s", v.rmseOurs},
                                {"rmse_burkett_model_s", v.rmseModel},
                                {"rmse_leave_one_out_s", v.rmseLeaveOneOut},
                                {"shortening_measured_s", v.shorteningMeasured},
                                {"shortening_ours_s", v.shorteningOurs},
                                {"shortening_burkett_model_s", v.shorteningModel}};
      for (const auto& c : results.calibrations)
        if (c.participant == ps.name)
          j["table4_validation"]["calibration"] = {{"target_s", c.targetTime}, {"time_scale", c.timeScale}, {"ok", c.ok},
                                                   {"failure", c.failure}};
    }
    for (const auto& c : results.terminalImpact) {
      if (c.participant != ps.name) continue;
      Json tracked = Json::array();
      for (const auto& t : c.tracked) {
        Json row = {{"lowering_m", t.lowering}, {"swing_ended", t.ok}};
        if (t.ok && !t.result.impacts.empty()) row["first_stop_impact"] = makeStopImpactJson(t.result.impacts.front());
        tracked.push_back(row);
      }
      j["terminal_impact"] = {{"knee_friction_Nm", c.frictionMoment},
                              {"bounce_lowerings_m", c.bounceLowerings},
                              {"interior_optimum", c.interiorOptimum},
                              {"without_friction", {{"bounce_lowerings_m", c.bounceLoweringsWithoutFriction},
                                                    {"fastest_lowering_m", c.fastestWithoutFriction},
                                                    {"fastest_swing_time_s", c.fastestTimeWithoutFriction},
                                                    {"interior_optimum", c.interiorOptimumWithoutFriction}}},
                              {"impacts", tracked},
                              {"findings", c.findings}};
    }
    if (ps.best >= 0) {
      const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
      j["best_lowering_m"] = b.lowering;
      j["best_swing_time_s"] = b.result.swingTime;
    } else {
      j["best_lowering_m"] = nullptr;
      j["best_swing_time_s"] = nullptr;
    }
    if (!ps.capNote.empty()) j["note"] = ps.capNote;
    if (ps.bestWithMass >= 0) {
      const auto& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
      j["best_with_added_mass"] = {{"lowering_m", b.lowering}, {"mass_kg", b.added.mass},
                                   {"distance_below_knee_m", b.added.distanceBelowKnee},
                                   {"swing_time_s", b.result.swingTime}};
    }
    if (const PublishedParticipant* pub = findPublished(ps.name)) {
      Json table4 = Json::array();
      for (const auto& row : pub->table4) {
        const SweepPoint* ours = pointAt(ps, row.lowering);
        table4.push_back({{"lowering_m", row.lowering}, {"model_s", row.model},
                          {"measured_prosthetic_s", row.measuredProsthetic},
                          {"measured_anatomical_s", row.measuredAnatomical},
                          {"ours_s", ours && ours->ok ? ours->result.swingTime : kNaN}});
      }
      j["published"] = {{"source", "Burkett et al. 2004 Tables 3 and 4"}, {"table3_model_s", pub->table3Model},
                        {"table3_measured_s", pub->table3Measured}, {"best_lowering_m", pub->predictedBestLowering},
                        {"table4", table4}};
    } else {
      j["published"] = nullptr;
    }
    if (const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name)) {
      j["fastest_lowering_interval_m"] = intervalJson(pu->fastestLowering);
      j["fastest_time_interval_s"] = intervalJson(pu->fastestTime);
      j["samples_without_swing_end"] = pu->samplesWithoutSwingEnd;
      j["sensitivity"] = sensitivityJson(*pu);
      j["uncertainty_samples"] = uncertainty->samples;
      j["seed"] = uncertainty->seed;
    }
    participants.push_back(j);
  }
  return formatJson({{"study", results.study}, {"participants", participants}});
}

namespace {

// A CSV field per RFC 4180: quoted when it holds a comma, a quote or a line break, with
// quotes doubled.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A number with `decimals` decimals; one too large for fixed notation in exponent form.
std::string csvNumber(double v, int decimals) {
  char buf[64];
  if (std::isfinite(v) && std::fabs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  else
    std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string formatSweepCsv(const SweepResults& results) {
  // status: ended (a swing time), failed (the swing ran and did not end: the report says
  // why) or not_run (an interrupted sweep never reached the point).
  std::string out = "participant,lowering_m,added_mass_kg,added_mass_below_knee_m,swing_ended,swing_time_s,"
                    "peak_knee_flexion_deg,peak_knee_flexion_time_s,bounce,min_toe_clearance_m,status\n";
  for (const auto& ps : results.participants) {
    for (const auto* list : {&ps.points, &ps.massPoints}) {
      for (const auto& pt : *list) {
        out += csvField(ps.name) + "," + csvNumber(pt.lowering, 3) + "," + csvNumber(pt.added.mass, 3) + "," +
               csvNumber(pt.added.distanceBelowKnee, 3) + ",";
        if (pt.ok) {
          out += "1," + csvNumber(pt.result.swingTime, 6) + "," + csvNumber(pt.result.peakKneeFlexion * kRadToDeg, 3) + "," +
                 csvNumber(pt.result.peakKneeFlexionTime, 6) + "," + (pt.result.bounce ? "1" : "0") + "," +
                 csvNumber(pt.result.minToeClearance, 4) + ",ended\n";
        } else {
          out += std::string("0,,,,,,") + (pt.ran ? "failed" : "not_run") + "\n";
        }
      }
    }
  }
  return out;
}

namespace {

SvgPlot makeSwingTimeFigure(const ParticipantSweep& ps, const ParticipantUncertainty* pu) {
  SvgPlot plot(800, 380);
  plot.setTitle(ps.name + ": swing time vs knee-axis lowering (cf. Burkett 2004 Fig. 4)");
  plot.setXLabel("knee-axis lowering below standard (m)");
  plot.setYLabel("swing time (s)");
  std::vector<double> x, y;
  for (const auto& pt : ps.points) {
    x.push_back(pt.lowering);
    y.push_back(pt.ok ? pt.result.swingTime : kNaN);
  }
  if (pu)
    plot.addFill(pu->bandLowerings, pu->bandP05, pu->bandP95, "5-95 % over the assumptions (docs/uncertainty.md)",
                 svgPaletteColor(0));
  plot.addLine(x, y, "this model", svgPaletteColor(0), 2.0);
  double xMax = x.empty() ? 0.2 : x.back();
  if (const PublishedParticipant* pub = findPublished(ps.name))
    for (const auto& row : pub->table4) xMax = std::max(xMax, row.lowering);
  plot.setXRange(-0.005, xMax + 0.01);
  if (const PublishedParticipant* pub = findPublished(ps.name)) {
    std::vector<double> px, pm, pp;
    for (const auto& row : pub->table4) {
      px.push_back(row.lowering);
      pm.push_back(row.model);
      pp.push_back(row.measuredProsthetic);
    }
    plot.addPoints(px, pm, "Burkett model (Table 4)", svgPaletteColor(1), 4);
    plot.addPoints(px, pp, "measured prosthetic (Table 4)", svgPaletteColor(2), 4);
    plot.addVLine(pub->predictedBestLowering, "Burkett's fastest", svgPaletteColor(1));
  }
  if (ps.best >= 0) {
    const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
    plot.addPoints({b.lowering}, {b.result.swingTime}, "our fastest", "#000000", 6);
  }
  return plot;
}

// Horizontal bars of the change in the fastest lowering when one assumption goes to the low
// or the high end of its range, largest effect on top; a dot at the end of each bar (so a
// zero change still shows) and "no swing end" in the label where a run found none.
SvgPlot makeTornadoFigure(const ParticipantUncertainty& pu) {
  const std::size_t n = pu.sensitivity.size();
  SvgPlot plot(800, 120 + 34 * static_cast<double>(n));
  plot.setTitle(pu.name + ": change in the fastest lowering, one assumption at a time");
  plot.setXLabel("fastest lowering minus nominal (m); each assumption at the low / high end of its range");
  const double nominal = pu.nominal.calcFastestLowering();
  std::vector<std::pair<double, std::string>> labels;
  double reach = 0.01;  // m: at least +-10 mm, one grid step either side
  constexpr double kOffset = 0.17;  // rows: low bar above, high bar below the row's centre
  constexpr double kBarPx = 10;
  bool labelled = false;
  for (std::size_t i = 0; i < n; ++i) {
    const SensitivityRow& r = pu.sensitivity[i];
    const double y = static_cast<double>(n - i);
    std::string label = r.name + " [" + formatAssumptionValue(r.assumption, r.lowValue) + " .. " +
                        formatAssumptionValue(r.assumption, r.highValue) + unitSuffix(r.unit) + "]";
    const double dLow = r.low.calcFastestLowering() - nominal, dHigh = r.high.calcFastestLowering() - nominal;
    if (!std::isfinite(dLow) || !std::isfinite(dHigh)) label += " (no swing end)";
    labels.emplace_back(y, label);
    const struct {
      double d, dy;
      int colour;
      const char* name;
    } ends[] = {{dLow, kOffset, 0, "low end"}, {dHigh, -kOffset, 1, "high end"}};
    for (const auto& e : ends) {
      if (!std::isfinite(e.d)) continue;
      reach = std::max(reach, std::fabs(e.d));
      plot.addLine({0.0, e.d}, {y + e.dy, y + e.dy}, labelled ? "" : e.name, svgPaletteColor(e.colour), kBarPx);
      plot.addPoints({e.d}, {y + e.dy}, "", svgPaletteColor(e.colour), 4);
    }
    labelled = labelled || (std::isfinite(dLow) && std::isfinite(dHigh));
  }
  plot.addVLine(0.0, "", "#333333", false);
  plot.setXRange(-1.15 * reach, 1.15 * reach);
  plot.setYRange(0.4, static_cast<double>(n) + 0.6);
  plot.setYTickLabels(labels, 330);
  return plot;
}

SvgPlot makeKneeFlexionFigure(const ParticipantSweep& ps, double zoneDeg) {
  SvgPlot plot(800, 380);
  plot.setTitle(ps.name + ": knee flexion during swing (cf. Burkett 2004 Fig. 3)");
  plot.setXLabel("time since toe-off (s)");
  plot.setYLabel("knee flexion (deg)");
  int colour = 0;
  for (const auto& pt : ps.points) {
    const int mm = static_cast<int>(std::lround(pt.lowering * 1000));
    if (mm % 50 != 0 || !pt.ok) continue;
    std::vector<double> deg;
    for (double q : pt.result.trajectory.kneeFlexion) deg.push_back(q * kRadToDeg);
    plot.addLine(pt.result.trajectory.time, deg, mm == 0 ? "standard" : "std +" + std::to_string(mm) + " mm",
                 svgPaletteColor(colour++), 1.8);
  }
  plot.addHBand(-100, zoneDeg, "zone of stability (< " + fmt("%.0f", zoneDeg) + " deg)", "#009E73");
  return plot;
}

SvgPlot makeFilmstrip(const std::string& title, const SwingResult& r, double hipHeight) {
  // Frames every 40 ms up to the swing end, shifted right so they do not overlap.
  const auto& tr = r.trajectory;
  const double frameStep = 0.04, shift = 0.45;
  std::vector<std::vector<double>> frameX, frameY;
  for (double t = 0; t <= r.swingTime + 1e-9 && frameX.size() < 14; t += frameStep) {
    std::size_t k = 0;
    while (k + 1 < tr.size() && tr.time[k] < t - 1e-9) ++k;
    const double dx = static_cast<double>(frameX.size()) * shift;
    frameX.push_back({dx, tr.kneeX[k] + dx, tr.ankleX[k] + dx, tr.toeX[k] + dx});
    frameY.push_back({hipHeight, tr.kneeY[k], tr.ankleY[k], tr.toeY[k]});
  }
  const double xLo = -0.6, xHi = static_cast<double>(frameX.size()) * shift + 0.3;
  const double yLo = -0.1, yHi = hipHeight + 0.1;
  // Equal scale on both axes so the leg is not distorted: about 700 px of plot width and
  // about 90 px of title and axis margins.
  SvgPlot plot(800, 90 + 700 * (yHi - yLo) / (xHi - xLo));
  plot.setTitle(title);
  plot.setXLabel("hip-thigh-shank-foot every 0.04 s from toe-off, frames shifted 0.45 m apart (m)");
  plot.setYLabel("height (m)");
  for (std::size_t f = 0; f < frameX.size(); ++f) {
    plot.addLine(frameX[f], frameY[f], "", svgPaletteColor(f % 2 ? 4 : 0), 2.2);
  }
  plot.addHLine(0.0, "", "#555555", false, true);
  plot.setXRange(xLo, xHi);
  plot.setYRange(yLo, yHi);
  plot.setLegend(false);
  return plot;
}

std::string mdRow(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) s += " " + c + " |";
  return s + "\n";
}

std::string ms(double seconds) {
  const double v = std::round(seconds * 1000);
  return v == 0 ? "0 ms" : fmt("%+.0f ms", v);
}

std::string formatUncertaintySection(const UncertaintyResults& u) {
  std::string md = "## How sure is the optimum\n\n";
  md += "The sweep above uses one value for each assumption the paper leaves out. Here each is varied over a "
        "documented range (docs/uncertainty.md: the range and its source for every row): one at a time to its low "
        "and high end (the tornado figure of each participant), and all together in " +
        std::to_string(u.samples) + " Monte Carlo samples (uniform draws, the COM rule 50/50; std::mt19937_64 seed " +
        std::to_string(u.seed) + "). The hip time scale is not recalibrated per sample: it is one ranged "
        "assumption. The interval is of the model's answer under these assumptions, not of a runner's optimum.\n\n";
  md += mdRow({"participant", "nominal fastest (m)", "median (m)", "5-95 % (m)", "swing time median (s)",
               "swing time 5-95 % (s)", "samples without a swing end"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  for (const auto& pu : u.participants) {
    md += mdRow({pu.name, formatLoweringOrNone(pu.nominal.calcFastestLowering()), fmt("%.3f", pu.fastestLowering.median),
                 fmt("%.3f", pu.fastestLowering.p05) + " - " + fmt("%.3f", pu.fastestLowering.p95),
                 fmt("%.4f", pu.fastestTime.median),
                 fmt("%.4f", pu.fastestTime.p05) + " - " + fmt("%.4f", pu.fastestTime.p95),
                 std::to_string(pu.samplesWithoutSwingEnd)});
  }
  md += "\n";
  for (const auto& pu : u.participants) {
    if (pu.sensitivity.empty()) continue;
    md += "**" + pu.name + ", one at a time** (largest change of the fastest lowering first):\n\n";
    md += mdRow({"assumption", "low", "high", "fastest at low (m)", "fastest at high (m)", "time at low (s)",
                 "time at high (s)"});
    md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
    for (const auto& r : pu.sensitivity) {
      auto t = [](double v) { return std::isfinite(v) ? fmt("%.4f", v) : std::string("no end"); };
      md += mdRow({r.name + (unitSuffix(r.unit).empty() ? "" : " (" + r.unit + ")"), formatAssumptionValue(r.assumption, r.lowValue),
                   formatAssumptionValue(r.assumption, r.highValue), formatLoweringOrNone(r.low.calcFastestLowering()),
                   formatLoweringOrNone(r.high.calcFastestLowering()), t(r.low.calcFastestTime()),
                   t(r.high.calcFastestTime())});
    }
    md += "\n";
  }
  return md;
}

}  // namespace

namespace {

// The fastest-lowering table's strike cell: only where the clearance's assumption holds.
std::string toeStrikeCell(const Participant* p, double clearance) {
  if (p != nullptr && !p->toeClearance.alarmHolds()) return "n/a (running; clearance " + fmt("%+.3f", clearance) + " m vs standing hip)";
  return clearance < 0 ? "yes" : "no";
}

// Burkett's terminal-impact findings, per participant (sweep/terminal_impact.h); "" if the
// check did not run.
std::string formatTerminalImpactSection(const SweepResults& results) {
  if (results.terminalImpact.empty()) return "";
  std::string md = "## Terminal impact: bounce and the interior optimum (Burkett's findings)\n\n";
  md += "Burkett et al. saw the knee bounce out of extension at large lowerings for every participant, and their "
        "model's swing time rise again past an interior optimum. The hyperextension stop here is a Hertz contact with a "
        "coefficient of restitution (README \"Terminal impact\"); the swing ends when the knee has settled in the zone "
        "of stability, so a bounce lengthens it. Each participant's first stop impact is booked by cause (work from "
        "contact to the top of the rebound), and the sweep is repeated without the knee friction near extension.\n\n";
  md += mdRow({"participant", "Tc (N m)", "bounces at", "interior optimum", "without friction: bounces at", "without friction: fastest (m)"});
  md += mdRow({"---", "---", "---", "---", "---", "---"});
  auto list = [](const std::vector<double>& v) {
    if (v.empty()) return std::string("none");
    std::string s;
    for (double d : v) s += (s.empty() ? "" : " ") + fmt("%.2f", d);
    return s;
  };
  for (const auto& c : results.terminalImpact) {
    md += mdRow({c.participant, fmt("%.1f", c.frictionMoment), list(c.bounceLowerings), c.interiorOptimum ? "yes" : "no",
                 list(c.bounceLoweringsWithoutFriction),
                 std::isnan(c.fastestWithoutFriction) ? "none ended" : fmt("%.3f", c.fastestWithoutFriction)});
  }
  md += "\n";
  for (const auto& c : results.terminalImpact) {
    md += "**" + c.participant + "**\n\n";
    for (const auto& f : c.findings) md += "- " + f + "\n";
    md += "\n";
  }
  return md;
}

}  // namespace

namespace {

// Table 4 as a validation set (sweep/measured_validation.h); "" if it did not run.
std::string formatTable4ValidationSection(const SweepResults& results) {
  if (results.table4.empty()) return "";
  std::string md = "## Table 4 as validation: errors against the measured swing times\n\n";
  if (results.calibratedTo == CalibrationTarget::kStored) {
    md += "The hip time scales are the participant files' (calibrated to Table 3's model column: `swingsim calibrate`). ";
  } else {
    md += std::string("This run calibrated each participant's hip time scale to Table 3's **") +
          calibrationTargetKey(results.calibratedTo) + "** column before sweeping (`calibrate_to:` in the study):\n\n";
    for (const auto& c : results.calibrations)
      md += "- " + c.participant + ": " +
            (c.ok ? "time scale " + fmt("%.4f", c.timeScale) + " gives " + fmt("%.3f", c.targetTime) + " s at the standard location"
                  : c.failure) +
            "\n";
    md += "\n";
  }
  md += "Fitted to Burkett's numbers: one hip time scale per participant, to his Table 3; nothing else (the hip moment "
        "shape, the damping table, the stop and the swing-end rule were chosen before any comparison with Table 4). "
        "Errors below are over Table 4's lowered rows (the standard-location row is Table 3, the calibration target).";
  const bool loo = results.calibratedTo != CalibrationTarget::kStored;
  if (loo)
    md += " Leave-one-out: each participant's time scale replaced by the mean of the other calibrated participants' "
          "scales, as a new runner without his own Table 3 time would be predicted.";
  md += "\n\n";
  std::vector<std::string> head = {"participant", "lowering (m)", "measured (s)", "ours (s)", "Burkett model (s)", "ours - measured",
                                   "model - measured"};
  if (loo) head.push_back("leave-one-out (s)");
  md += mdRow(head);
  md += mdRow(std::vector<std::string>(head.size(), "---"));
  auto num = [](double v) { return std::isnan(v) ? std::string("-") : fmt("%.3f", v); };
  auto diff = [](double a, double b) { return std::isnan(a) ? std::string("-") : ms(a - b); };
  std::vector<double> pooledOurs, pooledModel, pooledLoo;
  for (const auto& v : results.table4) {
    for (const auto& r : v.rows) {
      std::vector<std::string> row = {v.participant, fmt("%.3f", r.lowering), fmt("%.3f", r.measured), num(r.ours),
                                      fmt("%.3f", r.model), diff(r.ours, r.measured), diff(r.model, r.measured)};
      if (loo) row.push_back(num(r.oursLeaveOneOut));
      md += mdRow(row);
      if (r.lowering <= 0) continue;
      if (!std::isnan(r.ours)) pooledOurs.push_back(r.ours - r.measured);
      pooledModel.push_back(r.model - r.measured);
      if (!std::isnan(r.oursLeaveOneOut)) pooledLoo.push_back(r.oursLeaveOneOut - r.measured);
    }
  }
  md += "\n";
  std::vector<std::string> sumHead = {"participant", "RMSE ours (ms)", "RMSE Burkett model (ms)"};
  if (loo) sumHead.push_back("RMSE leave-one-out (ms)");
  for (const char* h : {"shortening measured (ms)", "shortening ours (ms)", "shortening Burkett model (ms)"}) sumHead.push_back(h);
  md += mdRow(sumHead);
  md += mdRow(std::vector<std::string>(sumHead.size(), "---"));
  auto msOrDash = [](double v) { return std::isnan(v) ? std::string("-") : fmt("%.0f", v * 1000); };
  for (const auto& v : results.table4) {
    std::vector<std::string> row = {v.participant + (v.calibrated || !loo ? "" : " (not calibrated)"), msOrDash(v.rmseOurs),
                                    msOrDash(v.rmseModel)};
    if (loo) row.push_back(msOrDash(v.rmseLeaveOneOut));
    for (double x : {v.shorteningMeasured, v.shorteningOurs, v.shorteningModel}) row.push_back(msOrDash(x));
    md += mdRow(row);
  }
  std::vector<std::string> all = {"all", msOrDash(calcRms(pooledOurs)), msOrDash(calcRms(pooledModel))};
  if (loo) all.push_back(msOrDash(calcRms(pooledLoo)));
  for (int k = 0; k < 3; ++k) all.push_back("");
  md += mdRow(all);
  md += "\nShortening: standard location minus the largest Table 4 lowering simulated here (positive = faster when "
        "lowered).\n\n";
  return md;
}

}  // namespace

std::map<std::string, std::string> makeSweepReport(const SweepStudy& study, const SweepResults& results,
                                                   const UncertaintyResults* uncertainty) {
  std::map<std::string, std::string> files;
  files["sweep.csv"] = formatSweepCsv(results);
  std::string md = "# Knee-axis sweep: " + study.name + "\n\n";
  md += "Generated by `swingsim sweep " + study.path + "`. Swing time is measured from toe-off until the thigh has "
        "reached its target flexion AND the knee, after its peak flexion, is back inside the zone of stability "
        "(in whichever order). All numbers below were computed by this run.\n\n";

  // Tables 3 and 4 side by side.
  md += "## Burkett 2004 Tables 3 and 4 beside this model\n\n";
  md += "Table 3 (standard location) is the calibration target: one hip-moment time scale per participant was "
        "fitted to it (`swingsim calibrate`). Table 4 is the validation set: nothing was tuned to it.\n\n";
  md += mdRow({"participant", "lowering (m)", "paper model (s)", "paper measured (s)", "ours (s)", "ours - paper model",
               "ours - measured"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  int disagree = 0;
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = findPublished(ps.name);
    if (!pub) continue;
    for (const auto& row : pub->table4) {
      const SweepPoint* ours = pointAt(ps, row.lowering);
      std::string o = "not simulated", d1 = "", d2 = "";
      if (ours && ours->ok) {
        o = fmt("%.3f", ours->result.swingTime);
        d1 = ms(ours->result.swingTime - row.model);
        d2 = ms(ours->result.swingTime - row.measuredProsthetic);
        if (std::fabs(ours->result.swingTime - row.model) > 0.020) ++disagree;
      } else if (ours) {
        o = shortFailure(*ours);
      }
      md += mdRow({ps.name, fmt("%.3f", row.lowering), fmt("%.3f", row.model), fmt("%.3f", row.measuredProsthetic), o, d1, d2});
    }
  }
  // Say, per participant, what the model's sweep did: an interior optimum as in the paper,
  // or a monotonic fall to the end of the simulated range.
  std::string shape;
  for (const auto& ps : results.participants) {
    if (ps.best < 0) continue;
    int lastOk = -1;
    for (std::size_t k = 0; k < ps.points.size(); ++k)
      if (ps.points[k].ok && ps.points[k].onGrid) lastOk = static_cast<int>(k);
    const double bestLowering = ps.points[static_cast<std::size_t>(ps.best)].lowering;
    shape += "- " + ps.name + ": ";
    if (ps.best == lastOk) {
      shape += "swing time keeps falling to the last lowering that ends a swing (" + fmt("%.3f", bestLowering) + " m)";
    } else {
      shape += "fastest at " + fmt("%.3f", bestLowering) + " m, slower beyond it (as in the paper)";
    }
    if (const PublishedParticipant* pub = findPublished(ps.name))
      shape += "; Burkett's model: fastest at " + fmt("%.3f", pub->predictedBestLowering) + " m";
    shape += ".\n";
  }
  md += "\n**Where we disagree with the paper** (" + std::to_string(disagree) +
        " rows differ from Burkett's model by more than 20 ms). At the standard location we agree by construction "
        "(calibration). What our sweep did:\n\n" + shape +
        "\nThe assumptions most likely responsible for the differences, in order: "
        "(1) the *hip moment shape*: Burkett applied each participant's measured dynamometer moment, which we do not "
        "have; ours is a smooth biphasic profile whose extension phase pulls the shank into extension at a fixed time; "
        "(2) the *swing-end rule*: where the thigh target becomes the later of the two conditions, swing time is "
        "governed by how fast the heavier, longer leg flexes at the hip rather than by the knee; "
        "(3) the *COM rule* (" +
        std::string(study.participants.front().comRule == ComRule::kFixedFromProximal ? "COMs fixed from the proximal joint" : "COMs proportional") +
        "): it sets how much shank-and-foot inertia about the hip grows as the knee is lowered.\n\n";

  md += formatTable4ValidationSection(results);

  // Fastest lowering.
  md += "## Fastest lowering per participant\n\n";
  md += mdRow({"participant", "ours (m)", "ours swing time (s)", "Burkett model (m)", "difference (m)", "bounce at ours", "toe strikes at ours"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = findPublished(ps.name);
    if (ps.best < 0) {
      md += mdRow({ps.name, "none ended", "", pub ? fmt("%.3f", pub->predictedBestLowering) : "", "", "", ""});
      continue;
    }
    const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
    md += mdRow({ps.name, fmt("%.3f", b.lowering), fmt("%.4f", b.result.swingTime),
                 pub ? fmt("%.3f", pub->predictedBestLowering) : "-",
                 pub ? fmt("%+.3f", b.lowering - pub->predictedBestLowering) : "-", b.result.bounce ? "yes" : "no",
                 toeStrikeCell(participantNamed(study, ps.name), b.result.minToeClearance)});
  }
  md += "\n";
  md += formatTerminalImpactSection(results);
  bool anyMass = false;
  for (const auto& ps : results.participants) anyMass = anyMass || ps.bestWithMass >= 0;
  if (anyMass) {
    md += "## Lowering and added shank mass together (beyond the paper)\n\n";
    md += mdRow({"participant", "lowering (m)", "added mass (kg)", "below knee (m)", "swing time (s)", "gain vs lowering alone"});
    md += mdRow({"---", "---", "---", "---", "---", "---"});
    for (const auto& ps : results.participants) {
      if (ps.bestWithMass < 0 || ps.best < 0) continue;
      const auto& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
      const double plain = ps.points[static_cast<std::size_t>(ps.best)].result.swingTime;
      md += mdRow({ps.name, fmt("%.3f", b.lowering), fmt("%.2f", b.added.mass), fmt("%.3f", b.added.distanceBelowKnee),
                   fmt("%.4f", b.result.swingTime), ms(b.result.swingTime - plain)});
    }
    md += "\n";
  }

  if (uncertainty) md += formatUncertaintySection(*uncertainty);

  for (const auto& ps : results.participants) {
    const Participant* p = participantNamed(study, ps.name);
    md += "## " + ps.name + "\n\n";
    if (!ps.capNote.empty()) md += "Note: " + ps.capNote + ".\n\n";
    const std::string base = "figures/" + makeSafeFileStem(ps.name);
    const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name);
    files[base + "-swing-time.svg"] = makeSwingTimeFigure(ps, pu).render();
    md += "![swing time vs lowering](" + base + "-swing-time.svg)\n\n";
    if (pu && !pu->sensitivity.empty()) {
      files[base + "-tornado.svg"] = makeTornadoFigure(*pu).render();
      md += "![one-at-a-time sensitivity of the fastest lowering](" + base + "-tornado.svg)\n\n";
    }
    files[base + "-knee-flexion.svg"] =
        makeKneeFlexionFigure(ps, p ? p->swingEnd.zoneOfStability * kRadToDeg : 6.0).render();
    md += "![knee flexion vs time](" + base + "-knee-flexion.svg)\n\n";
    if (p && !ps.points.empty() && ps.points.front().ok) {
      std::vector<SvgPlot> strips;
      strips.push_back(makeFilmstrip(ps.name + " at the standard knee location", ps.points.front().result, calcHipHeight(*p)));
      if (ps.best > 0) {
        const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
        strips.push_back(makeFilmstrip(ps.name + " at the fastest lowering, " + fmt("%.3f", b.lowering) + " m",
                                       b.result, calcHipHeight(*p)));
      }
      files[base + "-filmstrip.svg"] = renderStackedSvg(strips);
      md += "![stick-figure filmstrip](" + base + "-filmstrip.svg)\n\n";
    }
    SweepResults one;
    one.study = results.study;
    one.participants = {ps};
    md += "```\n" + formatSweepTables(study, one) + "```\n\n";
  }

  // Every point that ran and failed, with its full message (the tables give the short form).
  std::string failures;
  for (const auto& ps : results.participants)
    for (const auto* list : {&ps.points, &ps.massPoints})
      for (const auto& pt : *list) {
        if (!pt.ran || pt.ok) continue;
        failures += "- ";
        if (list == &ps.massPoints)
          failures += "with " + formatNumber(pt.added.mass) + " kg added " + formatNumber(pt.added.distanceBelowKnee) +
                      " m below the knee: ";
        failures += pt.failure + "\n";
      }
  if (!failures.empty()) md += "## Points that failed\n\n" + failures + "\n";

  md += "## Assumptions used in this run\n\n";
  if (!study.participants.empty()) {
    const Participant& p = study.participants.front();
    if (p.drive == SwingDrive::kHipMoment)
      md += "- Drive: hip moment (not published): " + p.hipMoment.describe() + " for " + p.name +
            "; each participant's time scale is calibrated to Table 3 (see participant YAML).\n";
    else
      md += "- Drive: " + describeDrive(p) + " (" + p.name + ").\n";
    md += "- Knee damping table (not published): " + studyKneeModelPath(study, p) +
          ", the same for everyone; viscous speed rule (moment scales with speed / 150 deg/s).\n";
    md += std::string("- COM rule: ") +
          (p.comRule == ComRule::kFixedFromProximal ? "thigh COM fixed from the hip, shank COM fixed from the knee (moves down with the knee unit)"
                                                    : "COMs keep their fraction of segment length") +
          "; inertias about the COMs unchanged (Burkett). Foot COM measured from the " +
          (p.footComFrom == FootComFrom::kToe ? "toe" : "ankle") + ".\n";
    md += "- Swing-end rule: thigh at " + fmt("%.0f", p.swingEnd.thighTargetFlexion * kRadToDeg) +
          " deg flexion AND knee back below " + fmt("%.0f", p.swingEnd.zoneOfStability * kRadToDeg) +
          " deg after its peak, in whichever order, and staying there for " + fmt("%.2f", p.swingEnd.settleDwell) +
          " s (the settle rule: a bounce out of the zone lengthens the swing to the next entry).\n";
    md += "- Toe-off: hip " + fmt("%.0f", p.initial.hipFlexion * kRadToDeg) + " deg, knee " +
          fmt("%.0f", p.initial.kneeFlexion * kRadToDeg) + " deg, zero velocities (Burkett). Knee friction Tc below 4 deg; "
          "Hunt-Crossley hyperextension stop at full extension.\n";
    md += "- Toe clearance: the lowest of ankle and toe from peak knee flexion to the swing end, with the hip at 0.530 x "
          "standing height (Winter's anthropometry, greater trochanter)" +
          (p.toeClearance.hipRiseGiven ? " + " + fmt("%.3f", p.toeClearance.hipRise) + " m (the stated hip rise)" : std::string()) +
          (p.toeClearance.alarmHolds()
               ? ". A negative value means the toe strikes the ground.\n"
               : ". Running: the body is in flight during much of the swing and the hip is higher by an amount not given "
                 "(toe_clearance.hip_rise_m), so the clearance is relative to standing hip height and no strike is "
                 "flagged.\n");
    const double converged = calcConvergedAccuracy(study.swing.integrator);
    md += std::string("- Integrator: ") + integratorName(study.swing.integrator) + ", accuracy " +
          fmt("%g", study.swing.accuracy) +
          (study.swing.accuracy <= converged
               ? " (swing times converged to 0.1 ms: README, Convergence study).\n"
               : " -- LOOSER than the " + fmt("%g", converged) +
                     " at which this integrator's swing times converge to 0.1 ms (README, Convergence study): "
                     "its swing times may be off by more than that.\n");
  }
  files["report.md"] = md;
  return files;
}

}  // namespace swingsim
