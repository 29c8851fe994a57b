// swingsim simulate PARTICIPANT.yaml [--lowering M] [--knee MODEL.yaml] [--integrator METHOD] [--accuracy A] [--json FILE] [--out DIR]
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command_registry.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"
#include "report/swing_json.h"

namespace swingsim::cli {
namespace {

int runSimulate(const Arguments& a) {
  SwingOptions options;
  if (a.has("--integrator")) {
    const std::string key = a.get("--integrator");
    const std::optional<SwingIntegrator> integrator = findIntegrator(key);
    if (!integrator) {
      std::string known;
      for (const auto& k : integratorKeys()) known += (known.empty() ? "" : ", ") + k;
      throw UsageError("--integrator: expected one of " + known + " (got '" + key + "')");
    }
    options.integrator = *integrator;
    options.accuracy = calcConvergedAccuracy(*integrator);  // its converged setting unless --accuracy says otherwise
  }
  options.accuracy = a.getDouble("--accuracy", options.accuracy);
  if (const std::string bad = checkAccuracy(options.accuracy); !bad.empty())
    throw UsageError("--accuracy: " + bad + " (got " + a.get("--accuracy") + ")");
  if (a.positional().size() != 1) throw UsageError("expected one participant YAML file");
  SwingSetup setup;
  setup.participant = loadParticipant(a.positional()[0]);
  Participant& p = setup.participant;
  setup.lowering = a.getDouble("--lowering", 0.0);
  if (a.has("--add-mass")) setup.added = parseAddedMass(a.get("--add-mass"));
  p.initial.hipFlexionRate = a.getDouble("--hip-rate-deg-s", p.initial.hipFlexionRate * kRadToDeg) * kDegToRad;
  p.initial.kneeFlexionRate = a.getDouble("--knee-rate-deg-s", p.initial.kneeFlexionRate * kRadToDeg) * kDegToRad;
  const KneeModel model = loadKneeModel(a.get("--knee", p.kneeModelPath));
  const KneeLawSum knee = makeKneeLaw(p, model);
  setup.knee = &knee;
  const SwingResult r = simulateSwing(setup, options);

  std::printf("%s, knee lowered %.3f m, knee model %s\n", p.name.c_str(), setup.lowering, model.name.c_str());
  std::printf("  swing time          %.4f s\n", r.swingTime);
  std::printf("  peak knee flexion   %.1f deg at %.4f s\n", r.peakKneeFlexion * kRadToDeg, r.peakKneeFlexionTime);
  std::printf("  bounce              %s\n", r.bounce ? "yes (knee left the zone of stability again)" : "no");
  std::printf("  min toe clearance   %.3f m%s\n", r.minToeClearance, r.minToeClearance < 0 ? "  (TOE STRIKES THE GROUND)" : "");
  std::printf("  integrator          %s, accuracy %g (%d realizations)\n", integratorName(options.integrator),
              options.accuracy, r.realizations);
  std::printf("  events:");
  for (const auto& e : r.events) std::printf(" %s@%.4f", e.name.c_str(), e.time);
  std::printf("\n");

  const std::string out = a.get("--out", "out/simulate-" + p.name);
  char tag[64];
  std::snprintf(tag, sizeof tag, "%s-lower%03.0fmm", p.name.c_str(), setup.lowering * 1000);
  writeFileAtomic(out + "/" + tag + ".csv", formatTrajectoryCsv(r.trajectory));
  writeFileAtomic(out + "/" + tag + ".sto", formatTrajectorySto(r.trajectory, tag));
  std::printf("  trajectory          %s/%s.csv and .sto\n", out.c_str(), tag);
  if (a.has("--json")) {
    writeJsonFile(a.get("--json"), makeSwingResultJson(p.name, setup.lowering, r));
  }
  return 0;
}

Registrar reg("simulate", {"simulate one swing: swing time, peak knee flexion, events, trajectory CSV/.sto",
                           "PARTICIPANT.yaml", "participant file",
                           {{"--lowering", "knee-axis lowering below the standard location, m (default 0)"},
                            {"--knee", "knee model YAML (default: the participant's knee_model)"},
                            {"--add-mass", "added shank mass as KG@METRES below the knee, e.g. 0.5@0.2 (default none)"},
                            {"--hip-rate-deg-s", "hip flexion rate at toe-off, deg/s (default: the participant's, 0)"},
                            {"--knee-rate-deg-s", "knee flexion rate at toe-off, deg/s (default: the participant's, 0)"},
                            {"--integrator", [] {
                               std::string keys;
                               for (const auto& k : integratorKeys()) keys += (keys.empty() ? "" : ", ") + k;
                               return "integration method, one of " + keys + " (default " + integratorKeys().front() +
                                      "), at its converged accuracy";
                             }()},
                            {"--accuracy", "integrator relative accuracy, (0, 0.01] (default: the integrator's converged one)"},
                            {"--json", "also write the machine-readable result to this JSON file"},
                            {"--out", "output folder for the trajectory (default out/simulate-<participant>/)"}},
                           runSimulate});

}  // namespace
}  // namespace swingsim::cli
