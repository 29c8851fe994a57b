// swingsim calibrate PARTICIPANT.yaml... [--target S] [--dry-run]
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "io/participant_loader.h"
#include "sweep/burkett_published.h"
#include "sweep/calibration.h"
#include "swing/knee_setup.h"

namespace swingsim::cli {
namespace {

/// What `swingsim calibrate` was given.
struct CalibrateArguments {
  std::vector<std::string> participants;
  std::optional<double> target;  ///< s; nullopt: Burkett 2004 Table 3, column `column`
  CalibrationTarget column = CalibrationTarget::kModel;
  bool dryRun = false;
};

// The Table 3 column a --target word names: model or measured ("stored" is not a target).
std::optional<CalibrationTarget> findTableColumn(const std::string& word) {
  const auto target = findCalibrationTarget(word);
  return target == CalibrationTarget::kStored ? std::nullopt : target;
}

int runCalibrate(const CalibrateArguments& a) {
  if (a.target && a.participants.size() != 1) throw CLI::ValidationError("--target", "applies to one participant file");
  checkDistinctFiles(a.participants, "give each participant file once (it would be calibrated and rewritten twice)");
  // Every file is loaded and calibrated before any is written; storeParticipants then checks
  // each rewritten file loads back before replacing any.
  std::vector<ParticipantEdit> edits;
  for (const std::string& path : a.participants) {
    const Participant loaded = loadParticipant(path);
    const Participant& p = loaded;
    checkCalibratable(p);  // before advice on the target, which could not help
    double target = 0;
    if (a.target) {
      target = *a.target;
    } else if (const PublishedParticipant* pub = findPublished(p.name)) {
      target = table3Target(*pub, a.column);
    } else {
      throw InputError(path + ": name: '" + p.name + "' is not a Burkett 2004 participant; give --target SECONDS");
    }
    const KneeModel model = loadKneeModel(p.kneeModelPath);
    const SwingSetup setup = makeSwingSetup(loaded, model);
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
  if (!a.dryRun) {
    storeParticipants(edits);
    for (const auto& e : edits) std::printf("  stored in %s (hip_moment.time_scale)\n", e.path.c_str());
  }
  return 0;
}

}  // namespace

Command addCalibrateCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("calibrate", "fit each participant's hip-moment time scale to Burkett Table 3 and store it in the YAML");
  auto a = std::make_shared<CalibrateArguments>();
  sub->add_option("PARTICIPANT.yaml", a->participants, "participant files (one or more)")->required()->type_name("");
  sub->add_option_function<std::string>(
         "--target",
         [a](const std::string& v) {
           if (const auto column = findTableColumn(v)) {
             a->column = *column;
           } else {
             a->target = std::stod(v);  // checked below
           }
         },
         "model | measured | SECONDS: Burkett 2004 Table 3's model column (default) or measured column, or a "
         "standard-location swing time in s (one file only)")
      ->type_name("model|measured|S")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            if (findTableColumn(v)) return "";
            try {
              std::size_t used = 0;
              const double x = std::stod(v, &used);
              if (used == v.size() && std::isfinite(x) && x > 0) return "";
            } catch (const std::exception&) {
            }
            return "expected model, measured or a positive swing time in seconds, found '" + v + "'";
          },
          "", ""));
  sub->add_flag("--dry-run", a->dryRun, "calibrate and print, but do not change the file (default: store)");
  return {sub, [a] { return runCalibrate(*a); }};
}

}  // namespace swingsim::cli
