#pragma once
// The leg a request to swingsim serve describes: a shipped participant by name or an
// uploaded participant YAML, the form's edits of its main numbers, a shipped knee model by
// name with its settings (model_scale, a microprocessor knee's swing states), the knee-axis
// lowering and an added shank mass. Built by the same loaders as the command line: every
// value gets the file's own checks, and a bad one is an InputError `key: expected (got V)`.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/json_file.h"
#include "io/knee_model_knobs.h"
#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "serve/shipped_files.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// The simulation budget of one request: a shared machine answers quickly or refuses.
struct ServeLimits {
  std::size_t maxBodyBytes = 64 * 1024;  ///< bytes of a request body (a participant file is ~2 KB)
  std::size_t maxOsimBytes = 4 << 20;    ///< bytes of an .osim upload's request (a scaled gait2354 model is ~420 KB)
  double maxSwingTimeLimit = 3.0;        ///< s, the largest swing_end.time_limit_s simulated
  double maxSwingWallSeconds = 5.0;      ///< s of wall-clock time one swing may take
  int maxSweepPoints = 41;               ///< lowerings of one sweep (0 to 0.2 m in 5 mm steps)
  double maxTuneWallSeconds = 30;        ///< s of one tuning; then it stops with the best setting so far
  long maxTuneSwings = 3000;             ///< swings of one tuning (P1 over 2 knobs takes ~500); then the same
  int maxConcurrentTunes =
      2;  ///< tunings at once (of 4 compute slots, ServeOptions::threads: the page's swings keep 2)
};

/// The options of the server's swings under `limits` (the wall-clock budget of one swing):
/// kAsSimulate those of `swingsim simulate` and `swingsim tune` (the energy bookkeeping on:
/// its extra states move the integrator's steps, so a swing shown is simulate's to the last
/// bit), kAsSweep those of `swingsim sweep`.
enum class ServeSwing { kAsSimulate, kAsSweep };
SwingOptions makeServeSwingOptions(const ServeLimits& limits, ServeSwing kind);

/// The participant keys the form edits (YAML key paths, in the file's units).
const std::vector<std::string>& editableParticipantKeys();

struct LegRequest {
  std::string participant;                                 ///< a shipped participant's name ("" with participantYaml)
  std::optional<std::string> participantYaml;              ///< an uploaded participant file's text
  std::vector<std::pair<std::string, std::string>> edits;  ///< editableParticipantKeys() -> the text typed
  std::optional<std::string> knee;                         ///< a shipped knee model's name; nullopt: the participant's
  std::optional<std::string> kneeYaml;                     ///< or an uploaded knee model file's text
  std::vector<std::pair<std::string, double>> kneeSettings;  ///< knee model key path -> value (file units)
  double lowering = 0;                                       ///< m
  AddedMass added;                                           ///< kg at m below the knee
};

/// Reads a request body: {"participant": NAME | "participant_yaml": TEXT, "edits": {KEY:
/// VALUE}, "knee": NAME | "knee_yaml": TEXT, "knee_settings": {KEY: NUMBER}, "lowering_m", "added_mass_kg",
/// "added_mass_position_m"}. Throws InputError naming the key for a wrong type or range.
LegRequest readLegRequest(const Json& body);

/// The top-level keys readLegRequest reads.
const std::vector<std::string>& legRequestKeys();

/// Refuses a key of `body` that is neither a leg request's nor in `extra` (a misspelt key,
/// `lowring_m`, was ignored and the unchanged swing answered): InputError naming the key, the
/// closest known key when one is near, and the keys the call takes. Long keys are cut in the
/// message.
void checkRequestKeys(const Json& body, const std::vector<std::string>& extra);

/// The participant and knee model a request gives, loaded and checked.
struct Leg {
  Participant participant;
  KneeModel knee;
  KneeModelKnobs kneeFile;  ///< the knee model's file (shipped or uploaded), whose numbers can be set
};

/// Loads the request's participant (with its edits) and knee model (with its settings).
/// An uploaded participant may name a shipped knee model only (NAME, NAME.yaml or
/// ../models/NAME.yaml), or bring its own as knee_yaml (then its knee_model is not read), and
/// no thigh_kinematics file: no file an upload names is read. An uploaded knee model is read
/// from its text, named upload-knee.yaml in messages.
/// Throws InputError for bad input, and for a swing_end.time_limit_s above the budget.
Leg loadLeg(const LegRequest& request, const ShippedFiles& files, const ServeLimits& limits);

/// The key an InputError message names: "segments.shank.mass_kg" of
/// "p1.yaml:11: segments.shank.mass_kg: must be positive (got -1)" ("" if none).
std::string findErrorKey(const std::string& message);

}  // namespace swingsim
