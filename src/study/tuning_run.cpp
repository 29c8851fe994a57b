#include "study/tuning_run.h"

#include <atomic>
#include <chrono>
#include <cstdio>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/progress_reporter.h"
#include "io/knee_model_knobs.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "report/tuning_report.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

// The knee model, lowering and added mass at knob values.
struct TunedSetting {
  KneeModel knee;
  double lowering = 0;
  AddedMass added;
};

class TuningModel {
 public:
  explicit TuningModel(const TuningStudy& s)
      : study_(s), participant_(loadParticipant(s.participantPath)), knobs_(s.kneeModelPath), base_(loadKneeModel(s.kneeModelPath)) {
    for (const TuningKnob& k : s.knobs)
      if (k.key != kLoweringKnob && k.key != kAddedMassKnob && k.key != kAddedMassDistanceKnob) kneeKeys_.push_back(k.key);
  }
  TunedSetting at(const std::vector<double>& values) const {
    TunedSetting t;
    t.lowering = study_.lowering;
    t.added = study_.added;
    std::vector<double> kneeValues;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::string& key = study_.knobs[i].key;
      if (key == kLoweringKnob) t.lowering = values[i];
      else if (key == kAddedMassKnob) t.added.mass = values[i];
      else if (key == kAddedMassDistanceKnob) t.added.distanceBelowKnee = values[i];
      else kneeValues.push_back(values[i]);
    }
    t.knee = kneeKeys_.empty() ? base_ : knobs_.make(kneeKeys_, kneeValues);
    return t;
  }
  SwingResult simulate(const std::vector<double>& values, const SwingOptions& options) const {
    const TunedSetting t = at(values);
    return simulateSwing(makeSwingSetup(participant_, t.knee, t.lowering, t.added), options);
  }
  const Participant& participant() const { return participant_; }

 private:
  const TuningStudy& study_;
  Participant participant_;
  KneeModelKnobs knobs_;
  KneeModel base_;
  std::vector<std::string> kneeKeys_;
};

// simulate's options: the default integrator and the energy bookkeeping it turns on, so every
// swing of the tuning is the one `swingsim simulate` gives for the same files (the bookkeeping's
// extra states move the integrator's steps: without it P1's swing time differs by ~4e-5 s).
SwingOptions simulateOptions() {
  SwingOptions o;
  o.trackImpactEnergy = true;
  return o;
}

}  // namespace

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
  return in;
}

TuningRun runTuningStudy(const TuningStudy& study, int jobs, SweepRunControl& control) {
  const auto start = std::chrono::steady_clock::now();
  const TuningModel model(study);
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
    return model.simulate(x, simulateOptions());
  };
  ProgressReporter progress("tune " + study.name, "start points");
  TuningSettings settings = study.settings;
  settings.jobs = jobs;
  TuningRun run;
  run.study = study;
  run.jobs = jobs;
  run.participantName = model.participant().name;
  run.result = runKneeTuning(study.knobs, study.targets, evaluate, settings, [&](int done, int total) {
    if (control.poll) control.poll();
    if (control.terminal) progress.update(done, total);
  }, stop);
  run.result.interrupted = run.result.interrupted || *stop;
  if (run.result.best.ran && !run.result.interrupted) {
    const TunedSetting t = model.at(run.result.best.knobs);
    run.tunedKnee = t.knee;
    run.tunedKnee.spec.name = t.knee.name + "-tuned";
    run.tunedKnee.spec.source = "swingsim tune " + study.path + " from " + study.kneeModelPath;
    run.lowering = t.lowering;
    run.added = t.added;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::string formatTunedSimulateCommand(const TuningRun& run, const std::string& kneeFile) {
  std::string c = "swingsim simulate " + run.study.participantPath + " --knee " + kneeFile;
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, " --lowering %.17g", run.lowering);
  c += buffer;
  if (run.added.mass > 0) {
    std::snprintf(buffer, sizeof buffer, " --add-mass %.17g@%.17g", run.added.mass, run.added.distanceBelowKnee);
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
                             "); re-run: " + in.simulateCommand;
  staged.add("tuned-knee.yaml", formatKneeModelYaml(run.tunedKnee.spec, header));
  staged.add("tuning.md", formatTuningMarkdown(in));
  const std::string document = formatTuningJson(in);
  staged.add("tuning.json", document);
  staged.add("tradeoff.svg", formatTuningTradeoffSvg(in));
  if (json) staged.addBeside(*json, document);
  staged.commit();
}

}  // namespace swingsim
