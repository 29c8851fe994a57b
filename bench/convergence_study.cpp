// The convergence study (docs/speed.md): swing time against the integrator, its accuracy, the
// knee friction smoothing width and the hyperextension stop stiffness, for every bundled
// participant. Prints Markdown tables (README "Convergence study").
//
//   swingsim_bench --convergence [--out FILE.md]
//
// Reference: the plain path (Simbody event handlers localizing to 1e-9 s) with
// Runge-Kutta-Merson at accuracy 1e-10. Errors are the largest over each participant's
// standard location, 0.100 m and its largest lowering in the Burkett sweep where a swing
// ends.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_inputs.h"
#include "knee/joint_stop.h"

namespace swingsim::bench {
namespace {

constexpr double kReferenceAccuracy = 1e-10;  // Simbody relative accuracy of the reference
constexpr double kReferenceWindow = 1e-9;     // s, event localization window of the reference
constexpr double kConvergedTol = 1e-4;        // s: "swing time converged to 0.1 ms"

struct Config {
  const LoadedParticipant* participant;
  double lowering;
  double referenceTime = 0;
};

struct Run {
  double swingTime = 0;
  int steps = 0, realizations = 0;
  double seconds = 0;  // wall clock of simulateSwing
  bool ok = false;
};

Run runOnce(const SwingSetup& setup, const SwingOptions& options) {
  Run r;
  const auto start = std::chrono::steady_clock::now();
  try {
    const SwingResult result = simulateSwing(setup, options);
    r.swingTime = result.swingTime;
    r.steps = result.steps;
    r.realizations = result.realizations;
    r.ok = true;
  } catch (const std::exception&) {
    r.ok = false;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

SwingOptions referenceOptions() {
  SwingOptions o = makePlainPathOptions(kReferenceAccuracy, kReferenceWindow);
  o.recordTrajectory = false;
  return o;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The knee law of `p` with the hyperextension stop stiffness and the friction smoothing
// width replaced (0 = keep).
KneeLawSum makeVariantKnee(const LoadedParticipant& p, double stopStiffness, double frictionWidth) {
  KneeLawSum law;
  for (std::size_t i = 0; i < p.model.law.size(); ++i) {
    const KneeLaw& part = p.model.law.part(i);
    if (const auto* stop = dynamic_cast<const JointStop*>(&part); stop && stopStiffness > 0) {
      JointStopParams params = stop->params();
      params.stiffness = stopStiffness;
      law.add(std::make_unique<JointStop>(params));
    } else {
      law.add(part.clone());
    }
  }
  KneeFrictionParams friction;
  if (frictionWidth > 0) friction.smoothingRate = frictionWidth;
  friction.frictionMoment = p.participant.kneeFriction;
  if (friction.frictionMoment > 0) law.add(std::make_unique<KneeFriction>(friction));
  return law;
}

}  // namespace

int runConvergenceStudy(int argc, char** argv) {
  std::string outPath;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) outPath = argv[++i];

  std::vector<std::unique_ptr<LoadedParticipant>> participants;
  for (const auto& file : participantFiles()) participants.push_back(std::make_unique<LoadedParticipant>(file));
  std::vector<Config> configs;
  for (const auto& p : participants) {
    const double largest = std::min(0.200, calcMaxLowering(p->participant));
    for (double lowering : {0.0, 0.100, largest}) configs.push_back({p.get(), lowering});
  }
  std::fprintf(stderr, "reference swings (plain path, accuracy %g)...\n", kReferenceAccuracy);
  for (auto& c : configs) {
    // A lowering where no swing ends (P2 at 0.200 m: the thigh never reaches its target)
    // steps back by 10 mm, as the sweep's fastest point does.
    for (Run r = runOnce(c.participant->setup(c.lowering), referenceOptions());;
         r = runOnce(c.participant->setup(c.lowering), referenceOptions())) {
      if (r.ok) {
        c.referenceTime = r.swingTime;
        break;
      }
      if (c.lowering < 0.010) throw std::runtime_error("reference swing failed for " + c.participant->participant.name);
      c.lowering -= 0.010;
    }
  }

  std::ostringstream md;
  md << "Reference: plain path (Simbody event handlers, window " << kReferenceWindow
     << " s), Runge-Kutta-Merson at accuracy " << kReferenceAccuracy
     << ". Error = largest |swing time - reference| over the standard location, 0.100 m and the "
     << "largest lowering where a swing ends, for each participant; cost = mean over the same 12 swings (fast "
        "path).\n\n";

  // 1. Integrator x accuracy.
  const std::vector<double> accuracies = {1e-2, 1e-3, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 1e-7, 1e-8};
  const SwingIntegrator integrators[] = {SwingIntegrator::kDormandPrince, SwingIntegrator::kRungeKuttaMerson,
                                         SwingIntegrator::kRungeKuttaFeldberg, SwingIntegrator::kRungeKutta3,
                                         SwingIntegrator::kVerlet};
  md << "| integrator | accuracy | max error (ms) | P1 | P2 | P3 | P4 | steps | realizations | ms per swing |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (SwingIntegrator integrator : integrators) {
    for (double accuracy : accuracies) {
      const bool lowOrder = integrator == SwingIntegrator::kRungeKutta3 || integrator == SwingIntegrator::kVerlet;
      if (lowOrder && accuracy < 1e-6) continue;  // thousands of steps: no contender
      std::fprintf(stderr, "%s %g\n", integratorName(integrator), accuracy);
      SwingOptions o;
      o.integrator = integrator;
      o.accuracy = accuracy;
      double maxError = 0, steps = 0, realizations = 0, seconds = 0;
      double perParticipant[4] = {0, 0, 0, 0};
      bool allOk = true;
      for (std::size_t k = 0; k < configs.size(); ++k) {
        const Run r = runOnce(configs[k].participant->setup(configs[k].lowering), o);
        allOk = allOk && r.ok;
        const double error = r.ok ? std::fabs(r.swingTime - configs[k].referenceTime) : INFINITY;
        maxError = std::max(maxError, error);
        perParticipant[k / 3] = std::max(perParticipant[k / 3], error);
        steps += r.steps;
        realizations += r.realizations;
        seconds += r.seconds;
      }
      const double n = static_cast<double>(configs.size());
      md << "| " << integratorName(integrator) << " | " << fmt("%.0e", accuracy) << " | "
         << (allOk ? fmt("%.4f", 1e3 * maxError) : std::string("failed"))
         << (maxError <= kConvergedTol ? " |" : " (not converged) |");
      for (double e : perParticipant)
        md << " " << (std::isfinite(e) ? fmt("%.4f", 1e3 * e) : std::string("failed")) << " |";
      md << " " << fmt("%.0f", steps / n) << " | " << fmt("%.0f", realizations / n) << " | "
         << fmt("%.2f", 1e3 * seconds / n) << " |\n";
    }
  }

  // 1b. The default integrator over the whole Burkett sweep (every participant and
  // lowering, Table 4's off-grid points included), as the guard test checks it: the
  // 12 swings above can miss the worst point.
  {
    std::fprintf(stderr, "whole sweep: plain path reference...\n");
    SweepStudy sweep = loadSweepStudy(sourcePath("studies/burkett2004.yaml"));
    sweep.addedMasses = {0.0};
    sweep.addedMassDistances.clear();
    sweep.swing = referenceOptions();
    const SweepResults reference = runSweep(sweep, 0);
    md << "\nDefault integrator (" << integratorName(SwingOptions{}.integrator)
       << ") over the whole Burkett sweep against the same reference:\n\n"
       << "| accuracy | swings | largest error (ms) | where |\n|---|---|---|---|\n";
    for (double accuracy : {1e-4, 3e-5, 2e-5, 1e-5, 3e-6}) {
      std::fprintf(stderr, "whole sweep at %g\n", accuracy);
      sweep.swing = SwingOptions{};
      sweep.swing.accuracy = accuracy;
      sweep.swing.recordTrajectory = false;
      const SweepResults r = runSweep(sweep, 0);
      double worst = 0;
      int swings = 0;
      std::string where;
      for (std::size_t i = 0; i < r.participants.size(); ++i) {
        for (std::size_t k = 0; k < r.participants[i].points.size(); ++k) {
          const SweepPoint& a = r.participants[i].points[k];
          const SweepPoint& b = reference.participants[i].points[k];
          if (!a.ok || !b.ok) continue;
          ++swings;
          const double error = std::fabs(a.result.swingTime - b.result.swingTime);
          if (error > worst) {
            worst = error;
            where = r.participants[i].name + " at " + fmt("%.3f", a.lowering) + " m";
          }
        }
      }
      md << "| " << fmt("%.0e", accuracy) << " | " << swings << " | " << fmt("%.4f", 1e3 * worst)
         << (worst <= kConvergedTol ? "" : " (not converged)") << " | " << where << " |\n";
    }
  }

  // 2. and 3. Knee law smoothing: friction width and stop stiffness, at the default
  // integrator and accuracy, against the same law at the reference accuracy. The model
  // changes, so each row has its own reference.
  auto lawTable = [&](const char* title, const char* unit, const std::vector<double>& values, bool isFriction) {
    md << "\n| " << title << " (" << unit << ") | swing time change vs default law (ms): P1 | P2 | P3 | P4 | "
       << "integration error at default settings (ms) | bounce (any) | realizations "
          "|\n|---|---|---|---|---|---|---|---|\n";
    const SwingOptions defaults;
    std::vector<double> baseline(participants.size());
    for (std::size_t i = 0; i < participants.size(); ++i) {
      const Run r = runOnce(participants[i]->setup(0.0), referenceOptions());
      baseline[i] = r.swingTime;
    }
    for (double v : values) {
      std::fprintf(stderr, "%s %g\n", title, v);
      md << "| " << fmt("%g", v) << " |";
      double maxIntegrationError = 0, realizations = 0;
      bool bounce = false;
      for (std::size_t i = 0; i < participants.size(); ++i) {
        const SwingSetup setup = makeSwingSetup(participants[i]->participant,
                                                std::make_shared<const KneeLawSum>(makeVariantKnee(
                                                    *participants[i], isFriction ? 0 : v, isFriction ? v : 0)));
        const Run reference = runOnce(setup, referenceOptions());
        SwingOptions o = defaults;
        o.recordTrajectory = false;
        const Run fast = runOnce(setup, o);
        SwingResult full;
        try {
          full = simulateSwing(setup, defaults);
          bounce = bounce || full.bounce;
        } catch (const std::exception&) {
        }
        md << " " << (reference.ok ? fmt("%+.1e", 1e3 * (reference.swingTime - baseline[i])) : std::string("failed"))
           << " |";
        maxIntegrationError = std::max(maxIntegrationError, std::fabs(fast.swingTime - reference.swingTime));
        realizations += fast.realizations;
      }
      md << " " << fmt("%.4f", 1e3 * maxIntegrationError) << " | " << (bounce ? "yes" : "no") << " | "
         << fmt("%.0f", realizations / static_cast<double>(participants.size())) << " |\n";
    }
  };
  lawTable("friction smoothing width", "rad/s", {4, 2, 1, 0.5, 0.25, 0.1, 0.05}, true);
  lawTable("stop stiffness", "N m/rad^1.5", {5e3, 1e4, 2e4, 4e4, 8e4, 1.6e5}, false);

  std::printf("%s", md.str().c_str());
  if (!outPath.empty()) {
    std::ofstream out(outPath);
    out << md.str();
    if (!out) throw std::runtime_error("cannot write " + outPath);
  }
  return 0;
}

}  // namespace swingsim::bench
