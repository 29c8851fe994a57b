#include "serve/serve_api.h"

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_tree.h"
#include "report/stick_figure_animation.h"
#include "report/sweep_figures.h"
#include "report/sweep_markdown.h"
#include "report/sweep_report.h"
#include "report/sweep_report_parts.h"
#include "report/swing_json.h"
#include "study/simulate_run.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

constexpr double kTrajectoryStep = 0.01;  // s between the trajectory samples sent to the page

ApiReply reply(const Json& json) { return {200, json.dump()}; }

// The value of each editable key in the participant's YAML text, as the file writes it.
Json readFields(const std::string& participantYaml) {
  const YamlTree root = YamlTree::parse(participantYaml, "participant", "a participant file");
  Json fields = Json::object();
  for (const std::string& key : editableParticipantKeys()) {
    const auto value = root.find(key).number();
    fields[key] = value ? Json(*value) : Json(nullptr);
  }
  return fields;
}

// A microprocessor knee's swing states as the knee file writes them (its impedance_state_machine
// states: name and the numbers of each), for the page's sliders; empty for another kind.
Json readKneeStates(const std::string& kneeYaml) {
  Json states = Json::array();
  for (const YamlTree& state :
       YamlTree::parse(kneeYaml, "knee", "a knee model file").find("impedance_state_machine.states").items()) {
    Json s = {{"name", state.get("name").scalar()}};
    for (const char* key : {"stiffness_Nm_per_rad", "damping_Nm_s_per_rad", "equilibrium_deg"}) {
      const auto value = state.get(key).number();
      s[key] = value ? Json(*value) : Json(nullptr);
    }
    states.push_back(s);
  }
  return states;
}

std::string stemOf(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// Trajectory samples about kTrajectoryStep apart (and the last), the page's stick figure.
Json makeTrajectorySamples(const SwingTrajectory& tr) {
  Json samples = {{"time_s", Json::array()},    {"hip_flexion_deg", Json::array()}, {"knee_flexion_deg", Json::array()},
                  {"knee_x_m", Json::array()},  {"knee_y_m", Json::array()},        {"ankle_x_m", Json::array()},
                  {"ankle_y_m", Json::array()}, {"toe_x_m", Json::array()},         {"toe_y_m", Json::array()}};
  double next = 0;
  for (std::size_t k = 0; k < tr.size(); ++k) {
    if (tr.time[k] < next && k + 1 < tr.size()) continue;
    next = tr.time[k] + kTrajectoryStep;
    const double values[] = {tr.time[k],
                             tr.hipFlexion[k] * kRadToDeg,
                             tr.kneeFlexion[k] * kRadToDeg,
                             tr.kneeX[k],
                             tr.kneeY[k],
                             tr.ankleX[k],
                             tr.ankleY[k],
                             tr.toeX[k],
                             tr.toeY[k]};
    int i = 0;
    for (auto& column : samples) column.push_back(values[i++]);
  }
  return samples;
}

// The sweep's lowering grid from the request; refused above the point budget.
void readSweepGrid(const Json& body, const ServeLimits& limits, SweepStudy& study) {
  for (const char* key : {"lowering_step_m", "lowering_max_m"})
    if (body.contains(key) && !body[key].is_number())
      throw InputError(std::string(key) + ": expected a number (got " + body[key].dump() + ")");
  study.loweringStep = body.value("lowering_step_m", 0.010);
  study.loweringMax = body.value("lowering_max_m", 0.200);
  if (!(study.loweringStep > 0))
    throw InputError("lowering_step_m: expected a positive step, m (got " + formatNumber(study.loweringStep) + ")");
  if (!(study.loweringMax >= 0 && study.loweringMax <= 0.5))
    throw InputError("lowering_max_m: expected 0 to 0.5 m (got " + formatNumber(study.loweringMax) + ")");
  const double points = std::floor(study.loweringMax / study.loweringStep + 1e-9) + 1;
  if (points > limits.maxSweepPoints)
    throw InputError("lowering_step_m: expected at most " + std::to_string(limits.maxSweepPoints) +
                     " lowerings in one sweep on swingsim serve (its simulation budget) (got " + formatNumber(points) +
                     " lowerings: step " + formatNumber(study.loweringStep) + " m to " +
                     formatNumber(study.loweringMax) + " m)");
}

// The curve the page shows: the plain sweep, or with an added mass the sweep of that mass
// (the study's added-mass grid), its fastest and its symmetry lowering.
ParticipantSweep selectShownCurve(const ParticipantSweep& ps, const Participant& p, const AddedMass& added) {
  if (added.mass <= 0) return ps;
  ParticipantSweep shown = ps;
  shown.points = ps.massPoints;
  shown.massPoints.clear();
  shown.best = ps.bestWithMass;
  // The added-mass grid is not bisected: neighbours with different bounce counts are taken to
  // lie on different pieces (no crossing is interpolated between them), and no jump is drawn.
  shown.jumps.clear();
  std::vector<double> lowerings, times;
  std::vector<int> pieces;
  int piece = 0;
  const SweepPoint* lastEnded = nullptr;
  for (const SweepPoint& pt : shown.points) {
    if (!pt.onGrid) continue;
    if (pt.ok) {
      if (lastEnded && lastEnded->result.bounces != pt.result.bounces) ++piece;
      lastEnded = &pt;
    }
    lowerings.push_back(pt.lowering);
    times.push_back(pt.ok ? pt.result.swingTime : std::numeric_limits<double>::quiet_NaN());
    pieces.push_back(piece);
  }
  shown.symmetry = calcSymmetryLowering(lowerings, times, p.soundLimbSwingTime.value_or(0), pieces);
  return shown;
}

Json makeSweepJson(const SweepStudy& study, const SweepResults& results, const AddedMass& added) {
  const ParticipantSweep ps = selectShownCurve(results.participants.front(), study.participants.front(), added);
  Json lowerings = Json::array(), times = Json::array();
  for (const SweepPoint& pt : ps.points) {
    if (!pt.onGrid) continue;
    lowerings.push_back(pt.lowering);
    times.push_back(pt.ok ? Json(pt.result.swingTime) : Json(nullptr));
  }
  const SweepPoint* best = ps.best >= 0 ? &ps.points[static_cast<std::size_t>(ps.best)] : nullptr;
  Json symmetry = nullptr;
  if (ps.symmetry.given)
    symmetry = {{"sound_limb_swing_time_s", ps.symmetry.soundTime},
                {"found", ps.symmetry.found},
                {"reached", ps.symmetry.reached},
                {"lowering_m", ps.symmetry.lowering},
                {"prosthetic_swing_time_s", ps.symmetry.prostheticTime},
                {"across_jump", ps.symmetry.acrossJump},
                {"text", sweep_report_parts::formatSymmetryLine(ps.symmetry, ps.jumps)}};
  Json jumps = Json::array();
  for (const SwingTimeJump& j : ps.jumps) jumps.push_back(makeSwingTimeJumpJson(j));
  Json sweepJson = Json::parse(formatSweepJson(results));
  return {{"participant", ps.name},
          {"lowering_step_m", study.loweringStep},
          {"added_mass_kg", added.mass},
          {"added_mass_position_m", added.distanceBelowKnee},
          {"lowerings_m", lowerings},
          {"swing_times_s", times},
          {"fastest_lowering_m", best ? Json(best->lowering) : Json(nullptr)},
          {"fastest_swing_time_s", best ? Json(best->result.swingTime) : Json(nullptr)},
          {"symmetry", symmetry},
          {"jumps", jumps},
          {"figure_svg", makeSwingTimeFigure(ps, nullptr).render()},
          {"sweep", sweepJson}};
}

struct LegSweep {
  SweepStudy study;
  SweepResults results;
  AddedMass added;  ///< the request's (0 kg: none)
};

// The sweep of a request's leg over its lowering grid, on one thread (the server's pool
// serves other requests meanwhile). The study is named after the participant.
LegSweep runLegSweep(const Json& json, const ShippedFiles& files, const ServeLimits& limits) {
  checkRequestKeys(json, {"lowering_step_m", "lowering_max_m"});
  const LegRequest request = readLegRequest(json);
  LegSweep run;
  readSweepGrid(json, limits, run.study);
  Leg leg = loadLeg(request, files, limits);
  run.study.name = leg.participant.name + "-sweep";
  run.study.includePublishedLowerings = false;
  run.study.swing = makeServeSwingOptions(limits, ServeSwing::kAsSweep);
  leg.participant.kneeModelPath = leg.knee.path;
  run.study.kneeModels.emplace(leg.knee.path, leg.knee);
  run.study.participants.push_back(std::move(leg.participant));
  run.added = request.added;
  if (request.added.mass > 0) {  // the added-mass grid beside the plain sweep, at the request's mass and position
    run.study.addedMasses = {0.0, request.added.mass};
    run.study.addedMassDistances = {request.added.distanceBelowKnee};
  }
  run.results = runSweep(run.study, 1);
  return run;
}

}  // namespace

ServeApi::ServeApi(ShippedFiles files, ServeLimits limits) : files_(std::move(files)), limits_(limits) {}

ApiReply ServeApi::hideServerPaths(ApiReply reply) const {
  for (const std::string& dir : files_.getDataDirSpellings()) {
    const std::string prefix = dir + "/";
    for (auto at = reply.body.find(prefix); at != std::string::npos; at = reply.body.find(prefix, at))
      reply.body.erase(at, prefix.size());
  }
  return reply;
}

ApiReply ServeApi::listFiles() const {
  return reply({{"participants", files_.getParticipantNames()},
                {"knee_models", files_.getKneeNames()},
                {"editable_keys", editableParticipantKeys()},
                {"limits",
                 {{"max_body_bytes", limits_.maxBodyBytes},
                  {"max_osim_bytes", limits_.maxOsimBytes},
                  {"max_swing_time_limit_s", limits_.maxSwingTimeLimit},
                  {"max_swing_wall_s", limits_.maxSwingWallSeconds},
                  {"max_sweep_points", limits_.maxSweepPoints}}}});
}

ApiReply ServeApi::describeParticipant(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const Json asked = readRequestBody(body);
    checkRequestKeys(asked, {});
    Leg leg = loadLeg(readLegRequest(asked), files_, limits_);
    Participant& p = leg.participant;
    p.kneeModelPath =
        leg.knee.path;  // the export names the knee in use (chosen or uploaded), as the knee export is named
    const std::string participantYaml = formatParticipantYaml(p, files_.getParticipantsDir());
    KneeModelSpec spec = leg.knee.spec;
    if (spec.name.empty()) spec.name = leg.knee.name;
    return Json{{"name", p.name},
                {"fields", readFields(participantYaml)},
                {"knee_model", stemOf(leg.knee.path)},
                {"knee_settings", {{"knee_effects.model_scale", spec.kneeEffects.modelScale}}},
                {"drive", p.drive == SwingDrive::kHipMoment ? "hip_moment" : "thigh_kinematics"},
                {"max_lowering_m", calcMaxLowering(p)},
                {"participant_yaml", participantYaml},
                {"knee_yaml", formatKneeModelYaml(spec)},
                {"knee_states", readKneeStates(formatKneeModelYaml(spec))}};
  }));
}

ApiReply ServeApi::simulate(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const Json asked = readRequestBody(body);
    checkRequestKeys(asked, {});
    const LegRequest request = readLegRequest(asked);
    Leg leg = loadLeg(request, files_, limits_);
    const double hipHeight = calcHipHeight(leg.participant);
    const SimulateRun run = runSimulate(std::move(leg.participant), leg.knee, request.lowering, request.added,
                                        makeServeSwingOptions(limits_, ServeSwing::kAsSimulate));
    const SwingResult& r = run.result;
    Json json = makeSimulateJson(run.setup, r);
    json["knee_model"] = stemOf(leg.knee.path);
    json["added_mass_kg"] = request.added.mass;
    json["added_mass_position_m"] = request.added.distanceBelowKnee;
    const bool ended = std::isfinite(r.swingTime) && r.swingTime > 0 && !r.trajectory.time.empty();
    json["stick_figure_svg"] = ended ? Json(renderStickFigureAnimation(r, hipHeight)) : Json(nullptr);
    json["hip_height_m"] = hipHeight;
    json["trajectory"] = makeTrajectorySamples(r.trajectory);
    return json;
  }));
}

ApiReply ServeApi::sweep(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const LegSweep run = runLegSweep(readRequestBody(body), files_, limits_);
    return makeSweepJson(run.study, run.results, run.added);
  }));
}

ApiReply ServeApi::report(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const LegSweep run = runLegSweep(readRequestBody(body), files_, limits_);
    const auto files = makeSweepReport(run.study, run.results);
    // The participant's name as a file stem that stays one file name (a hostile name reached it unchanged).
    return Json{{"file_name", makeSafeFileStem(run.study.name) + "-report.html"}, {"html", files.at("report.html")}};
  }));
}

}  // namespace swingsim
