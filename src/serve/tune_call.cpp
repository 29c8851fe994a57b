// swingsim serve's tuning (serve/serve_api.h): the page's knobs moved at once toward the
// sound limb's swing time within a peak-flexion window and a toe-clearance limit, by the
// same tuning `swingsim tune` runs (sweep/knee_tuning.h, study/tuning_model.h), under the
// server's budget.
#include <atomic>
#include <chrono>
#include <cmath>

#include "core/input_error.h"
#include "core/units.h"
#include "serve/serve_api.h"
#include "study/tuning_model.h"
#include "study/tuning_study.h"
#include "sweep/tuning_resolution.h"

namespace swingsim {
namespace {

constexpr int kMaxTuneKnobs = 4;
constexpr int kTuneStartPoints = 24;    // as swingsim tune's default
constexpr double kTuneMaxSeconds = 10;  // s of polish

// A knob's key: the lowering, the added mass or its position, or a number of the knee file
// (KneeModelKnobs::checkKey: its value then gets the knee loader's checks).
void checkTuneKnobKey(const Json& knob, const KneeModelKnobs& knee) {
  const std::string key =
      knob.is_object() && knob.contains("key") && knob["key"].is_string() ? knob["key"].get<std::string>() : "";
  if (isLegTuningKnob(key)) return;
  const std::string problem = key.empty() ? "no key" : knee.checkKey(key);
  if (!problem.empty())
    throw InputError(
        "knobs: expected {key, min, max} with a key of lowering_m, added_mass_kg, added_mass_below_knee_m or a "
        "number of the knee model file, e.g. knee_effects.model_scale (got " +
        knob.dump() + ": " + problem + ")");
}

double readFinite(const Json& v, const std::string& key) {
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw InputError(key + ": expected a number (got " + v.dump() + ")");
  return v.get<double>();
}

// "knobs": [{"key", "min", "max", "log_scale"}], 1 to kMaxTuneKnobs of them.
std::vector<TuningKnob> readTuneKnobs(const Json& body, const KneeModelKnobs& knee) {
  if (!body.contains("knobs") || !body["knobs"].is_array() || body["knobs"].empty() ||
      body["knobs"].size() > kMaxTuneKnobs)
    throw InputError("knobs: expected 1 to " + std::to_string(kMaxTuneKnobs) + " knobs, each {key, min, max} (got " +
                     (body.contains("knobs") ? body["knobs"].dump() : std::string("none")) + ")");
  std::vector<TuningKnob> knobs;
  for (const Json& k : body["knobs"]) {
    checkTuneKnobKey(k, knee);
    TuningKnob knob;
    knob.key = k["key"].get<std::string>();
    knob.lower = readFinite(k.value("min", Json()), knob.key + ".min");
    knob.upper = readFinite(k.value("max", Json()), knob.key + ".max");
    if (k.contains("log_scale") && !k["log_scale"].is_boolean())
      throw InputError(knob.key + ".log_scale: expected true or false (got " + k["log_scale"].dump() + ")");
    knob.logScale = k.value("log_scale", false);
    if (!(knob.lower < knob.upper)) throw InputError(knob.key + ": expected min below max (got " + k.dump() + ")");
    if (knob.logScale && !(knob.lower > 0))
      throw InputError(knob.key + ": expected min > 0 on a log scale (got " + k.dump() + ")");
    // The finest step a person can set (sweep/tuning_resolution.h): given, or implied by the key's unit.
    if (k.contains("resolution"))
      knob.resolution = readFinite(k["resolution"], knob.key + ".resolution");
    else if (const std::optional<double> byUnit = findDefaultKnobResolution(knob.key))
      knob.resolution = *byUnit;
    else
      throw InputError(knob.key +
                       ".resolution: the unit cannot be told from the key; expected the finest step a person "
                       "can set (got none)");
    if (!(knob.resolution > 0 && knob.resolution <= knob.upper - knob.lower))
      throw InputError(knob.key + ".resolution: expected above 0 and at most the range (got " + k.dump() + ")");
    for (const TuningKnob& earlier : knobs)  // as swingsim tune's study file refuses it
      if (earlier.key == knob.key) throw InputError(knob.key + ": expected each knob once (got it twice)");
    knobs.push_back(knob);
  }
  return knobs;
}

// The swing time (the sound limb's unless given), and the flexion window and clearance limit
// as hard limits (defaults: studies/tune-p1-damping.yaml's assumptions, docs/serve.md).
std::vector<TuningTarget> readTuneTargets(const Json& body, const Participant& p) {
  const Json targets = body.value("targets", Json::object());
  if (!targets.is_object()) throw InputError("targets: expected a map (got " + targets.dump() + ")");
  TuningTarget time;
  const Json given = targets.value("swing_time_s", Json());
  if (given.is_null() && !p.soundLimbSwingTime)
    throw InputError(
        "sound_limb_swing_time_s: expected the sound limb's swing time, s, to tune toward (got none: give it in "
        "the form, or a swing_time_s target)");
  time.lower = time.upper = given.is_null() ? *p.soundLimbSwingTime : readFinite(given, "swing_time_s");
  if (!(time.lower > 0 && time.lower < p.swingEnd.timeLimit))
    throw InputError("swing_time_s: expected 0 to the swing's time limit, " + formatNumber(p.swingEnd.timeLimit) +
                     " s (got " + formatNumber(time.lower) + ")");
  time.scale = tuningTargetScale(TuningQuantity::kSwingTime);
  TuningTarget flexion{TuningQuantity::kPeakKneeFlexion,
                       60 * kDegToRad,
                       90 * kDegToRad,
                       true,
                       1,
                       tuningTargetScale(TuningQuantity::kPeakKneeFlexion)};
  if (targets.contains("peak_knee_flexion_deg")) {
    const Json& w = targets["peak_knee_flexion_deg"];
    if (!w.is_array() || w.size() != 2)
      throw InputError("peak_knee_flexion_deg: expected [min, max] in deg (got " + w.dump() + ")");
    flexion.lower = readFinite(w[0], "peak_knee_flexion_deg") * kDegToRad;
    flexion.upper = readFinite(w[1], "peak_knee_flexion_deg") * kDegToRad;
    if (!(flexion.lower < flexion.upper))
      throw InputError("peak_knee_flexion_deg: expected [min, max] with min < max (got " + w.dump() + ")");
  }
  TuningTarget clearance{TuningQuantity::kMinToeClearance,
                         0.08,
                         std::numeric_limits<double>::infinity(),
                         true,
                         1,
                         tuningTargetScale(TuningQuantity::kMinToeClearance)};
  if (targets.contains("min_toe_clearance_m"))
    clearance.lower = readFinite(targets["min_toe_clearance_m"], "min_toe_clearance_m");
  return {time, flexion, clearance};
}

Json makeTuneJson(const TuningResult& r, double seconds) {
  Json knobs = Json::array(), targets = Json::array();
  for (std::size_t k = 0; k < r.knobs.size(); ++k)
    knobs.push_back({{"key", r.knobs[k].key},
                     {"value", k < r.best.knobs.size() ? Json(r.best.knobs[k]) : Json(nullptr)},
                     {"at_range_end", k < r.knobAtBound.size() && r.knobAtBound[k]}});
  for (const TargetOutcome& t : r.targets)
    targets.push_back(
        {{"quantity", tuningQuantityKey(t.target.quantity)},
         {"value", tuningQuantityInKeyUnit(t.target.quantity, t.value)},
         {"min", std::isfinite(t.target.lower) ? Json(tuningQuantityInKeyUnit(t.target.quantity, t.target.lower))
                                               : Json(nullptr)},
         {"max", std::isfinite(t.target.upper) ? Json(tuningQuantityInKeyUnit(t.target.quantity, t.target.upper))
                                               : Json(nullptr)},
         {"hard", t.target.hard},
         {"met", t.met}});
  return {{"knobs", knobs},
          {"targets", targets},
          {"feasible", r.feasible},
          {"interrupted", r.interrupted},
          {"identifiable", r.identifiable},
          {"identifiability", r.identifiability},
          {"evaluations", r.evaluations},
          {"seconds", seconds},
          {"resolution",
           r.resolution.ran ? Json("At the knobs' resolution: " + r.resolution.verdict + ".") : Json(nullptr)},
          {"swing_time_s", std::isfinite(r.best.swingTime) ? Json(r.best.swingTime) : Json(nullptr)}};
}

}  // namespace

ApiReply ServeApi::tune(const std::string& body, const std::function<bool()>& clientGone) const {
  // At most limits_.maxConcurrentTunes at once: the others are told to come back.
  struct Slot {
    std::atomic<int>& running;
    ~Slot() { --running; }
  } slot{tunesRunning_};
  if (++tunesRunning_ > limits_.maxConcurrentTunes)
    return {503, Json{{"error", "tune: " + std::to_string(limits_.maxConcurrentTunes) +
                                    " tunings are under way on this server (its budget); try again when one ends"}}
                     .dump()};
  return hideServerPaths(answerOrError([&] {
    const auto start = std::chrono::steady_clock::now();
    const Json json = readRequestBody(body);
    checkRequestKeys(json, {"knobs", "targets"});
    const LegRequest request = readLegRequest(json);
    Leg leg = loadLeg(request, files_, limits_);
    const std::vector<TuningKnob> knobs = readTuneKnobs(json, leg.kneeFile);
    const std::vector<TuningTarget> targets = readTuneTargets(json, leg.participant);
    const TuningModel model(std::move(leg.participant), leg.kneeFile, knobs, request.lowering, request.added,
                            request.kneeSettings);
    model.checkKnobRanges();  // a range the leg or the knee file refuses is a 400 naming the knob, before any swing
    const SwingOptions options =
        makeServeSwingOptions(limits_, ServeSwing::kAsSimulate);  // as swingsim tune's: simulate's
    TuningSettings settings;
    settings.startPoints = kTuneStartPoints;
    settings.jobs = 1;  // one request, one thread: the server's pool serves the others
    settings.maxSeconds = kTuneMaxSeconds;
    const auto seconds = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    volatile bool stop = false;
    bool gone = false;  // the client has closed its connection
    std::atomic<long> swings{0};
    const TuningEvaluator evaluate = [&](const std::vector<double>& x) {
      if (!gone && clientGone && clientGone()) gone = true;
      if (stop || stopping_ || gone || seconds() > limits_.maxTuneWallSeconds ||
          swings.fetch_add(1) >= limits_.maxTuneSwings) {
        stop = true;
        throw RunError(stopping_ ? "swingsim serve is stopping"
                       : gone    ? "the client has gone"
                                 : "stopped at swingsim serve's budget");
      }
      return model.simulate(x, options);
    };
    TuningResult r = runKneeTuning(knobs, targets, evaluate, settings, {}, &stop);
    r.interrupted = r.interrupted || stop;
    if (!r.best.ran && stopping_) throw RunError("tune: swingsim serve is stopping; no swing ran");
    if (!r.best.ran && gone) throw RunError("tune: the client has gone; no swing ran");
    if (!r.best.ran)
      throw RunError("tune: stopped at swingsim serve's budget (" + formatNumber(limits_.maxTuneWallSeconds) + " s, " +
                     std::to_string(limits_.maxTuneSwings) + " swings) before any swing ran");
    return makeTuneJson(r, seconds());
  }));
}

}  // namespace swingsim
