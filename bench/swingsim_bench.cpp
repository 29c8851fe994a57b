// Google Benchmark programs (docs/speed.md). Run them with `bash scripts/bench.sh` (build, run
// with repetitions, report medians and ratios). `swingsim_bench --convergence` runs the
// convergence study instead (convergence_study.cpp).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <thread>

#include "bench_inputs.h"
#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "identify/cylinder_plant.h"
#include "io/bench_csv.h"
#include "io/yaml_reader.h"
#include "knee/knee_added_effects.h"
#include "knee/knee_expression.h"
#include "leg/leg_model.h"
#include "report/cylinder_fit_report.h"
#include "study/cylinder_study.h"
#include "study/diagnosis_study.h"
#include "sweep/sweep_uncertainty.h"
#include "swing/reference_swing.h"
#include "swing/simbody_ode.h"

namespace swingsim::bench {
namespace {

// benchmark::DoNotOptimize on a copy: with g++ 12 and Debian's Google Benchmark 1.7 its
// "+m,r" constraint may pick a register and leave a double it was given clobbered (the
// reference swing time read back as 1e-310).
template <class T>
void keep(T value) {
  benchmark::DoNotOptimize(value);
}

const LoadedParticipant& p1() {
  static const LoadedParticipant p("participants/p1.yaml");
  return p;
}

// One P1 swing at the standard location through the full Simbody path (build the leg,
// integrate, find the swing end, sample the trajectory). Argument: 0 = the converged
// defaults the README and the CLI use (fast path, our Dormand-Prince stepping Simbody's
// realizations); 1 = the plain path before the fast path (Simbody's Runge-Kutta-Merson at 1e-4
// with Simbody event handlers); 2 = the fast path on Simbody's Runge-Kutta-Merson at 1e-4
// (the default before Dormand-Prince); 3 = the fast path on Simbody's Runge-Kutta 3 at
// 1e-3, its cheapest converged Simbody setting.
void BM_SwingSimbody(benchmark::State& state) {
  const SwingSetup setup = p1().setup();
  SwingOptions options;
  switch (state.range(0)) {
    case 1:
      options = makePlainPathOptions(1e-4, SwingOptions{}.eventWindow);
      break;
    case 2:
      options.integrator = SwingIntegrator::kRungeKuttaMerson;
      options.accuracy = 1e-4;
      break;
    case 3:
      options.integrator = SwingIntegrator::kRungeKutta3;
      options.accuracy = 1e-3;
      break;
    default:
      break;
  }
  SwingResult r;
  for (auto _ : state) {
    r = simulateSwing(setup, options);
    keep(r.swingTime);
  }
  state.counters["swing_time_ms"] = 1e3 * r.swingTime;
  state.counters["steps"] = r.steps;
  state.counters["realizations"] = r.realizations;
  state.counters["realizations_to_end"] = r.realizationsToEnd;  // the rest integrate the bounce window
}
BENCHMARK(BM_SwingSimbody)->ArgName("variant")->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

// One P1 swing (set-up included) with an added knee damper of 0.3 N m s/rad: argument 0 as
// the library's record (KneeAddedEffects), 1 as a user's expression "-c * knee_rate_rad_s"
// (knee/knee_expression.h, muparser). Issue 54: the expression at most 1.2x the library's.
void BM_SwingAddedDamper(benchmark::State& state) {
  KneeLawSum law = *p1().knee;
  if (state.range(0) == 0) {
    KneeAddedEffectsParams damper;
    damper.viscousDamping = 0.3;
    law.add(std::make_unique<KneeAddedEffects>(damper));
  } else {
    law.add(std::make_unique<KneeExpressionMoment>(
        KneeExpressionParams{"damper", "-c * knee_rate_rad_s", {{"c", "N m s/rad", 0.3}}}));
  }
  const auto shared = std::make_shared<const KneeLawSum>(std::move(law));
  SwingResult r;
  for (auto _ : state) {
    r = simulateSwing(makeSwingSetup(p1().participant, shared, 0.0), SwingOptions{});
    keep(r.swingTime);
  }
  state.counters["swing_time_ms"] = 1e3 * r.swingTime;
  state.counters["realizations"] = r.realizations;
}
BENCHMARK(BM_SwingAddedDamper)->ArgName("expression")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// One realization of the P1 leg to the Acceleration stage, as the default integrator asks
// for it (SimbodyOde: write t, q, u, realize, read the derivatives), at a new state each
// time. Its cost times BM_SwingSimbody's realization count says how much of a swing is
// Simbody's realization and how much is the rest.
void BM_RealizeLeg(benchmark::State& state) {
  const LoadedParticipant& p = p1();
  const LegModel leg(calcLegGeometry(p.participant, 0.0), *p.knee, p.participant.hipMoment, p.participant.hipRange,
                     calcHipHeight(p.participant), /*trackWork=*/false);
  const SimTK::State initial = leg.makeInitialState(p.participant.initial);
  SimTK::State work = initial;
  const SimbodyOde ode(leg.getSystem(), work);
  std::vector<double> y(ode.numStates()), dydt(ode.numStates());
  ode.readState(initial, y.data());
  double t = 0;
  for (auto _ : state) {
    t += 1e-6;
    y[1] += 1e-7;  // knee flexion: every call is a new state
    ode.calcDerivatives(t, y.data(), dydt.data());
    keep(dydt[2]);
  }
}
BENCHMARK(BM_RealizeLeg)->Unit(benchmark::kMicrosecond);

// The same swing with the hand-derived 2-DOF reference (own Dormand-Prince), same
// swing-end rule. Argument: -log10 of the Dormand-Prince relative and absolute tolerance;
// 0 = the default swing's accuracy (SwingOptions{}, 1e-5); 6 = 1e-6, converged to about
// 0.01 ms on this reference, the figure the README's ratio uses. Building the reference is
// inside the loop, as building the Simbody system is above.
void BM_SwingReference(benchmark::State& state) {
  const LoadedParticipant& p = p1();
  const double tolerance =
      state.range(0) == 0 ? SwingOptions{}.accuracy : std::pow(10.0, -static_cast<double>(state.range(0)));
  const LegGeometry geometry = calcLegGeometry(p.participant, 0.0);
  ReferenceSwingEnd end;
  for (auto _ : state) {
    const ReferenceSwing reference(geometry, *p.knee, p.participant.hipMoment, p.participant.hipRange);
    end = reference.calcSwingEnd(p.participant.initial, p.participant.swingEnd, tolerance, tolerance);
    keep(end.swingTime);
  }
  state.counters["swing_time_ms"] = 1e3 * end.swingTime;
  state.counters["steps"] = static_cast<double>(end.steps);
}
BENCHMARK(BM_SwingReference)->ArgName("tol_exp")->Arg(0)->Arg(6)->Unit(benchmark::kMillisecond);

// The plain Burkett sweep (4 participants x 21 lowerings) on N threads; N = 0 means all
// cores (std::thread::hardware_concurrency).
void BM_SweepBurkett(benchmark::State& state) {
  static const SweepStudy study = plainBurkettSweep();
  const int jobs = static_cast<int>(state.range(0));
  int swings = 0;
  for (auto _ : state) {
    const SweepResults r = runSweep(study, jobs);
    swings = 0;
    for (const auto& ps : r.participants) swings += static_cast<int>(ps.points.size());
    keep(swings);
  }
  state.counters["swings"] = swings;
  state.counters["threads"] = jobs > 0 ? jobs : static_cast<int>(std::thread::hardware_concurrency());
}
BENCHMARK(BM_SweepBurkett)->ArgName("jobs")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Fitting both Mauch models (2- and 4-phase) on the training file and evaluating them on
// all three bench files of studies/mauch2014.yaml. Files are read once, outside the loop.
void BM_FitMauch(benchmark::State& state) {
  YamlMap yaml = YamlMap::loadFile(sourcePath("studies/mauch2014.yaml"));
  yaml.getChoice("kind", {"cylinder-fit"}, "");
  const CylinderFitStudy study = readCylinderFitStudy(yaml);
  std::vector<MauchCylinderParams> models;
  for (const auto& path : study.models) models.push_back(loadMauchCylinder(path));
  std::vector<BenchData> train, validate;
  for (const auto& path : study.train) train.push_back(readBenchCsv(path, 13));
  for (const auto& path : study.validate) validate.push_back(readBenchCsv(path, 3));
  const bool fitSwitches = state.range(0) != 0;
  for (auto _ : state) {
    for (const auto& model : models) {
      CylinderFitOptions options;
      options.fitSwitches = fitSwitches;
      const CylinderFit fit = fitCylinder(model, train, options);
      const auto files = evaluateFiles(MauchCylinder(fit.params), train, validate);
      keep(files.size());
    }
  }
  state.counters["models"] = static_cast<double>(models.size());
  state.counters["files"] = static_cast<double>(train.size() + validate.size());
}
// fit_switches 0: the linear regression at the model file's switch constants (Chien's
// procedure); 1: switch constants too (multi-start variable projection with Ceres).
BENCHMARK(BM_FitMauch)->ArgName("fit_switches")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The cylinder diagnosis demo (`swingsim diagnose studies/diagnose-demo-cylinder.yaml`):
// baseline fit, candidate ranking, refits and the comparison before and after. Files are
// read once, outside the loop.
void BM_DiagnoseCylinder(benchmark::State& state) {
  const DiagnosisStudy study = loadDiagnosisStudy(sourcePath("studies/diagnose-demo-cylinder.yaml"));
  const auto plant = loadDiagnosisPlant(study, 8);
  std::size_t accepted = 0;
  for (auto _ : state) {
    const Diagnosis diagnosis = runDiagnosis(*plant, study.settings);
    const Comparison before = plant->compare(*diagnosis.baseline.model);
    const Comparison after = plant->compare(*diagnosis.final.model);
    accepted = diagnosis.accepted.size();
    keep(before.records.size() + after.records.size());
  }
  state.counters["accepted_effects"] = static_cast<double>(accepted);
}
BENCHMARK(BM_DiagnoseCylinder)->Unit(benchmark::kMillisecond);

// The swing diagnosis demo (`swingsim diagnose studies/diagnose-demo-swing.yaml`, three
// trials: train on one, hold out two), files read once outside the loop.
void BM_DiagnoseSwing(benchmark::State& state) {
  const DiagnosisStudy study = loadDiagnosisStudy(sourcePath("studies/diagnose-demo-swing.yaml"));
  const auto plant = loadDiagnosisPlant(study, 8);
  std::size_t accepted = 0;
  for (auto _ : state) {
    const Diagnosis diagnosis = runDiagnosis(*plant, study.settings);
    accepted = diagnosis.accepted.size();
  }
  state.counters["accepted"] = static_cast<double>(accepted);
}
BENCHMARK(BM_DiagnoseSwing)->Unit(benchmark::kMillisecond)->Iterations(1);

// The Monte Carlo of `sweep studies/burkett2004.yaml --uncertainty N` on 1 and 2
// threads, as that command runs it (planSweepUncertainty + runUncertaintySwings), with 20
// samples (1,764 swings: the nominal run and 20 samples of the 84-point grid; the
// one-at-a-time runs left out) instead of 1000 (84,000 swings, minutes): bench.sh extrapolates the time to 84,000
// swings and says so. One iteration per repetition, three repetitions whatever bench.sh's REPS (each is 5-10 s).
void BM_UncertaintyBurkett(benchmark::State& state) {
  static const SweepStudy study = plainBurkettSweep();
  UncertaintyOptions options;
  options.samples = 20;
  options.seed = 1;
  options.sensitivity = false;
  const int jobs = static_cast<int>(state.range(0));
  std::size_t swings = 0;
  for (auto _ : state) {
    const UncertaintyPlan plan = planSweepUncertainty(study, options);
    UncertaintySwingTimes times = UncertaintySwingTimes::makeEmpty(plan.swingCount);
    runUncertaintySwings(plan, 0, plan.swingCount, times, jobs);
    swings = times.countFinished();
    keep(swings);
  }
  state.counters["swings"] = static_cast<double>(swings);
  state.counters["samples"] = options.samples;
  state.counters["threads"] = jobs;
}
BENCHMARK(BM_UncertaintyBurkett)
    ->ArgName("jobs")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->Repetitions(3);

}  // namespace
}  // namespace swingsim::bench

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--convergence") == 0) {
      try {
        return swingsim::bench::runConvergenceStudy(argc, argv);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "swingsim_bench: %s\n", e.what());
        return 1;
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
