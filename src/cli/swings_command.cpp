// swingsim swings FILE.mot [--side r|l] [--grf GRF.mot] [--vertical-force LABEL]
//   [--threshold-N N] [--fallback-to-kinematics] [--gait walking|running] [--knee-sign S]
//   [--json FILE]
//
// Lists the complete swings of one leg in an OpenSim IK file, numbered from 1 so that a
// study can pick one (`swing: K`): toe-off and heel contact from the GRF file's vertical
// force where it covers the time, from the joint angles elsewhere, by a rule per gait; a force
// file is checked and its events against the kinematics (docs/swing-events.md).
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "io/json_file.h"
#include "io/swing_events.h"
#include "study/swing_listing.h"

namespace swingsim::cli {
namespace {

/// What `swingsim swings` was given: the listing's request and --json.
struct SwingsArguments : SwingListRequest {
  std::optional<std::string> json;
};

/// A disagreement for the table, ms, or "-" where there is none.
std::string disagreementText(const std::optional<double>& d) {
  if (!d) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.1f", *d * 1000);
  return buf;
}

int runSwings(const SwingsArguments& a) {
  checkOutputsAreNotInputs({{"FILE.mot", a.kinematics}, {"--grf", a.grf.value_or("")}},
                           {{"--json", a.json.value_or("")}});
  const SwingListing listing = listLegSwings(a);
  const MotionColumns& columns = listing.columns;
  const std::optional<GrfSettings>& grf = listing.grf;
  const SwingList& list = listing.list;
  const std::vector<FoundSwing>& swings = list.swings;

  std::printf("%s: %s leg (%s, %s x %g%s); events from %s\n", a.kinematics.c_str(), a.side == "l" ? "left" : "right",
              columns.hip.c_str(), columns.knee.c_str(), columns.kneeSign,
              columns.pelvisTilt.empty() ? "" : (", + " + columns.pelvisTilt).c_str(),
              grf ? (grf->path + " (" + grf->verticalForce + " below " + formatNumber(grf->thresholdN) +
                     " N) where it covers the time, the kinematics elsewhere")
                        .c_str()
                  : "the kinematics (no --grf)");
  const double frame = listing.framePeriod;
  std::printf(
      "gait: %s (%s); kinematic events: within %.0f ms of the force plates after their bias is removed "
      "(docs/swing-events.md)%s\n",
      gaitName(list.gait), list.gaitBasis.c_str(), list.kinematicAccuracy * 1000,
      list.kinematicAccuracyBeyondTwoFrames
          ? (", more than 2 frames at this file's " + formatNumber(std::round(1 / frame)) +
             " Hz: the kinematics alone cannot place an event within 2 frames")
                .c_str()
          : "");
  for (const std::string& note : list.notes) std::printf("note: %s\n", note.c_str());
  if (swings.empty()) {
    std::printf("no complete swing (toe-off and heel contact both inside the file)\n");
  } else {
    std::printf(
        "swing  toe-off s  heel contact s  duration s  toe-off from  heel contact from  force-kinematics ms: toe-off  "
        "heel contact\n");
    for (std::size_t i = 0; i < swings.size(); ++i)
      std::printf("%5zu  %9.4f  %14.4f  %10.4f  %-12s  %-17s  %28s  %12s\n", i + 1, swings[i].toeOff,
                  swings[i].heelContact, swings[i].duration(), swings[i].toeOffSource.c_str(),
                  swings[i].heelContactSource.c_str(), disagreementText(swings[i].toeOffDisagreement).c_str(),
                  disagreementText(swings[i].heelContactDisagreement).c_str());
  }
  if (a.json) writeJsonFile(*a.json, makeSwingListJson(a, listing));
  return 0;
}

}  // namespace

Command addSwingsCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "swings", "list the swings (toe-off to heel contact) in an OpenSim IK .mot, to pick one for a study");
  auto a = std::make_shared<SwingsArguments>();
  sub->add_option("FILE.mot", a->kinematics, "OpenSim inverse-kinematics file (hip_flexion_<side>, knee_angle_<side>)")
      ->required()
      ->type_name("");
  sub->add_option("--side", a->side, "which leg: r or l; reads hip_flexion_<side> and knee_angle_<side> (default r)")
      ->type_name("r|l")
      ->check(oneOf({"r", "l"}));
  CLI::Option* grf = addTextOption(
      sub, "--grf", a->grf,
      "OpenSim ground reaction force .mot on the same clock (default: none, events from the kinematics)", "GRF.mot");
  // The force's options without a force file would be ignored without a word: refused.
  addTextOption(
      sub, "--vertical-force", a->verticalForce,
      "the foot's vertical force column in the GRF file, N (default ground_force_vy for r, 1_ground_force_vy for l)",
      "LABEL")
      ->needs(grf);
  sub->add_option("--threshold-N", a->thresholdN, "vertical force below which the foot is in the air, N (default 20)")
      ->type_name("N")
      ->check(finiteNumber(checkForceThreshold))
      ->needs(grf);
  sub->add_flag("--fallback-to-kinematics", a->fallbackToKinematics,
                "a force file that fails its checks gives way to the kinematics' events (said in the listing) instead "
                "of an error")
      ->needs(grf);
  addTextOption(sub, "--gait", a->gait,
                "walking or running: which kinematic event rules (default: detected from the stride)",
                "walking|running")
      ->check(oneOf({"walking", "running"}));
  sub->add_option(
         "--knee-sign", a->kneeSign,
         "+1 or -1: knee flexion = sign * knee_angle (default -1, OpenSim's knee_angle is negative in flexion)")
      ->type_name("S")
      ->check(finiteNumber(checkKneeSign));
  addJsonOption(sub, a->json);
  return {sub, [a] { return runSwings(*a); }};
}

}  // namespace swingsim::cli
