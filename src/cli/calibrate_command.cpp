// swingsim calibrate PARTICIPANT.yaml... [--target S] [--dry-run]
#include <cmath>
#include <cstdio>
#include <vector>

#include "cli/command_registry.h"
#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "io/participant_loader.h"
#include "swing/burkett_published.h"
#include "swing/calibration.h"
#include "swing/knee_setup.h"

namespace swingsim::cli {
namespace {

int runCalibrate(const Arguments& a) {
  if (a.positional().empty()) throw UsageError("expected one or more participant YAML files");
  if (a.has("--target") && a.positional().size() != 1) throw UsageError("--target applies to one participant file");
  // Every file is loaded and calibrated before any is written; storeParticipants then checks
  // each rewritten file loads back before replacing any.
  std::vector<ParticipantEdit> edits;
  for (const std::string& path : a.positional()) {
    SwingSetup setup;
    setup.participant = loadParticipant(path);
    const Participant& p = setup.participant;
    double target = 0;
    if (a.has("--target")) {
      target = a.getDouble("--target", 0);
    } else if (const PublishedParticipant* pub = findPublished(p.name)) {
      target = pub->table3Model;
    } else {
      throw InputError(path + ": name: '" + p.name + "' is not a Burkett 2004 participant; give --target SECONDS");
    }
    const KneeModel model = loadKneeModel(p.kneeModelPath);
    const KneeLawSum knee = makeKneeLaw(p, model);
    setup.knee = &knee;
    std::fprintf(stderr, "calibrating %s to a standard-location swing time of %.4f s...\n", p.name.c_str(), target);
    const CalibrationResult r = calibrateHipTimeScale(setup, target);
    std::printf("%s: hip moment time scale %.6f gives swing time %.5f s (target %.4f s)\n", p.name.c_str(), r.timeScale,
                r.swingTime, target);
    std::printf("  monotonicity scan (scale: swing time s):");
    for (std::size_t i = 0; i < r.scanScales.size(); ++i)
      std::printf(" %.3f:%.4f", r.scanScales[i], r.scanSwingTimes[i]);
    std::printf("\n");
    ParticipantEdit edit{path, p};
    // Six decimals: the calibration's own tolerance is far below 1e-6 in time scale.
    edit.participant.hipMoment.timeScale = std::round(r.timeScale * 1e6) / 1e6;
    edits.push_back(edit);
  }
  if (!a.has("--dry-run")) {
    storeParticipants(edits);
    for (const auto& e : edits) std::printf("  stored in %s (hip_moment.time_scale)\n", e.path.c_str());
  }
  return 0;
}

Registrar reg("calibrate", {"fit each participant's hip-moment time scale to Burkett Table 3 and store it in the YAML",
                            "PARTICIPANT.yaml", "participant files (one or more)",
                            {{"--target", "target standard-location swing time, s (default: Burkett 2004 Table 3 model column; one file only)"},
                             {"--dry-run", "calibrate and print, but do not change the file", true}},
                            runCalibrate});

}  // namespace
}  // namespace swingsim::cli
