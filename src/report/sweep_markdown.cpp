// report.md of a knee-axis sweep: one function per section, assembled by makeSweepReport;
// the figures it links are drawn in report/sweep_figures.cpp.
#include "report/sweep_markdown.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/text_format.h"
#include "numerics/metrics.h"
#include "report/svg_plot.h"
#include "report/sweep_figures.h"
#include "report/sweep_html.h"
#include "report/sweep_report.h"
#include "report/sweep_report_parts.h"
#include "report/sweep_symmetry_markdown.h"
#include "sweep/burkett_published.h"

namespace swingsim {

using namespace sweep_report_parts;

namespace {

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
  md +=
      "The sweep above uses one value for each assumption the paper leaves out. Here each is varied over a "
      "documented range (docs/uncertainty.md: the range and its source for every row): one at a time to its low "
      "and high end (the tornado figure of each participant), and all together in " +
      std::to_string(u.samples) + " Monte Carlo samples (uniform draws, the COM rule 50/50; std::mt19937_64 seed " +
      std::to_string(u.seed) +
      "). The hip time scale is not recalibrated per sample: it is one ranged "
      "assumption. The interval is of the model's answer under these assumptions, not of a runner's optimum.\n\n";
  md += mdRow({"participant", "nominal fastest (m)", "median (m)", "5-95 % (m)", "swing time median (s)",
               "swing time 5-95 % (s)", "samples without a swing end"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  for (const auto& pu : u.participants) {
    md += mdRow(
        {pu.name, formatLoweringOrNone(pu.nominal.calcFastestLowering()), fmt("%.3f", pu.fastestLowering.median),
         fmt("%.3f", pu.fastestLowering.p05) + " - " + fmt("%.3f", pu.fastestLowering.p95),
         fmt("%.4f", pu.fastestTime.median), fmt("%.4f", pu.fastestTime.p05) + " - " + fmt("%.4f", pu.fastestTime.p95),
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
      md +=
          mdRow({r.name + (unitSuffix(r.unit).empty() ? "" : " (" + r.unit + ")"),
                 formatAssumptionValue(r.assumption, r.lowValue), formatAssumptionValue(r.assumption, r.highValue),
                 formatLoweringOrNone(r.low.calcFastestLowering()), formatLoweringOrNone(r.high.calcFastestLowering()),
                 t(r.low.calcFastestTime()), t(r.high.calcFastestTime())});
    }
    md += "\n";
  }
  return md;
}

}  // namespace

namespace {

// The fastest-lowering table's strike cell: only where the clearance's assumption holds.
std::string toeStrikeCell(const Participant* p, const std::optional<double>& clearance) {
  if (!clearance) return "none (no clearance)";
  if (p != nullptr && !p->toeClearance.alarmHolds())
    return "n/a (running; clearance " + fmt("%+.3f", *clearance) + " m vs standing hip)";
  return *clearance < 0 ? "yes" : "no";
}

// Burkett's terminal-impact findings, per participant (sweep/terminal_impact.h); "" if the
// check did not run.
std::string formatTerminalImpactSection(const SweepResults& results) {
  if (results.terminalImpact.empty()) return "";
  std::string md = "## Terminal impact: bounce and the interior optimum (Burkett's findings)\n\n";
  md +=
      "Burkett et al. saw the knee bounce out of extension at large lowerings for every participant, and their "
      "model's swing time rise again past an interior optimum. The hyperextension stop here is a Hertz contact with a "
      "coefficient of restitution (docs/assumptions.md, \"Hyperextension stop\"); the swing ends when the knee has "
      "settled in the zone of stability, so a bounce lengthens it. Each participant's first stop impact is booked "
      "by cause (work from contact to the top of the rebound), and the sweep is repeated without the knee friction "
      "near extension.\n\n";
  md += mdRow({"participant", "Tc (N m)", "bounces at", "interior optimum", "without friction: bounces at",
               "without friction: fastest (m)"});
  md += mdRow({"---", "---", "---", "---", "---", "---"});
  auto list = [](const std::vector<double>& v) {
    if (v.empty()) return std::string("none");
    std::string s;
    for (double d : v) s += (s.empty() ? "" : " ") + fmt("%.2f", d);
    return s;
  };
  for (const auto& c : results.terminalImpact) {
    md += mdRow({c.participant, fmt("%.1f", c.frictionMoment), list(c.bounceLowerings),
                 c.interiorOptimum ? "yes" : "no", list(c.bounceLoweringsWithoutFriction),
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

// The pooled errors over Table 4's lowered rows against the measured swing times (s): ours,
// Burkett's model's, and ours with leave-one-out time scales.
struct PooledTable4Errors {
  std::vector<double> ours, model, leaveOneOut;
};

PooledTable4Errors calcPooledTable4Errors(const SweepResults& results) {
  PooledTable4Errors e;
  for (const auto& v : results.table4)
    for (const auto& r : v.rows) {
      if (r.lowering <= 0) continue;
      if (!std::isnan(r.ours)) e.ours.push_back(r.ours - r.measured);
      e.model.push_back(r.model - r.measured);
      if (!std::isnan(r.oursLeaveOneOut)) e.leaveOneOut.push_back(r.oursLeaveOneOut - r.measured);
    }
  return e;
}

// Table 4 as a validation set (sweep/measured_validation.h); "" if it did not run.
std::string formatTable4ValidationSection(const SweepResults& results) {
  if (results.table4.empty()) return "";
  std::string md = "## Table 4 as validation: errors against the measured swing times\n\n";
  if (results.calibratedTo == CalibrationTarget::kStored) {
    md +=
        "The hip time scales are the participant files' (calibrated to Table 3's model column: `swingsim calibrate`). ";
  } else {
    md += std::string("This run calibrated each participant's hip time scale to Table 3's **") +
          calibrationTargetKey(results.calibratedTo) + "** column before sweeping (`calibrate_to:` in the study):\n\n";
    for (const auto& c : results.calibrations)
      md += "- " + c.participant + ": " +
            (c.ok ? "time scale " + fmt("%.4f", c.timeScale) + " gives " + fmt("%.3f", c.targetTime) +
                        " s at the standard location"
                  : c.failure) +
            "\n";
    md += "\n";
  }
  md +=
      "Fitted to Burkett's numbers: one hip time scale per participant, to his Table 3; nothing else (the hip moment "
      "shape, the damping table, the stop and the swing-end rule were chosen before any comparison with Table 4). "
      "Errors below are over Table 4's lowered rows (the standard-location row is Table 3, the calibration target).";
  const bool loo = results.calibratedTo != CalibrationTarget::kStored;
  if (loo)
    md +=
        " Leave-one-out: each participant's time scale replaced by the mean of the other calibrated participants' "
        "scales, as a new runner without his own Table 3 time would be predicted.";
  md += "\n\n";
  std::vector<std::string> head = {"participant",       "lowering (m)",    "measured (s)",    "ours (s)",
                                   "Burkett model (s)", "ours - measured", "model - measured"};
  if (loo) head.push_back("leave-one-out (s)");
  md += mdRow(head);
  md += mdRow(std::vector<std::string>(head.size(), "---"));
  auto num = [](double v) { return std::isnan(v) ? std::string("-") : fmt("%.3f", v); };
  auto diff = [](double a, double b) { return std::isnan(a) ? std::string("-") : ms(a - b); };
  for (const auto& v : results.table4) {
    for (const auto& r : v.rows) {
      std::vector<std::string> row = {
          v.participant,        fmt("%.3f", r.lowering),  fmt("%.3f", r.measured),  num(r.ours),
          fmt("%.3f", r.model), diff(r.ours, r.measured), diff(r.model, r.measured)};
      if (loo) row.push_back(num(r.oursLeaveOneOut));
      md += mdRow(row);
    }
  }
  md += "\n";
  std::vector<std::string> sumHead = {"participant", "RMSE ours (ms)", "RMSE Burkett model (ms)"};
  if (loo) sumHead.push_back("RMSE leave-one-out (ms)");
  for (const char* h : {"shortening measured (ms)", "shortening ours (ms)", "shortening Burkett model (ms)"})
    sumHead.push_back(h);
  md += mdRow(sumHead);
  md += mdRow(std::vector<std::string>(sumHead.size(), "---"));
  auto msOrDash = [](double v) { return std::isnan(v) ? std::string("-") : fmt("%.0f", v * 1000); };
  for (const auto& v : results.table4) {
    std::vector<std::string> row = {v.participant + (v.calibrated || !loo ? "" : " (not calibrated)"),
                                    msOrDash(v.rmseOurs), msOrDash(v.rmseModel)};
    if (loo) row.push_back(msOrDash(v.rmseLeaveOneOut));
    for (double x : {v.shorteningMeasured, v.shorteningOurs, v.shorteningModel}) row.push_back(msOrDash(x));
    md += mdRow(row);
  }
  const PooledTable4Errors pooled = calcPooledTable4Errors(results);
  std::vector<std::string> all = {"all", msOrDash(calcRms(pooled.ours)), msOrDash(calcRms(pooled.model))};
  if (loo) all.push_back(msOrDash(calcRms(pooled.leaveOneOut)));
  for (int k = 0; k < 3; ++k) all.push_back("");
  md += mdRow(all);
  md +=
      "\nShortening: standard location minus the largest Table 4 lowering simulated here (positive = faster when "
      "lowered).\n\n"
      "Which physical effect, shared by every runner, would explain these rows, tested on held-out runners: "
      "`swingsim diagnose studies/burkett2004-table4.yaml` (docs/diagnosis.md, \"The sweep\"; `scripts/main-job.sh` "
      "runs it after this sweep and writes out/burkett2004-table4/report.md).\n\n";
  return md;
}

}  // namespace

namespace {

// The title and how swing time is measured.
std::string formatIntro(const SweepStudy& study) {
  const std::string by =
      study.path.empty()
          ? "Generated by swingsim from a leg given without a study file (swingsim serve's page or Python)"
          : "Generated by `swingsim sweep " + study.path + "`";
  return by +
         ". Swing time is measured from toe-off until the thigh has "
         "reached its target flexion AND the knee, after its peak flexion, is back inside the zone of stability "
         "(in whichever order). All numbers below were computed by this run.\n\n";
}

constexpr double kDisagreeSeconds = 0.020;  // s: a Table 4 row differs from Burkett's model by more than this

// How many Table 4 rows this run simulated with a swing end, and how many of them differ
// from Burkett's model by more than kDisagreeSeconds.
struct PaperAgreement {
  int compared = 0, disagree = 0;
};

PaperAgreement calcPaperAgreement(const SweepResults& results) {
  PaperAgreement a;
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = ps.published;
    if (!pub) continue;
    for (const auto& row : pub->table4) {
      const SweepPoint* ours = pointAt(ps, row.lowering);
      if (!ours || !ours->ok) continue;
      ++a.compared;
      if (std::fabs(ours->result.swingTime - row.model) > kDisagreeSeconds) ++a.disagree;
    }
  }
  return a;
}

// The index of the last on-grid point that ended a swing; -1 if none.
int lastEndedOnGrid(const ParticipantSweep& ps) {
  int lastOk = -1;
  for (std::size_t k = 0; k < ps.points.size(); ++k)
    if (ps.points[k].ok && ps.points[k].onGrid) lastOk = static_cast<int>(k);
  return lastOk;
}

// One line per participant: the fastest lowering, its interval over the assumptions when
// the uncertainty analysis ran, and Burkett's model's.
std::string formatSummaryFastest(const SweepResults& results, const UncertaintyResults* uncertainty) {
  std::string md;
  for (const auto& ps : results.participants) {
    md += "- " + ps.name + ": ";
    if (ps.best < 0) {
      md += "no lowering ended a swing";
    } else {
      const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
      md += "fastest at " + fmt("%.3f", b.lowering) + " m (swing time " + fmt("%.4f", b.result.swingTime) + " s)";
      if (const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name); pu && pu->fastestLowering.count > 0)
        md += ", 5-95 % over the assumptions " + fmt("%.3f", pu->fastestLowering.p05) + " - " +
              fmt("%.3f", pu->fastestLowering.p95) + " m";
    }
    if (const PublishedParticipant* pub = ps.published)
      md += "; Burkett's model: " + fmt("%.3f", pub->predictedBestLowering) + " m";
    md += ".\n";
  }
  return md;
}

// What to read next in the report, from what this run found.
std::string formatSummaryNext(const SweepResults& results, const UncertaintyResults* uncertainty,
                              const PaperAgreement& agreement) {
  std::vector<std::string> next;
  if (agreement.disagree > 0)
    next.push_back(
        "the " + std::to_string(agreement.disagree) +
        " Table 4 rows that differ from Burkett's model by more than 20 ms (\"Where we disagree with the paper\")");
  std::string falling;
  for (const auto& ps : results.participants)
    if (ps.best >= 0 && ps.best == lastEndedOnGrid(ps)) falling += (falling.empty() ? "" : ", ") + ps.name;
  if (!falling.empty())
    next.push_back("the swing time of " + falling +
                   ", still falling at the last lowering that ends a swing (the figures)");
  std::string strongest;
  for (const auto& ps : results.participants) {
    const ParticipantUncertainty* pu = uncertaintyOf(uncertainty, ps.name);
    if (pu && !pu->sensitivity.empty())
      strongest += (strongest.empty() ? "" : "; ") + ps.name + ": " + pu->sensitivity.front().name;
  }
  if (!strongest.empty())
    next.push_back("the assumption that moves the fastest lowering most (the tornado figures): " + strongest);
  bool failed = false;
  for (const auto& ps : results.participants)
    for (const auto* list : {&ps.points, &ps.massPoints})
      for (const auto& pt : *list) failed = failed || (pt.ran && !pt.ok);
  if (failed) next.push_back("the points that failed (\"Points that failed\")");
  if (!uncertainty) next.push_back("how sure the optimum is: rerun with `--uncertainty N`");
  std::string md = "Look next at:\n\n";
  for (const auto& n : next) md += "- " + n + ".\n";
  return next.empty() ? "" : md + "\n";
}

// A few lines before the detail: the fastest lowering per participant, the agreement with
// Burkett's Tables 3 and 4, and what to look at next.
std::string formatSummary(const SweepResults& results, const UncertaintyResults* uncertainty,
                          const PaperAgreement& agreement) {
  std::string md = "## Summary\n\n" + formatSummaryFastest(results, uncertainty) + "\n";
  md += "Agreement with the paper: " + std::to_string(agreement.compared - agreement.disagree) + " of " +
        std::to_string(agreement.compared) + " Table 4 rows simulated here are within 20 ms of Burkett's model";
  if (!results.table4.empty()) {
    const PooledTable4Errors e = calcPooledTable4Errors(results);
    auto msOrDash = [](double v) { return std::isnan(v) ? std::string("-") : fmt("%.0f", v * 1000); };
    md += "; against the measured swing times (Table 4's lowered rows) the RMSE is " + msOrDash(calcRms(e.ours)) +
          " ms here and " + msOrDash(calcRms(e.model)) + " ms for Burkett's model";
  }
  md += ".\n\n" + formatSummaryNext(results, uncertainty, agreement);
  return md;
}

// Burkett's Table 4 rows beside this run's swing times.
std::string formatTables34Rows(const SweepResults& results) {
  std::string md = mdRow({"participant", "lowering (m)", "paper model (s)", "paper measured (s)", "ours (s)",
                          "ours - paper model", "ours - measured"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = ps.published;
    if (!pub) continue;
    for (const auto& row : pub->table4) {
      const SweepPoint* ours = pointAt(ps, row.lowering);
      std::string o = "not simulated", d1 = "", d2 = "";
      if (ours && ours->ok) {
        o = fmt("%.3f", ours->result.swingTime);
        d1 = ms(ours->result.swingTime - row.model);
        d2 = ms(ours->result.swingTime - row.measuredProsthetic);
      } else if (ours) {
        o = shortFailure(*ours);
      }
      md += mdRow(
          {ps.name, fmt("%.3f", row.lowering), fmt("%.3f", row.model), fmt("%.3f", row.measuredProsthetic), o, d1, d2});
    }
  }
  return md;
}

// Per participant, what the model's sweep did: an interior optimum as in the paper, or a
// monotonic fall to the end of the simulated range.
std::string formatSweepShape(const SweepResults& results) {
  std::string shape;
  for (const auto& ps : results.participants) {
    if (ps.best < 0) continue;
    const double bestLowering = ps.points[static_cast<std::size_t>(ps.best)].lowering;
    shape += "- " + ps.name + ": ";
    if (ps.best == lastEndedOnGrid(ps)) {
      shape += "swing time keeps falling to the last lowering that ends a swing (" + fmt("%.3f", bestLowering) + " m)";
    } else {
      shape += "fastest at " + fmt("%.3f", bestLowering) + " m, slower beyond it (as in the paper)";
    }
    if (const PublishedParticipant* pub = ps.published)
      shape += "; Burkett's model: fastest at " + fmt("%.3f", pub->predictedBestLowering) + " m";
    shape += ".\n";
  }
  return shape;
}

// Tables 3 and 4 side by side, where and why this model disagrees with the paper.
std::string formatTables34Section(const SweepStudy& study, const SweepResults& results,
                                  const PaperAgreement& agreement) {
  std::string md = "## Burkett 2004 Tables 3 and 4 beside this model\n\n";
  md +=
      "Table 3 (standard location) is the calibration target: one hip-moment time scale per participant was "
      "fitted to it (`swingsim calibrate`). Table 4 is the validation set: nothing was tuned to it.\n\n";
  md += formatTables34Rows(results);
  md += "\n**Where we disagree with the paper** (" + std::to_string(agreement.disagree) +
        " rows differ from Burkett's model by more than 20 ms). At the standard location we agree by construction "
        "(calibration). What our sweep did:\n\n" +
        formatSweepShape(results) +
        "\nThe assumptions most likely responsible for the differences, in order: "
        "(1) the *hip moment shape*: Burkett applied each participant's measured dynamometer moment, which we do not "
        "have; ours is a smooth biphasic profile whose extension phase pulls the shank into extension at a fixed time; "
        "(2) the *swing-end rule*: where the thigh target becomes the later of the two conditions, swing time is "
        "governed by how fast the heavier, longer leg flexes at the hip rather than by the knee; "
        "(3) the *COM rule* (" +
        std::string(study.participants.front().comRule == ComRule::kFixedFromProximal
                        ? "COMs fixed from the proximal joint"
                        : "COMs proportional") +
        "): it sets how much shank-and-foot inertia about the hip grows as the knee is lowered.\n\n";
  return md;
}

// The fastest lowering per participant beside Burkett's model's.
std::string formatFastestSection(const SweepStudy& study, const SweepResults& results) {
  std::string md = "## Fastest lowering per participant\n\n";
  md += mdRow({"participant", "ours (m)", "ours swing time (s)", "Burkett model (m)", "difference (m)",
               "bounce at ours", "toe strikes at ours"});
  md += mdRow({"---", "---", "---", "---", "---", "---", "---"});
  for (const auto& ps : results.participants) {
    const PublishedParticipant* pub = ps.published;
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
  return md + "\n";
}

// Every jump of the swing time along the lowering, with its cause and the continuous companion
// (the knee's first entry into the zone) on both sides; says so when there is none.
std::string formatJumpsSection(const SweepResults& results) {
  std::string md = "## Jumps of the swing time\n\n";
  md +=
      "The swing ends once the knee stays inside the zone of stability, so a knee that rebounds just past the "
      "zone's edge swings a whole excursion longer than one that stops just short of it: the swing time jumps "
      "there (docs/swing-time-jumps.md). Each jump between neighbouring grid lowerings is narrowed by bisection to " +
      fmt("%.1f", kJumpBracket * 1000) +
      " mm; no symmetry lowering or interpolated time is read across one. The knee's "
      "first entry into the zone is continuous across a jump: the difference between the two columns is the "
      "settle rule's share.\n\n";
  std::string rows;
  for (const auto& ps : results.participants)
    for (const SwingTimeJump& j : ps.jumps)
      rows += mdRow({ps.name, fmt("%.4f", j.calcLowering()),
                     fmt("%.4f", j.below.swingTime) + " -> " + fmt("%.4f", j.above.swingTime),
                     fmtOrNone("%.4f", j.below.firstZoneEntry) + " -> " + fmtOrNone("%.4f", j.above.firstZoneEntry),
                     j.describeCause()});
  if (rows.empty()) return md + "No participant's swing time jumps between neighbouring grid lowerings.\n\n";
  md += mdRow({"participant", "jump at (m)", "swing time (s)", "first zone entry (s)", "cause"});
  md += mdRow({"---", "---", "---", "---", "---"});
  return md + rows + "\n";
}

// Lowering and added shank mass together; "" if no participant swept added mass.
std::string formatMassSection(const SweepResults& results) {
  bool anyMass = false;
  for (const auto& ps : results.participants) anyMass = anyMass || ps.bestWithMass >= 0;
  if (!anyMass) return "";
  std::string md = "## Lowering and added shank mass together (beyond the paper)\n\n";
  md += mdRow(
      {"participant", "lowering (m)", "added mass (kg)", "below knee (m)", "swing time (s)", "gain vs lowering alone"});
  md += mdRow({"---", "---", "---", "---", "---", "---"});
  for (const auto& ps : results.participants) {
    if (ps.bestWithMass < 0 || ps.best < 0) continue;
    const auto& b = ps.massPoints[static_cast<std::size_t>(ps.bestWithMass)];
    const double plain = ps.points[static_cast<std::size_t>(ps.best)].result.swingTime;
    md += mdRow({ps.name, fmt("%.3f", b.lowering), fmt("%.2f", b.added.mass), fmt("%.3f", b.added.distanceBelowKnee),
                 fmt("%.4f", b.result.swingTime), ms(b.result.swingTime - plain)});
  }
  return md + "\n";
}

// One participant's section: its figures (added to `files`) and its text table.
std::string formatParticipantSection(const SweepStudy& study, const SweepResults& results, const ParticipantSweep& ps,
                                     const ParticipantUncertainty* pu, std::map<std::string, std::string>& files) {
  const Participant* p = participantNamed(study, ps.name);
  std::string md = "## " + ps.name + "\n\n";
  if (!ps.capNote.empty()) md += "Note: " + ps.capNote + ".\n\n";
  const std::string base = "figures/" + makeSafeFileStem(ps.name);
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
    strips.push_back(
        makeFilmstrip(ps.name + " at the standard knee location", ps.points.front().result, calcHipHeight(*p)));
    if (ps.best > 0) {
      const auto& b = ps.points[static_cast<std::size_t>(ps.best)];
      strips.push_back(makeFilmstrip(ps.name + " at the fastest lowering, " + fmt("%.3f", b.lowering) + " m", b.result,
                                     calcHipHeight(*p)));
    }
    files[base + "-filmstrip.svg"] = renderStackedSvg(strips);
    md += "![stick-figure filmstrip](" + base + "-filmstrip.svg)\n\n";
  }
  SweepResults one;
  one.study = results.study;
  one.participants = {ps};
  return md + "```\n" + formatSweepTables(study, one) + "```\n\n";
}

// Every point that ran and failed, with its full message (the tables give the short form);
// "" if none.
std::string formatFailuresSection(const SweepResults& results) {
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
  return failures.empty() ? "" : "## Points that failed\n\n" + failures + "\n";
}

// The assumptions of this run, from the first participant (the same for everyone).
std::string formatAssumptionsSection(const SweepStudy& study) {
  std::string md = "## Assumptions used in this run\n\n";
  if (study.participants.empty()) return md;
  const Participant& p = study.participants.front();
  if (p.drive == SwingDrive::kHipMoment)
    md += "- Drive: hip moment (not published): " + p.hipMoment.describe() + " for " + p.name +
          "; each participant's time scale is calibrated to Table 3 (see participant YAML).\n";
  else
    md += "- Drive: " + describeDrive(p) + " (" + p.name + ").\n";
  md += "- Knee damping table (not published): " + studyKneeModelPath(study, p) +
        ", the same for everyone; viscous speed rule (moment scales with speed / 150 deg/s).\n";
  md += std::string("- COM rule: ") +
        (p.comRule == ComRule::kFixedFromProximal
             ? "thigh COM fixed from the hip, shank COM fixed from the knee (moves down with the knee unit)"
             : "COMs keep their fraction of segment length") +
        "; inertias about the COMs unchanged (Burkett). Foot COM measured from the " +
        (p.footComFrom == FootComFrom::kToe ? "toe" : "ankle") + ".\n";
  md += "- Swing-end rule: thigh at " + fmt("%.0f", p.swingEnd.thighTargetFlexion * kRadToDeg) +
        " deg flexion AND knee back below " + fmt("%.0f", p.swingEnd.zoneOfStability * kRadToDeg) +
        " deg after its peak, in whichever order, and staying there for " + fmt("%.2f", p.swingEnd.settleDwell) +
        " s (the settle rule: a bounce out of the zone lengthens the swing to the next entry).\n";
  md += "- Toe-off: hip " + fmt("%.0f", p.initial.hipFlexion * kRadToDeg) + " deg, knee " +
        fmt("%.0f", p.initial.kneeFlexion * kRadToDeg) +
        " deg, zero velocities (Burkett). Knee friction Tc below 4 deg; "
        "Hunt-Crossley hyperextension stop at full extension.\n";
  md +=
      "- Toe clearance: the lowest of ankle and toe from peak knee flexion to the swing end, with the hip at 0.530 x "
      "standing height (Winter's anthropometry, greater trochanter)" +
      (p.toeClearance.hipRiseGiven ? " + " + fmt("%.3f", p.toeClearance.hipRise) + " m (the stated hip rise)"
                                   : std::string()) +
      (p.toeClearance.alarmHolds()
           ? ". A negative value means the toe strikes the ground.\n"
           : ". Running: the body is in flight during much of the swing and the hip is higher by an amount not given "
             "(toe_clearance.hip_rise_m), so the clearance is relative to standing hip height and no strike is "
             "flagged.\n");
  const double converged = calcConvergedAccuracy(study.swing.integrator);
  md += std::string("- Integrator: ") + integratorName(study.swing.integrator) + ", accuracy " +
        fmt("%g", study.swing.accuracy) +
        (study.swing.accuracy <= converged
             ? " (swing times converged to 0.1 ms: docs/speed.md, \"Convergence study\").\n"
             : " -- LOOSER than the " + fmt("%g", converged) +
                   " at which this integrator's swing times converge to 0.1 ms (docs/speed.md, \"Convergence "
                   "study\"): its swing times may be off by more than that.\n");
  return md;
}

}  // namespace

std::map<std::string, std::string> makeSweepReport(const SweepStudy& study, const SweepResults& results,
                                                   const UncertaintyResults* uncertainty) {
  std::map<std::string, std::string> files;
  files["sweep.csv"] = formatSweepCsv(results);
  const PaperAgreement agreement = calcPaperAgreement(results);
  std::string md = "# Knee-axis sweep: " + study.name + "\n\n" + formatIntro(study);
  md += formatSummary(results, uncertainty, agreement);
  md += formatTables34Section(study, results, agreement);
  md += formatTable4SymmetrySection(results);
  md += formatTable4ValidationSection(results);
  md += formatFastestSection(study, results);
  md += formatJumpsSection(results);
  md += formatSymmetrySection(results, uncertainty);
  md += formatTerminalImpactSection(results);
  md += formatMassSection(results);
  if (uncertainty) md += formatUncertaintySection(*uncertainty);
  for (const auto& ps : results.participants)
    md += formatParticipantSection(study, results, ps, uncertaintyOf(uncertainty, ps.name), files);
  md += formatFailuresSection(results);
  md += formatAssumptionsSection(study);
  files["report.md"] = md;
  files["report.html"] = makeSweepReportHtml(study, results, files);
  return files;
}

}  // namespace swingsim
