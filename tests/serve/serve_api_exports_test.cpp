// swingsim serve's export, import, report and tuning calls (serve/serve_api.h), without
// HTTP: each gives what the command line's own sequence gives for the same leg (export-osim
// and simulate's .sto, import-osim, sweep's report.html, swingsim tune), and refuses bad
// input by the key the page shows it beside.
#include "serve/serve_api.h"
#include "serve_api_calls.h"

#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/output_files.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "study/osim_export.h"
#include "study/osim_import.h"
#include "study/tuning_run.h"
#include "study/tuning_study.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

using serve_test::callServeApi;

const std::string kSource = SWINGSIM_SOURCE_DIR;
const std::string kSubject01 = kSource + "/studies/data/opensim-subject01/gait2354_subject01_simbody.osim";

TEST(ServeExportOsim, IsExportOsimsModelAndSimulatesSto) {
  const Json j = callServeApi(&ServeApi::exportOsim, {{"participant", "p1"},
                                                      {"lowering_m", 0.05},
                                                      {"side", "l"},
                                                      {"added_mass_kg", 0.5},
                                                      {"added_mass_position_m", 0.2}});
  const Participant p = loadParticipant(kSource + "/participants/p1.yaml");
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  const AddedMass added{0.5, 0.2};
  const std::string stem = makeTrajectoryFileStem(p.name, 0.05);
  EXPECT_EQ(j["osim_file_name"], stem + ".osim");
  EXPECT_EQ(j["osim_text"], formatParticipantOsim(p, knee, OsimExportOptions{'l', 0.05, added}, stem + ".sto"));
  SwingOptions options;
  options.trackImpactEnergy = true;  // simulate's
  const SwingResult r = simulateSwing(makeSwingSetup(p, knee, 0.05, added), options);
  EXPECT_EQ(j["sto_text"], formatTrajectorySto(r.trajectory, stem, 'l'));
  EXPECT_THAT(j["sto_text"].get<std::string>(), HasSubstr("knee_angle_l"));
}

TEST(ServeExportOsim, RefusesAWrongSide) {
  EXPECT_EQ(callServeApi(&ServeApi::exportOsim, {{"participant", "p1"}, {"side", "x"}}, 400)["key"], "side");
}

TEST(ServeImportOsim, IsImportOsimsParticipantAndLoadsAsAnUpload) {
  const Json j =
      callServeApi(&ServeApi::importOsim,
                   {{"osim_text", readFile(kSubject01)}, {"file_name", "/home/a/subject01.osim"}, {"side", "l"}});
  OsimImportOptions o;
  o.side = 'l';
  o.kneeModelPath = kSource + "/models/damping-table-default.yaml";
  const ImportedParticipantYaml cli = importOsimParticipant(kSubject01, o, kSource + "/participants");
  // The same participant; only the header's file name differs (the upload's name, no folder).
  const auto dropComments = [](const std::string& text) {
    std::string out, line;
    std::istringstream in(text);
    while (std::getline(in, line))
      if (line.rfind("#", 0) != 0) out += line + "\n";
    return out;
  };
  std::string expected = dropComments(cli.text);
  const std::string file = "gait2354_subject01_simbody.osim";
  expected.replace(expected.find(file), file.size(), "subject01.osim");
  EXPECT_EQ(dropComments(j["participant_yaml"]), expected);
  EXPECT_EQ(j["name"], cli.name);
  EXPECT_THAT(j["participant_yaml"].get<std::string>(), HasSubstr("model subject01.osim"));
  EXPECT_THAT(j["participant_yaml"].get<std::string>(), Not(HasSubstr("/home/a")));
  const Json described = callServeApi(&ServeApi::describeParticipant, {{"participant_yaml", j["participant_yaml"]}});
  EXPECT_EQ(described["knee_model"], "damping-table-default");
}

TEST(ServeImportOsim, NamesCatalogueParts) {
  const Json j = callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)},
                                                      {"file_name", "subject01.osim"},
                                                      {"knee_part", "osl-knee"},
                                                      {"foot_part", "osl-foot"}});
  const std::string yaml = j["participant_yaml"];
  EXPECT_THAT(yaml, HasSubstr("knee: osl-knee"));
  EXPECT_THAT(yaml, HasSubstr("foot: osl-foot"));
  EXPECT_EQ(
      callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)}, {"knee_part", "c-leg"}}, 400)["key"],
      "knee_part");
  EXPECT_EQ(callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)}, {"foot_part", 3}}, 400)["key"],
            "foot_part");
}

TEST(ServeImportOsim, RefusesWhatIsNotAModelByItsKey) {
  const Json notXml =
      callServeApi(&ServeApi::importOsim, {{"osim_text", "<OpenSimDocument"}, {"file_name", "bad.osim"}}, 400);
  EXPECT_THAT(notXml["error"].get<std::string>(), HasSubstr("bad.osim:1:"));
  EXPECT_EQ(callServeApi(&ServeApi::importOsim, {{"file_name", "x.osim"}}, 400)["key"], "osim_text");
  EXPECT_EQ(callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)}, {"side", "both"}}, 400)["key"],
            "side");
  EXPECT_EQ(callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)}, {"knee", "../../etc/passwd"}},
                         400)["key"],
            "knee");
  EXPECT_EQ(
      callServeApi(&ServeApi::importOsim, {{"osim_text", readFile(kSubject01)}, {"shank_mass_kg", -1}}, 400)["key"],
      "shank_mass_kg");
}

TEST(ServeReport, IsTheSweepsSelfContainedReport) {
  const Json request = {{"participant", "p1"}, {"lowering_step_m", 0.05}};
  const Json j = callServeApi(&ServeApi::report, request);
  const Json sweep = callServeApi(&ServeApi::sweep, request);
  EXPECT_EQ(j["file_name"], "P1-sweep-report.html");
  const std::string html = j["html"];
  EXPECT_THAT(html, HasSubstr("<svg"));
  EXPECT_THAT(html, HasSubstr("P1"));
  EXPECT_THAT(html, HasSubstr("without a study file (swingsim serve"));
  EXPECT_THAT(html, Not(HasSubstr("<script")));
  EXPECT_THAT(html, Not(HasSubstr("src=\"http")));
  char fastest[32];
  std::snprintf(fastest, sizeof fastest, "%.4f", sweep["fastest_swing_time_s"].get<double>());
  EXPECT_THAT(html, HasSubstr(fastest));
}

// Issue 57: a hostile participant name reached the report's file name unchanged.
TEST(ServeReport, AHostileNameGivesASafeFileName) {
  std::string p1 = readFile(kSource + "/participants/p1.yaml");
  const auto at = p1.find("name: P1");
  ASSERT_NE(at, std::string::npos);
  p1.replace(at, 8, "name: \"../../x/evil name\"");
  const Json j = callServeApi(&ServeApi::report, {{"participant_yaml", p1}, {"lowering_step_m", 0.1}});
  const std::string name = j["file_name"];
  EXPECT_EQ(name.find('/'), std::string::npos) << name;
  EXPECT_EQ(name.find(' '), std::string::npos) << name;
  EXPECT_NE(name.find("-report.html"), std::string::npos) << name;
}

// With an added mass the sweep shown is the leg's with it: each lowering's swing time is the
// one simulateSwing gives with that mass (the sweep's options), and differs from the plain
// sweep's by far more than the integrator's 0.1 ms.
TEST(ServeSweep, WithAnAddedMassShowsTheLegWithIt) {
  const Json plain = callServeApi(&ServeApi::sweep, {{"participant", "p1"}, {"lowering_step_m", 0.05}});
  const Json heavy = callServeApi(
      &ServeApi::sweep,
      {{"participant", "p1"}, {"lowering_step_m", 0.05}, {"added_mass_kg", 1.0}, {"added_mass_position_m", 0.25}});
  EXPECT_EQ(heavy["added_mass_kg"], 1.0);
  const Participant p = loadParticipant(kSource + "/participants/p1.yaml");
  const KneeModel knee = loadKneeModel(p.kneeModelPath);
  ASSERT_EQ(heavy["lowerings_m"].size(), plain["lowerings_m"].size());
  for (std::size_t k = 0; k < heavy["lowerings_m"].size(); ++k) {
    const double lowering = heavy["lowerings_m"][k];
    const SwingResult r = simulateSwing(makeSwingSetup(p, knee, lowering, AddedMass{1.0, 0.25}), SwingOptions{});
    EXPECT_EQ(heavy["swing_times_s"][k].get<double>(), r.swingTime) << lowering;
    EXPECT_GT(std::abs(heavy["swing_times_s"][k].get<double>() - plain["swing_times_s"][k].get<double>()), 1e-3)
        << lowering;
  }
  double fastest = 1e9;
  for (const Json& t : heavy["swing_times_s"]) fastest = std::min(fastest, t.get<double>());
  EXPECT_EQ(heavy["fastest_swing_time_s"].get<double>(), fastest);
  EXPECT_EQ(heavy["symmetry"]["sound_limb_swing_time_s"], 0.499);
}

// P1's damping-table knee tuned over the lowering and model_scale, as a `kind: knee-tuning`
// study with the same knobs and targets would be by `swingsim tune`.
const Json kTuneRequest = {{"participant", "p1"},
                           {"knobs",
                            {{{"key", "lowering_m"}, {"min", 0}, {"max", 0.06}},
                             {{"key", "knee_effects.model_scale"}, {"min", 0.5}, {"max", 8}, {"log_scale", true}}}}};

TEST(ServeTune, IsSwingsimTunesResultForTheSameKnobs) {
  const Json j = callServeApi(&ServeApi::tune, kTuneRequest);
  const auto dir = std::filesystem::temp_directory_path() / ("ServeTune-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string study = (dir / "tune.yaml").string();
  std::ofstream(study)
      << "kind: knee-tuning\nparticipant: " << kSource << "/participants/p1.yaml\nknee_model: " << kSource
      << "/models/damping-table-default.yaml\nknobs:\n  - {key: lowering_m, range: [0, 0.06]}\n"
      << "  - {key: knee_effects.model_scale, range: [0.5, 8], log_scale: true}\n"
      << "targets:\n  swing_time_s: {value: sound_limb, weight: 1}\n"
      << "  peak_knee_flexion_deg: {min: 60, max: 90, hard: true}\n  min_toe_clearance_m: {min: 0.08, hard: true}\n";
  SweepRunControl control;
  const TuningRun cli = runTuningStudy(loadTuningStudy(study), 1, control);
  ASSERT_EQ(j["knobs"].size(), 2u);
  EXPECT_EQ(j["knobs"][0]["value"].get<double>(), cli.result.best.knobs[0]);
  EXPECT_EQ(j["knobs"][1]["value"].get<double>(), cli.result.best.knobs[1]);
  EXPECT_EQ(j["swing_time_s"].get<double>(), cli.result.best.swingTime);
  EXPECT_EQ(j["feasible"], cli.result.feasible);
}

TEST(ServeTune, ItsSettingSwingsAsTheSimulateCallShowsIt) {
  const Json j = callServeApi(&ServeApi::tune, kTuneRequest);
  const Json before = callServeApi(&ServeApi::simulate, {{"participant", "p1"}});
  const Json after =
      callServeApi(&ServeApi::simulate, {{"participant", "p1"},
                                         {"lowering_m", j["knobs"][0]["value"]},
                                         {"knee_settings", {{"knee_effects.model_scale", j["knobs"][1]["value"]}}}});
  EXPECT_EQ(after["swing_time_s"].get<double>(), j["swing_time_s"].get<double>());
  const double sound = 0.499;  // P1's sound_limb_swing_time_s (participants/p1.yaml, Burkett 2004 Table 4)
  EXPECT_LT(std::abs(after["swing_time_s"].get<double>() - sound),
            std::abs(before["swing_time_s"].get<double>() - sound));
  for (const Json& t : j["targets"])
    if (t["hard"].get<bool>()) {
      EXPECT_TRUE(t["met"].get<bool>()) << t.dump();
    }
}

// A tuning past the server's budget stops between swings and says so; with no swing run it
// is a failed run (422), never knob values of a setting not simulated. The budget here is
// 0 s, so the first swing is already past it: no clock decides the outcome.
TEST(ServeTune, StopsAtTheBudgetAndSaysSo) {
  ServeLimits limits;
  limits.maxTuneWallSeconds = 0;
  const ServeApi tight(ShippedFiles(SWINGSIM_SOURCE_DIR), limits);
  const ApiReply r = tight.tune(kTuneRequest.dump());
  const Json j = Json::parse(r.body);
  EXPECT_EQ(r.status, 422) << r.body;
  EXPECT_THAT(j["error"].get<std::string>(), HasSubstr("budget (0 s, 3000 swings) before any swing ran"));
}

// Stopped by the swing budget after the start set (24 swings), the best so far comes back
// marked interrupted, and it is a setting that was simulated: /api/simulate at its knobs
// gives its swing time.
TEST(ServeTune, StoppedItReturnsTheBestSimulatedSoFar) {
  ServeLimits limits;
  limits.maxTuneSwings = 30;
  const ServeApi tight(ShippedFiles(SWINGSIM_SOURCE_DIR), limits);
  const ApiReply r = tight.tune(kTuneRequest.dump());
  ASSERT_EQ(r.status, 200) << r.body;
  const Json j = Json::parse(r.body);
  EXPECT_TRUE(j["interrupted"].get<bool>());
  EXPECT_LE(j["evaluations"].get<int>(), 31);
  const Json swing =
      callServeApi(&ServeApi::simulate, {{"participant", "p1"},
                                         {"lowering_m", j["knobs"][0]["value"]},
                                         {"knee_settings", {{"knee_effects.model_scale", j["knobs"][1]["value"]}}}});
  EXPECT_EQ(swing["swing_time_s"].get<double>(), j["swing_time_s"].get<double>());
}

// Issue 57: SIGTERM during a tuning waited for the whole tuning (up to its 30 s budget). A
// stopping server's tuning ends at its next swing.
TEST(ServeTune, AStoppingServerEndsATuningAtItsNextSwing) {
  ServeApi api(ShippedFiles(SWINGSIM_SOURCE_DIR), ServeLimits{});
  api.requestStop();
  const ApiReply r = api.tune(kTuneRequest.dump());
  EXPECT_EQ(r.status, 422) << r.body;  // it ran its whole tuning (200) before
  EXPECT_THAT(r.body, HasSubstr("swingsim serve is stopping; no swing ran"));
}

// Issue 57: a tuning whose client had gone (a closed page) ran to its budget, holding a
// compute slot. It ends at its next swing once the client is gone.
TEST(ServeTune, AGoneClientEndsATuningAtItsNextSwing) {
  const ServeApi api(ShippedFiles(SWINGSIM_SOURCE_DIR), ServeLimits{});
  const ApiReply none = api.tune(kTuneRequest.dump(), [] { return true; });
  EXPECT_EQ(none.status, 422) << none.body;
  EXPECT_THAT(none.body, HasSubstr("the client has gone; no swing ran"));
  int asked = 0;  // gone after 30 swings: the best of those comes back, marked interrupted
  const ApiReply some = api.tune(kTuneRequest.dump(), [&asked] { return ++asked > 30; });
  ASSERT_EQ(some.status, 200) << some.body;
  const Json j = Json::parse(some.body);
  EXPECT_TRUE(j["interrupted"].get<bool>());
  EXPECT_LE(j["evaluations"].get<int>(), 31);
  EXPECT_EQ(asked, 31);  // asked once a swing, and not again once it said gone
}

TEST(ServeTune, RefusesBeyondItsConcurrentTunings) {
  ServeLimits limits;
  limits.maxConcurrentTunes = 0;
  const ServeApi none(ShippedFiles(SWINGSIM_SOURCE_DIR), limits);
  const ApiReply r = none.tune(kTuneRequest.dump());
  EXPECT_EQ(r.status, 503);
  EXPECT_THAT(r.body, HasSubstr("tunings are under way"));
  limits.maxConcurrentTunes = 1;  // the slot is given back: one at a time runs, twice in a row
  const ServeApi one(ShippedFiles(SWINGSIM_SOURCE_DIR), limits);
  Json cheap = kTuneRequest;
  cheap["knobs"] = {{{"key", "lowering_m"}, {"min", 0}, {"max", 0.02}}};
  EXPECT_EQ(one.tune(cheap.dump()).status, 200);
  EXPECT_EQ(one.tune(cheap.dump()).status, 200);
}

TEST(ServeTune, RefusesBadKnobsAndTargetsByTheirKey) {
  const auto refuse = [](Json body) { return callServeApi(&ServeApi::tune, body, 400)["key"].get<std::string>(); };
  Json none = kTuneRequest;
  none.erase("knobs");
  EXPECT_EQ(refuse(none), "knobs");
  Json five = kTuneRequest;
  for (int k = 0; k < 3; ++k) five["knobs"].push_back(five["knobs"][0]);
  EXPECT_EQ(refuse(five), "knobs");
  Json traversal = kTuneRequest;
  traversal["knobs"][0]["key"] = "../../etc/passwd";
  EXPECT_EQ(refuse(traversal), "knobs");
  Json far = kTuneRequest;
  far["knobs"][0]["max"] = 5.0;
  EXPECT_EQ(refuse(far), "lowering_m");
  Json logZero = kTuneRequest;
  logZero["knobs"][1]["min"] = 0;
  EXPECT_EQ(refuse(logZero), "knee_effects.model_scale");
  Json badScale = kTuneRequest;
  badScale["knobs"][1]["min"] = -1;
  badScale["knobs"][1]["log_scale"] = false;
  EXPECT_EQ(refuse(badScale), "knee_effects.model_scale");
  Json noSound = kTuneRequest;
  std::string p1 = readFile(kSource + "/participants/p1.yaml");
  p1 = p1.substr(0, p1.find("sound_limb_swing_time_s"));
  noSound.erase("participant");
  noSound["participant_yaml"] = p1;
  EXPECT_EQ(refuse(noSound), "sound_limb_swing_time_s");
  Json badMass = kTuneRequest;
  badMass["knobs"][0] = {{"key", "added_mass_kg"}, {"min", -5}, {"max", 2}};
  EXPECT_EQ(refuse(badMass), "added_mass_kg");
  Json farMass = kTuneRequest;
  farMass["added_mass_kg"] = 1.0;
  farMass["knobs"][0] = {{"key", "added_mass_below_knee_m"}, {"min", 0}, {"max", 3}};
  EXPECT_EQ(refuse(farMass), "added_mass_below_knee_m");
  Json badFlag = kTuneRequest;
  badFlag["knobs"][1]["log_scale"] = "yes";
  EXPECT_EQ(refuse(badFlag), "knee_effects.model_scale.log_scale");
  // Issue 57: as swingsim tune's study files, a knob given twice and a reversed flexion window.
  Json twice = kTuneRequest;
  twice["knobs"][1] = twice["knobs"][0];
  EXPECT_EQ(refuse(twice), twice["knobs"][0]["key"].get<std::string>());
  Json reversed = kTuneRequest;
  reversed["targets"]["peak_knee_flexion_deg"] = {90, 60};
  EXPECT_EQ(refuse(reversed), "peak_knee_flexion_deg");
  Json misspelt = kTuneRequest;
  misspelt["knob"] = misspelt["knobs"];
  EXPECT_EQ(refuse(misspelt), "knob");
}

}  // namespace
}  // namespace swingsim
