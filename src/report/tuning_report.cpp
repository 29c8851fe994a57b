#include "report/tuning_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/units.h"
#include "io/json_file.h"
#include "report/svg_plot.h"

namespace swingsim {
namespace {

std::string format(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// `text` padded with spaces to `width` columns (at least one space after it).
std::string padded(const std::string& text, std::size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

std::string describeWindow(const TuningTarget& t) {
  const double lo = toTargetUnit(t.quantity, t.lower), hi = toTargetUnit(t.quantity, t.upper);
  if (t.lower == t.upper) return "= " + format("%.4g", lo);
  if (!std::isfinite(t.lower)) return "<= " + format("%.4g", hi);
  if (!std::isfinite(t.upper)) return ">= " + format("%.4g", lo);
  return "[" + format("%.4g", lo) + ", " + format("%.4g", hi) + "]";
}

std::string describeKind(const TuningTarget& t) { return t.hard ? "hard" : "soft, weight " + format("%g", t.weight); }

// "band [0.019, 0.025] (down: peak_knee_flexion_deg 90.2, past its limit by 0.2; up: swing time +11 ms)"
std::string describeBand(const KnobBand& b) {
  return "band [" + format("%.6g", b.low) + ", " + format("%.6g", b.high) + "] (down: " + b.lowStop +
         "; up: " + b.highStop + ")";
}

void printKnobs(std::ostringstream& s, const TuningResult& r) {
  s << "  knobs\n";
  const ResolutionCheck& res = r.resolution;
  for (std::size_t k = 0; k < r.knobs.size(); ++k) {
    const TuningKnob& knob = r.knobs[k];
    s << "    " << padded(knob.key, 36) << format("%-12.6g", r.best.knobs[k]) << "range [" << format("%g", knob.lower)
      << ", " << format("%g", knob.upper) << "]" << (knob.logScale ? " log" : "")
      << (knob.resolution > 0 ? ", step " + format("%g", knob.resolution) : "")
      << (k < r.knobAtBound.size() && r.knobAtBound[k] ? "  AT A RANGE END" : "") << "\n";
    if (k < res.bands.size()) s << "      " << describeBand(res.bands[k]) << "\n";
  }
  if (res.ran) {
    s << "  at resolution       " << (res.holds ? "" : "NOT HELD: ") << res.verdict << "\n";
    s << "  continuous optimum  " << formatTuningPoint(r.knobs, res.continuous) << "\n";
    if (!res.bands.empty())
      s << "  tolerance bands     each knob alone, in steps of its resolution, with every hard limit met and the swing "
           "time within "
        << format("%.0f", res.window * 1000) << " ms of the result's\n";
  }
}

void printTargets(std::ostringstream& s, const TuningReportInputs& in) {
  const TuningResult& r = *in.result;
  s << "  targets\n";
  for (const TargetOutcome& o : r.targets) {
    const TuningQuantity q = o.target.quantity;
    std::string key = tuningQuantityKey(q);
    s << "    " << padded(key, 24) << format("%-10.4f", toTargetUnit(q, o.value)) << "target "
      << describeWindow(o.target) << " (" << describeKind(o.target) << ")  " << (o.met ? "met" : "MISSED")
      << ", margin " << format("%+.4g", toTargetUnit(q, o.margin)) << (o.binding ? "  BINDS" : "") << "\n";
  }
  if (!in.swingTimeSource.empty()) s << "    (swing time target from " << in.swingTimeSource << ")\n";
  if (in.chance != nullptr && in.chance->ran)
    s << "  chance              " << in.chance->verdict << ", over the sweep's assumption ranges (seed "
      << in.chance->options.seed << ")\n";
}

void printSensitivity(std::ostringstream& s, const TuningResult& r) {
  s << "  sensitivity at the result (change of each target per unit of each knob; targets in their file units)\n";
  for (std::size_t k = 0; k < r.knobs.size(); ++k) {
    const std::string& key = r.knobs[k].key;
    s << "    " << padded(key, 36);
    for (std::size_t i = 0; i < r.targets.size(); ++i) {
      const TuningQuantity q = r.targets[i].target.quantity;
      const double d = r.sensitivity(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
      s << "  " << tuningQuantityKey(q) << " "
        << (std::isfinite(d) ? format("%+.4g", toTargetUnit(q, d))
                             : std::string("none (a swing beside the result failed)"));
    }
    s << "\n";
  }
}

// What stops a missed soft target: the hard limits at their edge and the knobs at a range end.
std::string describeBinding(const TuningResult& r) {
  std::string b;
  for (const TargetOutcome& o : r.targets)
    if (o.target.hard && (o.binding || !o.met))
      b += std::string(b.empty() ? "" : "; ") + "hard limit " + tuningQuantityKey(o.target.quantity) +
           (o.met ? " holds the result back (at its edge)" : " missed");
  for (std::size_t k = 0; k < r.knobs.size() && k < r.knobAtBound.size(); ++k)
    if (r.knobAtBound[k]) b += std::string(b.empty() ? "" : "; ") + "knob " + r.knobs[k].key + " at a range end";
  return b.empty() ? "none (the result is inside every range and limit)" : b;
}

// A missed target is "not found" by a local search (a start set, then a polish from its best
// few), not proof that no setting meets it (docs/tuning.md, "The search is local").
std::string describeSearch(const TuningResult& r) {
  for (const TargetOutcome& o : r.targets)
    if (!o.met)
      return "local: a missed target was not found from " + std::to_string(r.startSet.size()) +
             " start points and the polish; settings that meet it may exist (rerun with more start_points before "
             "reading "
             "it as unreachable)";
  return "";
}

}  // namespace

double toTargetUnit(TuningQuantity q, double si) { return tuningQuantityInKeyUnit(q, si); }

std::string formatTuningPoint(const std::vector<TuningKnob>& knobs, const TuningPoint& p) {
  if (!p.ran) return "none (no swing ran)";
  std::ostringstream s;
  for (std::size_t k = 0; k < knobs.size() && k < p.knobs.size(); ++k)
    s << knobs[k].key << " " << format("%.6g", p.knobs[k]) << ", ";
  s << "swing time " << format("%.4f", p.swingTime) << " s, peak knee flexion "
    << format("%.1f", p.peakKneeFlexion * kRadToDeg) << " deg, min toe clearance " << format("%.4f", p.minToeClearance)
    << " m, max stop impact " << format("%.1f", p.maxStopImpactSpeed * kRadToDeg) << " deg/s, "
    << (p.feasible() ? "meets" : "breaks") << " the hard limits, cost " << format("%.4g", p.cost);
  return s.str();
}

std::string formatTuningSummary(const TuningReportInputs& in) {
  const TuningResult& r = *in.result;
  std::ostringstream s;
  s << "tune " << in.studyName << ": " << in.participantName << ", knee model " << in.kneeModelPath << ", "
    << r.knobs.size() << " knobs; " << r.startSet.size() << " start points + " << r.polished.size()
    << " polish swings, " << format("%.1f", in.seconds) << " s\n";
  s << "  result              "
    << (r.feasible ? "meets every hard limit" : "NO SETTING MET EVERY HARD LIMIT: the least violation") << "; Ceres "
    << (r.converged ? "converged" : "stopped: " + r.stopReason) << " after " << r.iterations
    << " iterations from start point " << r.polishStart + 1 << " of the ranked start set\n";
  if (r.feasible && r.polishEnd.ran && !r.polishEnd.feasible())
    s << "  polish end          Ceres' solution breaks a hard limit (its penalty let it past); the result is the best "
         "evaluated setting that meets every one\n";
  if (r.best.dwellCutByRecord)
    s << "  record end          the measured record ends inside the settle dwell (knee in the zone, thigh at its "
         "target): the swing end is the knee's entry into the zone, the dwell unconfirmed\n";
  printKnobs(s, r);
  printTargets(s, in);
  s << "  binding             " << describeBinding(r) << "\n";
  if (const std::string search = describeSearch(r); !search.empty()) s << "  search              " << search << "\n";
  printSensitivity(s, r);
  s << "  identifiability     " << (r.identifiable ? "" : "NOT IDENTIFIABLE: ") << r.identifiability << "\n";
  if (!r.identifiable && !r.ridge.empty()) {
    s << "    ridge direction (per unit of each knob's range):";
    for (std::size_t k = 0; k < r.knobs.size(); ++k) s << " " << r.knobs[k].key << " " << format("%+.3f", r.ridge[k]);
    s << "\n";
  }
  s << "  re-run              " << in.simulateCommand << "\n";
  return s.str();
}

std::string formatTuningMarkdown(const TuningReportInputs& in) {
  std::ostringstream s;
  s << "# Knee tuning: " << in.studyName << "\n\n";
  if (!in.commandLine.empty()) s << "`" << in.commandLine << "`\n\n";
  s << "Participant " << in.participantName << " (`" << in.participantPath << "`), knee model `" << in.kneeModelPath
    << "`. Start set: a Latin hypercube over the knobs' ranges, then a bounded least-squares polish (Ceres) from the "
       "best "
       "point (those that meet every hard limit first), each hard limit a penalty that asks for a small margin inside "
       "it; "
       "the result is the best evaluated point that meets every hard limit. "
       "Soft targets cost weight x (miss / scale)^2, scales 0.01 s, 1 deg, 0.005 m, 10 deg/s. See docs/tuning.md.\n\n";
  s << "```\n" << formatTuningSummary(in) << "```\n\n";
  s << "Tuned knee model: `" << in.kneeFile
    << "`. Trade-off figure: `tradeoff.svg` (swing time against peak knee flexion "
       "over every evaluated setting).\n\n![trade-off](tradeoff.svg)\n";
  return s.str();
}

namespace {

Json finiteOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json makePointJson(const TuningPoint& p, const char* stage) {
  Json j;
  j["stage"] = stage;
  j["knobs"] = p.knobs;
  j["ran"] = p.ran;
  j["feasible"] = p.feasible();
  j["swing_time_s"] = finiteOrNull(p.swingTime);
  j["peak_knee_flexion_deg"] = finiteOrNull(p.peakKneeFlexion * kRadToDeg);
  j["min_toe_clearance_m"] = finiteOrNull(p.minToeClearance);
  j["max_stop_impact_deg_s"] = p.ran ? Json(p.maxStopImpactSpeed * kRadToDeg) : Json(nullptr);
  j["cost"] = finiteOrNull(p.cost);
  j["settle_dwell_cut_by_record"] = p.dwellCutByRecord;
  if (!p.ran) j["failure"] = p.failure;
  return j;
}

Json makeTargetsJson(const TuningResult& r) {
  Json targets = Json::array();
  for (std::size_t i = 0; i < r.targets.size(); ++i) {
    const TargetOutcome& o = r.targets[i];
    const TuningQuantity q = o.target.quantity;
    Json t;
    t["quantity"] = tuningQuantityKey(q);
    t["min"] = finiteOrNull(toTargetUnit(q, o.target.lower));
    t["max"] = finiteOrNull(toTargetUnit(q, o.target.upper));
    t["hard"] = o.target.hard;
    t["weight"] = o.target.hard ? Json(nullptr) : Json(o.target.weight);
    t["value"] = toTargetUnit(q, o.value);
    t["margin"] = toTargetUnit(q, o.margin);
    t["met"] = o.met;
    t["binding"] = o.binding;
    Json sensitivity;
    for (std::size_t k = 0; k < r.knobs.size(); ++k)
      sensitivity[r.knobs[k].key] =
          finiteOrNull(toTargetUnit(q, r.sensitivity(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k))));
    t["sensitivity"] = sensitivity;
    targets.push_back(t);
  }
  return targets;
}

}  // namespace

std::string formatTuningJson(const TuningReportInputs& in) {
  const TuningResult& r = *in.result;
  Json j;
  j["study"] = in.studyPath;
  j["participant"] = in.participantPath;
  j["knee_model"] = in.kneeModelPath;
  j["tuned_knee_model"] = in.kneeFile;
  j["simulate_command"] = in.simulateCommand;
  j["seconds"] = in.seconds;
  j["feasible"] = r.feasible;
  j["interrupted"] = r.interrupted;
  j["converged"] = r.converged;
  j["iterations"] = r.iterations;
  j["polish_start_rank"] = r.polishStart + 1;
  j["polish_end"] = makePointJson(r.polishEnd, "polish end");
  j["stop_reason"] = r.stopReason;
  j["evaluations"] = r.evaluations;
  Json knobs = Json::array();
  const ResolutionCheck& res = r.resolution;
  for (std::size_t k = 0; k < r.knobs.size(); ++k) {
    Json knob = {{"key", r.knobs[k].key},
                 {"min", r.knobs[k].lower},
                 {"max", r.knobs[k].upper},
                 {"log_scale", r.knobs[k].logScale},
                 {"value", r.best.knobs[k]},
                 {"resolution", r.knobs[k].resolution > 0 ? Json(r.knobs[k].resolution) : Json(nullptr)},
                 {"at_range_end", k < r.knobAtBound.size() && r.knobAtBound[k]}};
    if (k < res.bands.size())
      knob["tolerance_band"] = {{"low", res.bands[k].low},
                                {"high", res.bands[k].high},
                                {"low_stop", res.bands[k].lowStop},
                                {"high_stop", res.bands[k].highStop}};
    knobs.push_back(knob);
  }
  j["knobs"] = knobs;
  if (res.ran) {
    Json corners = Json::array();
    for (const TuningPoint& p : res.corners) corners.push_back(makePointJson(p, "rounding neighbour"));
    j["resolution"] = {{"holds", res.holds},
                       {"verdict", res.verdict},
                       {"cells_tried", res.cellsTried},
                       {"tolerance_window_s", res.window},
                       {"continuous", makePointJson(res.continuous, "continuous")},
                       {"neighbours", corners}};
  }
  j["targets"] = makeTargetsJson(r);
  if (in.chance != nullptr && in.chance->ran) {
    const TuningChance& c = *in.chance;
    Json misses = Json::object();
    for (std::size_t t = 0; t < r.targets.size() && t < c.misses.size(); ++t)
      if (r.targets[t].target.hard) misses[tuningQuantityKey(r.targets[t].target.quantity)] = c.misses[t];
    j["chance_of_meeting_hard_limits"] = {{"samples", c.options.samples},
                                          {"seed", c.options.seed},
                                          {"met", c.met},
                                          {"chance", c.chance()},
                                          {"ci95", {c.low, c.high}},
                                          {"failed", c.failed},
                                          {"misses", misses},
                                          {"nominal_swing_time_s", c.nominalSwingTime},
                                          {"verdict", c.verdict}};
  }
  j["swing"] = makePointJson(r.best, "result");
  j["identifiable"] = r.identifiable;
  j["identifiability"] = r.identifiability;
  j["ridge"] = r.ridge;
  Json points = Json::array();
  for (const TuningPoint& p : r.startSet) points.push_back(makePointJson(p, "start"));
  for (const TuningPoint& p : r.polished) points.push_back(makePointJson(p, "polish"));
  j["points"] = points;
  return formatJson(j);
}

std::string formatTuningTradeoffSvg(const TuningReportInputs& in) {
  const TuningResult& r = *in.result;
  SvgPlot plot(800, 420);
  plot.setTitle(in.studyName + ": swing time against peak knee flexion over every evaluated setting");
  plot.setXLabel("peak knee flexion (deg)");
  plot.setYLabel("swing time (s)");
  std::vector<double> fx, fy, ix, iy;
  for (const auto* set : {&r.startSet, &r.polished})
    for (const TuningPoint& p : *set) {
      if (!p.ran) continue;
      (p.feasible() ? fx : ix).push_back(p.peakKneeFlexion * kRadToDeg);
      (p.feasible() ? fy : iy).push_back(p.swingTime);
    }
  for (const TargetOutcome& o : r.targets) {
    const TuningTarget& t = o.target;
    if (t.quantity == TuningQuantity::kPeakKneeFlexion && std::isfinite(t.lower) && std::isfinite(t.upper))
      plot.addBand(t.lower * kRadToDeg, t.upper * kRadToDeg, "peak flexion target", svgPaletteColor(2));
    else if (t.quantity == TuningQuantity::kPeakKneeFlexion)
      plot.addVLine((std::isfinite(t.lower) ? t.lower : t.upper) * kRadToDeg, "peak flexion limit", svgPaletteColor(2));
    if (t.quantity == TuningQuantity::kSwingTime && t.lower == t.upper)
      plot.addHLine(t.lower, "swing time target", "#555555");
  }
  plot.addPoints(ix, iy, "breaks a hard limit", svgPaletteColor(5), 2.5);
  plot.addPoints(fx, fy, "meets the hard limits", svgPaletteColor(1), 3);
  if (r.best.ran) plot.addPoints({r.best.peakKneeFlexion * kRadToDeg}, {r.best.swingTime}, "result", "#000000", 6);
  return plot.render();
}

}  // namespace swingsim
