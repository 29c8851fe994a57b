#include "report/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/text_format.h"
#include "io/csv_table.h"
#include "io/json_file.h"
#include "numerics/metrics.h"
#include "report/sweep_report_parts.h"
#include "report/swing_json.h"
#include "sweep/burkett_published.h"

namespace swingsim {

using namespace sweep_report_parts;

namespace {

// The JSON arrays and CSV columns hold NaN for an absent value: null in JSON, an empty field
// in CSV.
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// rad, the swing's peak knee flexion, if it had one (every ended swing has).
std::optional<double> peakFlexion(const SwingResult& r) {
  return r.peakKneeFlexion ? std::optional<double>(r.peakKneeFlexion->flexion) : std::nullopt;
}

}  // namespace

std::string formatUncertaintyTables(const UncertaintyResults& u) {
  std::string out = "\nHow sure is the optimum: " + std::to_string(u.samples) + " Monte Carlo samples, seed " +
                    std::to_string(u.seed) + " (assumptions and ranges: docs/uncertainty.md)\n";
  out +=
      "  participant  nominal_m  fastest_median_m  fastest_p05_m  fastest_p95_m  time_median_s  time_p05_s  "
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
    const PublishedParticipant* pub = ps.published;
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
        const std::optional<double>& clearance = pt.result.minToeClearance;
        std::snprintf(line, sizeof line, "  %10.3f  %12.4f  %13s  %6s  %15s  %13s  %16s%s%s\n", pt.lowering,
                      pt.result.swingTime, fmtOrNone("%.1f", peakFlexion(pt.result), kRadToDeg).c_str(),
                      pt.result.bounce ? "yes" : "no", fmtOrNone("%.3f", clearance).c_str(), paperModel.c_str(),
                      paperMeasured.c_str(), static_cast<int>(k) == ps.best ? "  <- fastest" : "",
                      clearance && *clearance < 0 && strikeAlarm ? "  (toe strikes)" : "");
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
      out += formatJumpBesideBest(ps) + "\n";
    }
    for (const SwingTimeJump& j : ps.jumps) out += "  jump: " + j.describe() + "\n";
    if (ps.symmetry.given) out += "  " + formatSymmetryLine(ps.symmetry, ps.jumps) + "\n";
    if (ps.bestWithMass >= 0) {
      const SweepPoint& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
      out += "  fastest with added shank mass: lowering " + fmt("%.3f", b.lowering) + " m + " +
             fmt("%.2f", b.added.mass) + " kg at " + fmt("%.3f", b.added.distanceBelowKnee) +
             " m below the knee: " + fmt("%.4f", b.result.swingTime) + " s\n";
    }
  }
  return out;
}

namespace {

Json intervalJson(const Interval& i) { return {{"median", i.median}, {"p05", i.p05}, {"p95", i.p95}}; }

Json sensitivityJson(const ParticipantUncertainty& pu) {
  Json rows = Json::array();
  for (const auto& r : pu.sensitivity) {
    Json row = {{"assumption", r.assumption},
                {"unit", r.unit},
                {"low_value", r.lowValue},
                {"high_value", r.highValue},
                {"fastest_lowering_low_m", r.low.calcFastestLowering()},
                {"fastest_lowering_high_m", r.high.calcFastestLowering()},
                {"time_low_s", r.low.calcFastestTime()},
                {"time_high_s", r.high.calcFastestTime()}};
    if (const SweepAssumption* a = assumptionKeyed(r.assumption); a && a->discrete) {
      row["low_choice"] = formatAssumptionValue(r.assumption, r.lowValue);
      row["high_choice"] = formatAssumptionValue(r.assumption, r.highValue);
    }
    rows.push_back(row);
  }
  return rows;
}

/// The participant's name and the sweep's per-lowering arrays (NaN where the swing did not end).
Json sweepPointsJson(const ParticipantSweep& ps) {
  std::vector<double> lowering, swing, zoneEntry, peak, clearance, bounceHeight;
  std::vector<bool> bounce, ok;
  std::vector<int> bounces;
  for (const auto& pt : ps.points) {
    lowering.push_back(pt.lowering);
    swing.push_back(pt.ok ? pt.result.swingTime : kNaN);
    zoneEntry.push_back(pt.ok ? calcFirstZoneEntry(pt.result).value_or(kNaN) : kNaN);
    peak.push_back(pt.ok ? peakFlexion(pt.result).value_or(kNaN) * kRadToDeg : kNaN);
    clearance.push_back(pt.ok ? pt.result.minToeClearance.value_or(kNaN) : kNaN);
    bounce.push_back(pt.ok && pt.result.bounce);
    bounces.push_back(pt.ok ? pt.result.bounces : 0);
    bounceHeight.push_back(pt.ok ? pt.result.bounceHeight.value_or(kNaN) * kRadToDeg : kNaN);
    ok.push_back(pt.ok);
  }
  return {{"name", ps.name},
          {"lowering_m", lowering},
          {"swing_time_s", swing},
          {"first_zone_entry_s", zoneEntry},
          {"peak_knee_flexion_deg", peak},
          {"bounce", bounce},
          {"bounces", bounces},
          {"bounce_height_deg", bounceHeight},
          {"swing_ended", ok},
          {"min_toe_clearance_m", clearance}};
}

/// The participant's Table 4 validation, with its calibration if one ran.
Json table4ValidationJson(const SweepResults& results, const Table4Validation& v) {
  Json rows = Json::array();
  for (const auto& r : v.rows)
    rows.push_back({{"lowering_m", r.lowering},
                    {"measured_s", r.measured},
                    {"burkett_model_s", r.model},
                    {"ours_s", r.ours},
                    {"ours_leave_one_out_s", r.oursLeaveOneOut}});
  Json validation = {{"calibrated_to", calibrationTargetKey(results.calibratedTo)},
                     {"calibrated", v.calibrated},
                     {"rows", rows},
                     {"rmse_ours_s", v.rmseOurs},
                     {"rmse_burkett_model_s", v.rmseModel},
                     {"rmse_leave_one_out_s", v.rmseLeaveOneOut},
                     {"shortening_measured_s", v.shorteningMeasured},
                     {"shortening_ours_s", v.shorteningOurs},
                     {"shortening_burkett_model_s", v.shorteningModel}};
  for (const auto& c : results.calibrations)
    if (c.participant == v.participant)
      validation["calibration"] = {
          {"target_s", c.targetTime}, {"time_scale", c.timeScale}, {"ok", c.ok}, {"failure", c.failure}};
  return validation;
}

/// The terminal-impact check: bounces with and without knee friction, each tracked swing's
/// first stop impact, the findings.
Json terminalImpactJson(const TerminalImpactCheck& c) {
  Json tracked = Json::array();
  for (const auto& t : c.tracked) {
    Json row = {{"lowering_m", t.lowering}, {"swing_ended", t.ok}};
    if (t.ok && !t.result.impacts.empty()) row["first_stop_impact"] = makeStopImpactJson(t.result.impacts.front());
    tracked.push_back(row);
  }
  return {{"knee_friction_Nm", c.frictionMoment},
          {"bounce_lowerings_m", c.bounceLowerings},
          {"interior_optimum", c.interiorOptimum},
          {"without_friction",
           {{"bounce_lowerings_m", c.bounceLoweringsWithoutFriction},
            {"fastest_lowering_m", c.fastestWithoutFriction},
            {"fastest_swing_time_s", c.fastestTimeWithoutFriction},
            {"interior_optimum", c.interiorOptimumWithoutFriction}}},
          {"impacts", tracked},
          {"findings", c.findings}};
}

/// Adds the fastest lowering (null when no swing ended), the cap's note, and the fastest with
/// added shank mass.
void addBestJson(const ParticipantSweep& ps, Json& j) {
  if (ps.best >= 0) {
    const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
    j["best_lowering_m"] = b.lowering;
    j["best_swing_time_s"] = b.result.swingTime;
    const SwingTimeJump* beside = jumpBesideBest(ps);
    j["best_beside_jump_m"] = beside ? Json(beside->calcLowering()) : Json(nullptr);
  } else {
    j["best_lowering_m"] = nullptr;
    j["best_swing_time_s"] = nullptr;
  }
  if (!ps.capNote.empty()) j["note"] = ps.capNote;
  if (ps.bestWithMass >= 0) {
    const auto& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
    j["best_with_added_mass"] = {{"lowering_m", b.lowering},
                                 {"mass_kg", b.added.mass},
                                 {"distance_below_knee_m", b.added.distanceBelowKnee},
                                 {"swing_time_s", b.result.swingTime}};
  }
}

/// The symmetry lowering (sweep/sweep_symmetry.h) as JSON; lowering_m and the times null
/// when no swing ended.
Json symmetryJson(const SymmetryLowering& sym) {
  const auto orNull = [&](double v) { return sym.found ? Json(v) : Json(nullptr); };
  return {{"sound_limb_swing_time_s", sym.soundTime},
          {"lowering_m", orNull(sym.lowering)},
          {"reached", sym.found && sym.reached},
          {"prosthetic_swing_time_s", orNull(sym.prostheticTime)},
          {"gap_s", orNull(sym.gap)},
          {"ratio", orNull(sym.calcRatio())},
          {"across_jump", sym.acrossJump},
          {"jump_from_m", sym.acrossJump ? Json(sym.jumpFrom) : Json(nullptr)},
          {"jump_to_m", sym.acrossJump ? Json(sym.jumpTo) : Json(nullptr)}};
}

/// Burkett's published rows for the participant beside ours, or null for one not in the paper.
Json publishedJson(const ParticipantSweep& ps) {
  const PublishedParticipant* pub = ps.published;
  if (!pub) return nullptr;
  Json table4 = Json::array();
  for (const auto& row : pub->table4) {
    const SweepPoint* ours = pointAt(ps, row.lowering);
    table4.push_back({{"lowering_m", row.lowering},
                      {"model_s", row.model},
                      {"measured_prosthetic_s", row.measuredProsthetic},
                      {"measured_anatomical_s", row.measuredAnatomical},
                      {"ours_s", ours && ours->ok ? ours->result.swingTime : kNaN}});
  }
  return {{"source", "Burkett et al. 2004 Tables 3 and 4"},
          {"table3_model_s", pub->table3Model},
          {"table3_measured_s", pub->table3Measured},
          {"best_lowering_m", pub->predictedBestLowering},
          {"table4", table4}};
}

/// Adds the uncertainty analysis's intervals and sensitivity for the participant.
void addUncertaintyJson(const ParticipantUncertainty& pu, const UncertaintyResults& uncertainty, Json& j) {
  j["fastest_lowering_interval_m"] = intervalJson(pu.fastestLowering);
  j["fastest_time_interval_s"] = intervalJson(pu.fastestTime);
  j["samples_without_swing_end"] = pu.samplesWithoutSwingEnd;
  if (pu.symmetry.given) {
    j["symmetry_lowering_interval_m"] = intervalJson(pu.symmetryLowering);
    j["symmetry_samples_not_reached"] = pu.symmetryNotReached;
  }
  j["sensitivity"] = sensitivityJson(pu);
  j["uncertainty_samples"] = uncertainty.samples;
  j["seed"] = uncertainty.seed;
}

/// One participant's object of the sweep's JSON.
Json participantJson(const SweepResults& results, const ParticipantSweep& ps, const UncertaintyResults* uncertainty) {
  Json j = sweepPointsJson(ps);
  for (const auto& v : results.table4)
    if (v.participant == ps.name) j["table4_validation"] = table4ValidationJson(results, v);
  for (const auto& c : results.terminalImpact)
    if (c.participant == ps.name) j["terminal_impact"] = terminalImpactJson(c);
  addBestJson(ps, j);
  Json jumps = Json::array();
  for (const SwingTimeJump& jump : ps.jumps) jumps.push_back(makeSwingTimeJumpJson(jump));
  j["swing_time_jumps"] = jumps;
  if (ps.symmetry.given) j["symmetry"] = symmetryJson(ps.symmetry);
  j["published"] = publishedJson(ps);
  if (const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name)) addUncertaintyJson(*pu, *uncertainty, j);
  return j;
}

}  // namespace

std::string formatSweepJson(const SweepResults& results, const UncertaintyResults* uncertainty) {
  Json participants = Json::array();
  for (const auto& ps : results.participants) participants.push_back(participantJson(results, ps, uncertainty));
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

// An empty field for an absent (NaN) value, else csvNumber.
std::string csvOptional(double v, int decimals) { return std::isnan(v) ? "" : csvNumber(v, decimals); }

}  // namespace

std::string formatSweepCsv(const SweepResults& results) {
  // status: ended (a swing time), failed (the swing ran and did not end: the report says
  // why) or not_run (an interrupted sweep never reached the point).
  std::string out =
      "participant,lowering_m,added_mass_kg,added_mass_below_knee_m,swing_ended,swing_time_s,"
      "peak_knee_flexion_deg,peak_knee_flexion_time_s,bounce,min_toe_clearance_m,status\n";
  for (const auto& ps : results.participants) {
    for (const auto* list : {&ps.points, &ps.massPoints}) {
      for (const auto& pt : *list) {
        out += csvField(ps.name) + "," + csvNumber(pt.lowering, 3) + "," + csvNumber(pt.added.mass, 3) + "," +
               csvNumber(pt.added.distanceBelowKnee, 3) + ",";
        if (pt.ok) {
          const std::optional<KneePeak>& peak = pt.result.peakKneeFlexion;
          out += "1," + csvNumber(pt.result.swingTime, 6) + "," +
                 csvOptional(peak ? peak->flexion * kRadToDeg : kNaN, 3) + "," +
                 csvOptional(peak ? peak->time : kNaN, 6) + "," + (pt.result.bounce ? "1" : "0") + "," +
                 csvOptional(pt.result.minToeClearance.value_or(kNaN), 4) + ",ended\n";
        } else {
          out += std::string("0,,,,,,") + (pt.ran ? "failed" : "not_run") + "\n";
        }
      }
    }
  }
  return out;
}

}  // namespace swingsim
