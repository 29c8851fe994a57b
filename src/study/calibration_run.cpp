#include "study/calibration_run.h"

#include <cmath>
#include <cstdio>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "sweep/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

// The swing time `p` is calibrated to: the request's, else Burkett's Table 3 column.
double findCalibrationTime(const CalibrationRequest& request, const Participant& p, const std::string& path) {
  if (request.target) return *request.target;
  if (const PublishedParticipant* pub = findPublished(p.name)) return table3Target(*pub, request.column);
  throw InputError(path + ": name: '" + p.name + "' is not a Burkett 2004 participant; give --target SECONDS");
}

}  // namespace

void runCalibration(const CalibrationRequest& request) {
  // Every file is loaded and calibrated before any is written; storeParticipants then checks
  // each rewritten file loads back before replacing any.
  std::vector<ParticipantEdit> edits;
  for (const std::string& path : request.participants) {
    const Participant p = loadParticipant(path);
    checkCalibratable(p);  // before advice on the target, which could not help
    const double target = findCalibrationTime(request, p, path);
    const KneeModel model = loadKneeModel(p.kneeModelPath);
    const SwingSetup setup = makeSwingSetup(p, model);
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
  if (request.dryRun) return;
  storeParticipants(edits);
  for (const auto& e : edits) std::printf("  stored in %s (hip_moment.time_scale)\n", e.path.c_str());
}

}  // namespace swingsim
