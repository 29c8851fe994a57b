#pragma once
// `swingsim tune` and Python swingsim.tune(): a knee-tuning study from its file to its
// written outputs (the tuned knee model, the report, the JSON, the trade-off figure).
#include <optional>
#include <string>

#include "model/knee_model.h"
#include "report/tuning_report.h"
#include "study/sweep_run.h"
#include "study/tuning_study.h"
#include "sweep/knee_tuning.h"

namespace swingsim {

/// The files a tuning writes into its folder.
inline const std::vector<std::string> kTuningOutputFiles = {"tuned-knee.yaml", "tuning.md", "tuning.json",
                                                            "tradeoff.svg"};

struct TuningRun {
  TuningStudy study;
  std::string participantName;
  TuningResult result;  ///< result.best re-run with simulate's options (energy bookkeeping on)
  KneeModel tunedKnee;  ///< the knee model at the result
  double lowering = 0;  ///< m, at the result
  AddedMass added;      ///< at the result
  TuningChance chance;  ///< of meeting every hard limit at the result (the study's `uncertainty:`)
  double seconds = 0;   ///< wall time of the tuning
  int jobs = 0;
};

/// Runs the tuning on `jobs` threads (0: all cores) under `control` (progress on stderr when
/// terminal; the stop flag, polled, and the test stop after N swings). Throws InputError.
TuningRun runTuningStudy(const TuningStudy& study, int jobs, SweepRunControl& control);

/// Lines for the tuned knee file's header: each hard limit the result misses, by how much, and
/// a result that does not hold at the knobs' resolution; "" when it meets them all.
std::string describeTunedKneeMisses(const TuningResult& r);

/// `swingsim simulate` arguments that re-run the tuned swing, with the tuned knee at `kneeFile`.
std::string formatTunedSimulateCommand(const TuningRun& run, const std::string& kneeFile);

/// Writes kTuningOutputFiles into `folder` and the JSON to `json` if given, as one staged
/// set: all or none. `commandLine` goes into the report.
void writeTuningOutputs(const TuningRun& run, const std::string& folder, const std::optional<std::string>& json,
                        const std::string& commandLine);

/// What the report needs of a run (its result is referred to, not copied: keep `run` alive).
TuningReportInputs makeTuningReportInputs(const TuningRun& run, const std::string& kneeFile);

/// The JSON document of a run (tuning.json; Python returns it).
std::string formatTuningRunJson(const TuningRun& run, const std::string& kneeFile);

}  // namespace swingsim
