#pragma once
// Reports of `swingsim compare` and `swingsim diagnose` for the Mauch cylinder: metric
// tables overall and per phase, residual plots (residual vs time with phases shaded, binned
// mean residual with its 99 % band against position, velocity and acceleration, residual
// autocorrelation with its 99 % band), the candidate ranking, and the JSON of issue 5.
#include <limits>
#include <string>
#include <vector>

#include "identify/cylinder_diagnosis.h"

namespace swingsim {

/// Metrics per file (ME, RMSE, R^2 %) and per phase (RMSE, share of squared error, share
/// of samples), as printed by `compare`.
std::string formatComparisonTable(const CylinderComparison& comparison);

/// The inputs of the residual panels, for any diagnosis kind (cylinder, swing).
struct ResidualPlotData {
  std::vector<double> time;              ///< s
  std::vector<double> residual;          ///< measured - model, in the unit of the labels
  std::vector<int> phase;                ///< index into phaseNames per sample
  std::vector<std::string> phaseNames;
  double plotSeconds = std::numeric_limits<double>::infinity();  ///< span shown against time
  std::string timeTitle;                 ///< title of the residual-vs-time panel
  std::string residualLabel;             ///< its y label with unit, e.g. "measured - model (N)"
  std::string meanLabel;                 ///< y label of the binned panels, e.g. "mean residual (N)"
  struct Variable {
    std::vector<double> values;          ///< one per sample
    std::string label;                   ///< with unit; the x label of its panel
    std::string title;                   ///< panel title; empty: "binned mean residual vs <label>, 99 % band ..."
  };
  std::vector<Variable> variables;       ///< binned against (position, velocity, acceleration)
};

/// Stacked panels: residual vs time with phases shaded, binned mean residual with its 99 %
/// band against each variable, residual autocorrelation with the 99 % band 2.576 / sqrt(n).
std::string renderResidualPanels(const ResidualPlotData& data, const std::string& title);

/// One SVG with five stacked panels for one record (see the header comment). Residuals in N;
/// the first `plotSeconds` of the record are shown against time.
std::string renderResidualSvg(const RecordComparison& record, const std::vector<std::string>& phaseNames,
                              double plotSeconds, const std::string& title);

/// Writes `<prefix>-<stem>-residual.svg` for every record into `outDir`; returns the paths.
std::vector<std::string> writeResidualPlots(const std::string& outDir, const std::string& prefix,
                                            const CylinderComparison& comparison, double plotSeconds);

/// `{"model", "files": {"<stem>": {"training", "me", "rmse", "r2", "phases": {"<phase>":
/// {"rmse", "share_of_squared_error", "share_of_samples"}}}}}`.
std::string formatComparisonJson(const std::string& model, const CylinderComparison& comparison);

class JsonWriter;

/// Shared by every diagnosis kind: the ranking table of one step (RMSE in `unit`, printed
/// with `rmseFormat`), one accepted effect with its parameters, intervals, where and sign,
/// and one candidate's JSON object (issue 5 keys).
std::string formatCandidateRanking(const std::vector<const EffectScore*>& candidates, const std::string& unit,
                                   const char* rmseFormat);
std::string formatAcceptedEffect(const EffectScore& score, const std::string& sentence);
/// The outcome line of one stepwise step: "  -> added X (ambiguous with Y Z)" when
/// `chosen` names an effect, "  -> no candidate passes the acceptance rule; stop" when it
/// is empty. `group` is the ambiguity group, chosen effect first.
std::string formatStepOutcome(const std::string& chosen, const std::vector<std::string>& group);
void writeCandidateJson(JsonWriter& w, const EffectScore& score, int step, const std::vector<std::string>& stems);

/// The ranking of every step, the accepted effects with parameters, and the before/after
/// table for the training and each validation file.
std::string formatDiagnosisText(const CylinderDiagnosis& diagnosis, const CylinderComparison& before,
                                const CylinderComparison& after);

/// The JSON of issue 5: baseline, candidates (every step), accepted, ambiguous, final.
std::string formatDiagnosisJson(const CylinderDiagnosis& diagnosis, const CylinderComparison& before,
                                const CylinderComparison& after);

}  // namespace swingsim
