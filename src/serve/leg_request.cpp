#include "serve/leg_request.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/identifier.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/text_format.h"
#include "io/knee_model_knobs.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/yaml_tree.h"
#include "study/run_arguments.h"
#include "study/simulate_run.h"

namespace swingsim {
namespace {

constexpr double kMaxAddedMassPosition = kMaxSegmentLength;  // m: below the knee, along the shank

std::string describeJson(const Json& value) { return value.dump(); }

double readNumber(const Json& body, const std::string& key, double fallback) {
  if (!body.contains(key) || body[key].is_null()) return fallback;
  const Json& v = body[key];
  if (!v.is_number()) throw InputError(key + ": expected a number (got " + describeJson(v) + ")");
  return v.get<double>();
}

std::optional<std::string> readText(const Json& body, const std::string& key) {
  if (!body.contains(key) || body[key].is_null()) return std::nullopt;
  if (!body[key].is_string()) throw InputError(key + ": expected a string (got " + describeJson(body[key]) + ")");
  return body[key].get<std::string>();
}

// The form's edits: {KEY: "text" or number}, each KEY one of editableParticipantKeys().
std::vector<std::pair<std::string, std::string>> readEdits(const Json& body) {
  std::vector<std::pair<std::string, std::string>> edits;
  if (!body.contains("edits")) return edits;
  if (!body["edits"].is_object()) throw InputError("edits: expected a map of participant keys to values");
  const auto& keys = editableParticipantKeys();
  for (const auto& [key, value] : body["edits"].items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      throw InputError("edits: expected a main number of the form, e.g. body_mass_kg (got '" + key + "')");
    if (!value.is_string() && !value.is_number())
      throw InputError(key + ": expected a number (got " + describeJson(value) + ")");
    edits.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  }
  return edits;
}

// A knee setting the page offers: the scale of the knee law, a microprocessor knee's states.
bool isKneeSettingKey(const std::string& key) {
  if (key == "knee_effects.model_scale") return true;
  // impedance_state_machine.states[I].KEY, I of one or two digits, KEY of letters and _.
  const std::string_view prefix = "impedance_state_machine.states[";
  if (key.compare(0, prefix.size(), prefix) != 0) return false;
  std::size_t i = prefix.size(), digits = 0;
  while (i < key.size() && std::isdigit(static_cast<unsigned char>(key[i]))) ++i, ++digits;
  if (digits < 1 || digits > 2 || key.compare(i, 2, "].") != 0) return false;
  const std::string_view name = std::string_view(key).substr(i + 2);
  return !name.empty() && std::all_of(name.begin(), name.end(),
                                      [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; });
}

std::vector<std::pair<std::string, double>> readKneeSettings(const Json& body) {
  std::vector<std::pair<std::string, double>> settings;
  if (!body.contains("knee_settings")) return settings;
  if (!body["knee_settings"].is_object())
    throw InputError("knee_settings: expected a map of knee model keys to numbers");
  for (const auto& [key, value] : body["knee_settings"].items()) {
    if (!isKneeSettingKey(key))
      throw InputError(
          "knee_settings: expected knee_effects.model_scale or impedance_state_machine.states[I].KEY (got '" + key +
          "')");
    if (!value.is_number()) throw InputError(key + ": expected a number (got " + describeJson(value) + ")");
    settings.emplace_back(key, value.get<double>());
  }
  return settings;
}

// The form's edits into `root`. A segment's mass edited without its inertia keeps its radius of
// gyration: the inertia scales with the mass (as import-osim's --shank-mass-kg), so a lighter
// prosthetic shank is not given the intact one's inertia.
void applyEdits(YamlTree& root, const std::vector<std::pair<std::string, std::string>>& edits) {
  const auto edited = [&](const std::string& key) {
    for (const auto& e : edits)
      if (e.first == key) return true;
    return false;
  };
  std::vector<std::pair<std::string, double>> inertiaScales;  // (inertia key, new mass / old mass)
  for (const auto& [key, value] : edits) {
    const std::string suffix = ".mass_kg";
    if (key.rfind("segments.", 0) != 0 || key.size() <= suffix.size() ||
        key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string inertiaKey = key.substr(0, key.size() - suffix.size()) + ".inertia_kgm2";
    if (edited(inertiaKey)) continue;
    const YamlTree oldMass = root.find(key);
    try {
      const double newMass = std::stod(value);
      if (oldMass.number() && *oldMass.number() > 0 && newMass > 0 && std::isfinite(newMass))
        inertiaScales.emplace_back(inertiaKey, newMass / *oldMass.number());
    } catch (const std::exception&) {
      // Not a number: the participant loader says what is wrong with the edited value.
    }
  }
  for (const auto& [key, value] : edits) root.set(key, value, "the participant");
  for (const auto& [key, scale] : inertiaScales)
    if (const auto inertia = root.find(key).number())  // else the loader refuses the file's value
      root.set(key, fmt("%.17g", *inertia * scale), "the participant");
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); !from.empty() && at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

std::string formatShippedKneeList(const ShippedFiles& files) {
  std::string list;
  for (const auto& n : files.getKneeNames()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

const std::string kUploadedKneeName = "upload-knee.yaml";

// An upload's knee_model as ../models/NAME.yaml of a shipped model (with a knee upload it is
// not read, so not checked), and no measured thigh file: the server reads no path an upload
// gives. True if knee_model was rewritten.
bool checkUploadedPaths(YamlTree root, const ShippedFiles& files, bool kneeUploaded) {
  if (!root.get("thigh_kinematics").isNull())
    throw InputError(
        "thigh_kinematics: expected none in an uploaded participant (swingsim serve reads no file an upload "
        "names; use drive: hip_moment) (got a thigh_kinematics entry)");
  if (kneeUploaded) return false;  // its knee_model is a name only: the knee comes from the knee upload's text
  const YamlTree knee = root.get("knee_model");
  if (!knee.isScalar()) return false;  // the loader says what is missing
  std::string name = knee.scalar();
  const std::string prefix = "../models/", suffix = ".yaml";
  if (name.rfind(prefix, 0) == 0) name = name.substr(prefix.size());
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    name = name.substr(0, name.size() - suffix.size());
  const auto& names = files.getKneeNames();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw InputError("knee_model: expected a shipped knee model by name, one of " + formatShippedKneeList(files) +
                     ", or a knee model uploaded with it (got '" + knee.scalar() + "')");
  if (knee.scalar() == prefix + name + suffix) return false;
  root.set("knee_model", prefix + name + suffix, "the participant");
  return true;
}

// The participant's YAML tree: the shipped file's, or the upload's (checked), with the edits.
Participant loadRequestParticipant(const LegRequest& request, const ShippedFiles& files) {
  const bool uploaded = request.participantYaml.has_value();
  // An upload resolves ../models/NAME.yaml as a shipped participant does; nothing is read there.
  const std::string source =
      uploaded ? files.getParticipantsDir() + "/upload.yaml" : files.findParticipantPath(request.participant);
  const std::string text = uploaded ? *request.participantYaml : readFile(source);
  YamlTree root = YamlTree::parse(text, "participant_yaml", "a participant file");
  if (!root.isMap())
    throw InputError("participant_yaml: expected a map of participant keys (got another YAML document)");
  // The text as given where nothing was changed, so that messages give the upload's own lines.
  const bool rewritten = uploaded && checkUploadedPaths(root, files, request.kneeYaml.has_value());
  applyEdits(root, request.edits);
  try {
    return parseParticipant(uploaded && !rewritten && request.edits.empty() ? text : root.emit(), source);
  } catch (const InputError& e) {
    if (!uploaded) throw;
    throw InputError(replaceAll(e.what(), source, "upload.yaml"));  // no path of the server's in an upload's messages
  }
}

// The knee model file: the request's upload, a shipped one by name, or the participant's.
KneeModelKnobs loadRequestKneeFile(const LegRequest& request, const Participant& p, const ShippedFiles& files) {
  if (!request.kneeYaml) return KneeModelKnobs(request.knee ? files.findKneePath(*request.knee) : p.kneeModelPath);
  if (!YamlTree::parse(*request.kneeYaml, "knee_yaml", "a knee model file").isMap())
    throw InputError("knee_yaml: expected a map of knee model keys (got another YAML document)");
  const std::string path = files.getModelsDir() + "/" + kUploadedKneeName;
  try {
    return KneeModelKnobs::fromText(*request.kneeYaml, path);
  } catch (const InputError& e) {
    throw InputError(replaceAll(e.what(), path, kUploadedKneeName));
  }
}

KneeModel loadRequestKnee(const LegRequest& request, const KneeModelKnobs& knobs) {
  std::vector<std::string> keys;
  std::vector<double> values;
  for (const auto& [key, value] : request.kneeSettings) {
    keys.push_back(key);
    values.push_back(value);
  }
  for (const auto& key : keys)
    if (const std::string problem = knobs.checkKey(key); !problem.empty()) throw InputError(key + ": " + problem);
  return knobs.make(keys, values);  // the loader's message names the key (its line is the edited tree's)
}

}  // namespace

SwingOptions makeServeSwingOptions(const ServeLimits& limits, ServeSwing kind) {
  // As simulate (its integrator and stop-impact bookkeeping), or as the sweep.
  SwingOptions options =
      kind == ServeSwing::kAsSimulate ? makeSimulateOptions(std::nullopt, std::nullopt) : SwingOptions{};
  options.maxWallSeconds = limits.maxSwingWallSeconds;
  return options;
}

const std::vector<std::string>& editableParticipantKeys() {
  static const std::vector<std::string> kKeys = [] {
    std::vector<std::string> keys = {"height_m", "body_mass_kg"};
    for (const char* segment : {"thigh", "shank", "foot"})
      for (const char* field : {"length_m", "mass_kg", "com_from_distal_m", "inertia_kgm2"})
        keys.push_back(std::string("segments.") + segment + "." + field);
    keys.insert(keys.end(), {"knee_friction_Nm", "sound_limb_swing_time_s", "hip_moment.time_scale"});
    // A compliant socket (docs/socket.md): a value typed turns it on, the rest at its defaults.
    // The dampers hold the socket more than its springs over a swing: both are here.
    keys.insert(keys.end(),
                {"socket.piston_stiffness_N_per_m", "socket.piston_damping_N_s_per_m",
                 "socket.rotation_stiffness_Nm_per_rad", "socket.rotation_damping_Nm_s_per_rad", "socket.mass_kg"});
    return keys;
  }();
  return kKeys;
}

const std::vector<std::string>& legRequestKeys() {
  static const std::vector<std::string> keys = {"participant", "participant_yaml", "edits",
                                                "knee",        "knee_yaml",        "knee_settings",
                                                "lowering_m",  "added_mass_kg",    "added_mass_position_m"};
  return keys;
}

namespace {

// Levenshtein distance, for "did you mean" (keys are short; a long one is cut first).
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

void checkRequestKeys(const Json& body, const std::vector<std::string>& extra) {
  if (!body.is_object()) return;  // readLegRequest says what is wrong with it
  std::vector<std::string> known = legRequestKeys();
  known.insert(known.end(), extra.begin(), extra.end());
  for (const auto& [key, value] : body.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const std::string shown = key.size() > 60 ? key.substr(0, 60) + "..." : key;
    std::string closest;
    std::size_t best = 3;  // at most two edits away
    for (const auto& k : known)
      if (const std::size_t d = editDistance(shown, k); d < best) best = d, closest = k;
    std::string all;
    for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
    throw InputError(shown + ": unknown request key" + (closest.empty() ? "" : " (did you mean " + closest + "?)") +
                     "; this call takes " + all);
  }
}

LegRequest readLegRequest(const Json& body) {
  if (!body.is_object()) throw InputError("request: expected a JSON object (got " + describeJson(body) + ")");
  LegRequest r;
  r.participantYaml = readText(body, "participant_yaml");
  r.participant = readText(body, "participant").value_or("");
  if (!r.participantYaml && r.participant.empty())
    throw InputError("participant: expected a shipped participant's name or a participant_yaml upload (got neither)");
  r.edits = readEdits(body);
  r.knee = readText(body, "knee");
  r.kneeYaml = readText(body, "knee_yaml");
  if (r.knee && r.kneeYaml)
    throw InputError("knee_yaml: expected a shipped knee by name or an uploaded knee model, not both (got both)");
  r.kneeSettings = readKneeSettings(body);
  r.lowering = readNumber(body, "lowering_m", 0);
  if (const std::string problem = checkLowering(r.lowering); !problem.empty())
    throw InputError("lowering_m: " + problem + " (got " + formatNumber(r.lowering) + ")");
  r.added.mass = readNumber(body, "added_mass_kg", 0);
  if (!(r.added.mass >= 0 && r.added.mass <= kMaxSegmentMass))
    throw InputError("added_mass_kg: expected 0 to " + formatNumber(kMaxSegmentMass) + " kg (got " +
                     formatNumber(r.added.mass) + ")");
  r.added.distanceBelowKnee = readNumber(body, "added_mass_position_m", 0);
  if (!(r.added.distanceBelowKnee >= 0 && r.added.distanceBelowKnee <= kMaxAddedMassPosition))
    throw InputError("added_mass_position_m: expected 0 to " + formatNumber(kMaxAddedMassPosition) +
                     " m below the knee (got " + formatNumber(r.added.distanceBelowKnee) + ")");
  return r;
}

Leg loadLeg(const LegRequest& request, const ShippedFiles& files, const ServeLimits& limits) {
  Participant p = loadRequestParticipant(request, files);
  if (p.swingEnd.timeLimit > limits.maxSwingTimeLimit)
    throw InputError("swing_end.time_limit_s: expected at most " + formatNumber(limits.maxSwingTimeLimit) +
                     " s on swingsim serve (its simulation budget) (got " + formatNumber(p.swingEnd.timeLimit) + ")");
  KneeModelKnobs kneeFile = loadRequestKneeFile(request, p, files);
  KneeModel knee = loadRequestKnee(request, kneeFile);
  return {std::move(p), std::move(knee), std::move(kneeFile)};
}

namespace {

// The key at `at` when "KEY: " starts there ("" otherwise).
std::string keyAt(const std::string& message, std::size_t at) {
  const std::size_t n = identifierLength(std::string_view(message).substr(std::min(at, message.size())), ".[]");
  return n > 0 && message.compare(at + n, 2, ": ") == 0 ? message.substr(at, n) : "";
}

}  // namespace

std::string findErrorKey(const std::string& message) {
  // "FILE:LINE: KEY: ..." (the first such prefix on the first line whose key follows), else
  // "KEY: ...".
  const std::size_t lineEnd = std::min(message.find('\n'), message.size());
  for (std::size_t i = 0; i < lineEnd; ++i) {
    if (message[i] != ':') continue;
    std::size_t j = i + 1;
    while (j < message.size() && std::isdigit(static_cast<unsigned char>(message[j]))) ++j;
    if (j == i + 1 || message.compare(j, 2, ": ") != 0) continue;
    if (std::string key = keyAt(message, j + 2); !key.empty()) return key;
  }
  return keyAt(message, 0);
}

}  // namespace swingsim
