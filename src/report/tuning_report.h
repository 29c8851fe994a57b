#pragma once
// The report of a knee tuning (sweep/knee_tuning.h): the summary printed by `swingsim tune`
// (also the top of tuning.md), the Markdown report, the JSON and the trade-off figure.
#include <string>

#include "sweep/knee_tuning.h"
#include "sweep/tuning_chance.h"

namespace swingsim {

/// What the report says beside the result; plain text, filled by the study layer.
struct TuningReportInputs {
  std::string studyName, studyPath;
  std::string participantName, participantPath;
  std::string kneeModelPath;    ///< the model tuned
  std::string kneeFile;         ///< the tuned model written
  std::string swingTimeSource;  ///< "" or where the swing-time target came from
  std::string simulateCommand;  ///< re-runs the tuned swing
  std::string commandLine;      ///< the command that ran (the report's first line)
  double seconds = 0;           ///< wall time
  int jobs = 0;                 ///< threads (0: all cores)
  const TuningResult* result = nullptr;
  /// The chance of meeting every hard limit over the assumptions' ranges; null or not ran
  /// when the study did not ask for it.
  const TuningChance* chance = nullptr;
};

/// A target quantity in its file unit (deg for angles and rates, else SI).
double toTargetUnit(TuningQuantity q, double si);

/// The summary lines: knobs, targets met or missed with margins, binding limits,
/// sensitivity, identifiability and the re-run command.
std::string formatTuningSummary(const TuningReportInputs& in);
/// One line: the knob values and the swing's quantities at `point` ("none" if no point ran).
std::string formatTuningPoint(const std::vector<TuningKnob>& knobs, const TuningPoint& point);
std::string formatTuningMarkdown(const TuningReportInputs& in);
std::string formatTuningJson(const TuningReportInputs& in);
/// Swing time against peak knee flexion over every evaluated point (feasible and not), the
/// result marked, the targets drawn.
std::string formatTuningTradeoffSvg(const TuningReportInputs& in);

}  // namespace swingsim
