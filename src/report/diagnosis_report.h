#pragma once
// Reports of `swingsim compare` and `swingsim diagnose`, the same for every plant: metric
// tables overall and per phase, residual plots (residual vs time with phases shaded, binned
// mean residual with its 99 % band against each state variable, residual autocorrelation
// with its 99 % band), the candidate ranking of every step, the accepted effects with their
// intervals, the before/after table, and one JSON schema (docs/diagnosis.md, "JSON").
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "identify/comparison.h"
#include "identify/diagnosis_engine.h"
#include "io/json_file.h"

namespace swingsim {

/// Metrics per record (ME, RMSE, R^2 %, mean residual) and per phase (ME, RMSE, bias,
/// share of squared error, share of samples), as printed by `compare`.
std::string formatComparisonTable(const Comparison& comparison);

/// The inputs of the residual panels.
struct ResidualPlotData {
  std::vector<double> time;      ///< s
  std::vector<double> residual;  ///< measured - model, in the unit of the labels
  std::vector<int> phase;        ///< index into phaseNames per sample
  std::vector<std::string> phaseNames;
  double plotSeconds = std::numeric_limits<double>::infinity();  ///< span shown against time
  std::string timeTitle;                                         ///< title of the residual-vs-time panel
  std::string residualLabel;                                     ///< its y label with unit, e.g. "measured - model (N)"
  std::string meanLabel;                 ///< y label of the binned panels, e.g. "mean residual (N)"
  std::vector<StateVariable> variables;  ///< binned against (position, velocity, acceleration, ...)
};

/// Stacked panels: residual vs time with phases shaded, binned mean residual with its 99 %
/// band against each variable, residual autocorrelation with the 99 % band 2.576 / sqrt(n).
std::string renderResidualPanels(const ResidualPlotData& data, const std::string& title);

/// The panels of one record of a comparison.
std::string renderResidualSvg(const RecordComparison& record, const Comparison& comparison, const std::string& title);

/// Writes `<prefix>-<stem>-residual.svg` for every record into `outDir`, and for a plant
/// with a second quantity (the swing) `<prefix>-<stem>-overlay.svg` (report/overlay_plot.h,
/// with the knee moment of `heldBack` when given); returns the paths.
std::vector<std::string> writeResidualPlots(const std::string& outDir, const std::string& prefix,
                                            const Comparison& comparison, const HeldBackComparison* heldBack = nullptr);

/// `{"model", "quantity", "unit", "files": {"<stem>": {"training", "me", "rmse", "r2",
/// "phases": {"<phase>": {"rmse", "share_of_squared_error", "share_of_samples"}}}}}`.
Json makeComparisonJson(const std::string& model, const Comparison& comparison);

/// The ranking table of one step (RMSE in `unit` with `decimals`).
std::string formatCandidateRanking(const std::vector<const EffectScore*>& candidates, const std::string& unit,
                                   int decimals);
/// One accepted effect with its parameters, intervals, where it acted and its sign.
std::string formatAcceptedEffect(const EffectScore& score, const std::string& sentence);
/// The outcome line of one stepwise step: "  -> added X (ambiguous with Y Z)" when
/// `chosen` names an effect, "  -> no candidate passes the acceptance rule; stop" when it
/// is empty. `group` is the ambiguity group, chosen effect first.
std::string formatStepOutcome(const std::string& chosen, const std::vector<std::string>& group);

/// One base-model parameter: "<prefix><name><verb> value (95 % CI lower .. upper[; how])".
std::string formatBaseParameter(const std::string& prefix, const std::string& verb, const EffectParameter& p);

/// The ranking of every step, the accepted effects with parameters, the base model's own
/// parameters, the before/after table for every record, and the verdict on the residual.
std::string formatDiagnosisText(const Diagnosis& diagnosis, const Comparison& before, const Comparison& after);

/// The diagnosis JSON (docs/diagnosis.md, "JSON"): plant, unit, baseline, candidates (every
/// step), accepted, ambiguous, final, base_parameters, residual_white, structure.
Json makeDiagnosisJson(const Diagnosis& diagnosis, const Comparison& before, const Comparison& after);

/// The held-back comparison before and after the diagnosis (the swing's knee moment
/// against inverse dynamics): one line per record and the totals, RMSE and correlation.
std::string formatHeldBackText(const HeldBackComparison& before, const HeldBackComparison& after);
/// `{"quantity", "unit", "note", "before": {"rmse", "correlation", "files": {"<stem>":
/// {"training", "rmse", "correlation"}}}, "after": {...}}` (docs/diagnosis.md, "JSON").
Json makeHeldBackJson(const HeldBackComparison& before, const HeldBackComparison& after);
/// What `swingsim diagnose --json` writes: makeDiagnosisJson, plus "knee_moment_comparison"
/// (makeHeldBackJson) when both held-back comparisons are there.
Json makeDiagnoseJson(const Diagnosis& diagnosis, const Comparison& before, const Comparison& after,
                      const std::optional<HeldBackComparison>& heldBefore,
                      const std::optional<HeldBackComparison>& heldAfter);
/// Measured and model (before, after) against time, one panel per record, SVG.
std::string renderHeldBackSvg(const HeldBackComparison& before, const HeldBackComparison& after,
                              const std::string& title);

}  // namespace swingsim
