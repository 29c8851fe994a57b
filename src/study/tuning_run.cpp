#include "study/tuning_run.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "core/text_format.h"
#include "io/knee_model_knobs.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "report/tuning_report.h"
#include "study/tuning_model.h"

namespace swingsim {

TuningReportInputs makeTuningReportInputs(const TuningRun& run, const std::string& kneeFile) {
  TuningReportInputs in;
  in.studyName = run.study.name;
  in.studyPath = run.study.path;
  in.participantName = run.participantName;
  in.participantPath = run.study.participantPath;
  in.kneeModelPath = run.study.kneeModelPath;
  in.kneeFile = kneeFile;
  in.swingTimeSource = run.study.swingTimeSource;
  in.simulateCommand = formatTunedSimulateCommand(run, kneeFile);
  in.seconds = run.seconds;
  in.jobs = run.jobs;
  in.result = &run.result;
  in.chance = &run.chance;
  return in;
}

TuningRun runTuningStudy(const TuningStudy& study, int jobs, SweepRunControl& control) {
  const auto start = std::chrono::steady_clock::now();
  const TuningModel model(loadParticipant(study.participantPath), KneeModelKnobs(study.kneeModelPath), study.knobs,
                          study.lowering, study.added);
  volatile bool localStop = false;
  volatile bool* stop = control.stop != nullptr ? control.stop : &localStop;
  std::atomic<long> swings{0};
  const long stopAfter = control.stopAfterSwings;
  const TuningEvaluator evaluate = [&](const std::vector<double>& x) {
    if (*stop) throw RunError("stopped");
    if (stopAfter >= 0 && swings.fetch_add(1) >= stopAfter) {
      *stop = true;
      throw RunError("stopped");
    }
    return model.simulate(x, makeTuningSwingOptions());
  };
  ProgressReporter progress("tune " + study.name, "start points");
  TuningSettings settings = study.settings;
  settings.jobs = jobs;
  TuningRun run;
  run.study = study;
  run.jobs = jobs;
  run.participantName = model.participant().name;
  run.result = runKneeTuning(
      study.knobs, study.targets, evaluate, settings,
      [&](int done, int total) {
        if (control.poll) control.poll();
        if (control.terminal) progress.update(done, total);
      },
      stop);
  run.result.interrupted = run.result.interrupted || *stop;
  if (run.result.best.ran && !run.result.interrupted) {
    const TunedSetting t = model.at(run.result.best.knobs);
    run.tunedKnee = t.knee;
    run.tunedKnee.spec.name = t.knee.name + "-tuned";
    run.tunedKnee.spec.source = "swingsim tune " + study.path + " from " + study.kneeModelPath;
    run.lowering = t.lowering;
    run.added = t.added;
    if (study.chance.samples > 0) {
      if (control.terminal)
        std::fprintf(stderr, "tune %s: chance of meeting the hard limits, %d samples\n", study.name.c_str(),
                     study.chance.samples);
      run.chance = calcTuningChance({model.participant(), t.knee, t.lowering, t.added, makeTuningSwingOptions()},
                                    study.targets, study.chance, jobs, stop);
    }
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::string describeTunedKneeMisses(const TuningResult& r) {
  std::string out;
  for (const TargetOutcome& o : r.targets) {
    if (!o.target.hard || o.met) continue;
    const TuningQuantity q = o.target.quantity;
    out += "\nMISSES the hard limit " + std::string(tuningQuantityKey(q)) + ": " +
           fmt("%.4g", toTargetUnit(q, o.value)) + ", outside its window by " +
           fmt("%.3g", std::fabs(toTargetUnit(q, o.margin))) + " (no setting tried met it)";
  }
  if (r.resolution.ran && !r.resolution.holds) out += "\nNOT HELD at the knobs' resolution: " + r.resolution.verdict;
  return out;
}

std::string formatTunedSimulateCommand(const TuningRun& run, const std::string& kneeFile) {
  std::string c = "swingsim simulate " + run.study.participantPath + " --knee " + kneeFile;
  char buffer[96];
  // 12 digits: a value on a knob's grid prints as set (0.022, not 0.021999999999999999).
  std::snprintf(buffer, sizeof buffer, " --lowering %.12g", run.lowering);
  c += buffer;
  if (run.added.mass > 0) {
    std::snprintf(buffer, sizeof buffer, " --add-mass %.12g@%.12g", run.added.mass, run.added.distanceBelowKnee);
    c += buffer;
  }
  return c;
}

std::string formatTuningRunJson(const TuningRun& run, const std::string& kneeFile) {
  return formatTuningJson(makeTuningReportInputs(run, kneeFile));
}

void writeTuningOutputs(const TuningRun& run, const std::string& folder, const std::optional<std::string>& json,
                        const std::string& commandLine) {
  const std::string kneeFile = folder + "/tuned-knee.yaml";
  TuningReportInputs in = makeTuningReportInputs(run, kneeFile);
  in.commandLine = commandLine;
  StagedOutput staged(folder);
  const std::string header = "Tuned by swingsim tune from " + run.study.kneeModelPath + " (study " + run.study.path +
                             "); re-run: " + in.simulateCommand + describeTunedKneeMisses(run.result);
  staged.add("tuned-knee.yaml", formatKneeModelYaml(run.tunedKnee.spec, header));
  staged.add("tuning.md", formatTuningMarkdown(in));
  const std::string document = formatTuningJson(in);
  staged.add("tuning.json", document);
  staged.add("tradeoff.svg", formatTuningTradeoffSvg(in));
  if (json) staged.addBeside(*json, document);
  staged.commit();
}

}  // namespace swingsim
