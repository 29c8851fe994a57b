// swingsim calibrate PARTICIPANT.yaml... [--target S] [--dry-run]
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "core/output_paths.h"
#include "study/calibration_run.h"

namespace swingsim::cli {
namespace {

// The Table 3 column a --target word names: model or measured ("stored" is not a target).
std::optional<CalibrationTarget> findTableColumn(const std::string& word) {
  const auto target = findCalibrationTarget(word);
  return target == CalibrationTarget::kStored ? std::nullopt : target;
}

int runCalibrate(const CalibrationRequest& a) {
  if (a.target && a.participants.size() != 1) throw CLI::ValidationError("--target", "applies to one participant file");
  checkDistinctFiles(a.participants, "give each participant file once (it would be calibrated and rewritten twice)");
  runCalibration(a);
  return 0;
}

}  // namespace

Command addCalibrateCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "calibrate", "fit each participant's hip-moment time scale to Burkett Table 3 and store it in the YAML");
  auto a = std::make_shared<CalibrationRequest>();
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
