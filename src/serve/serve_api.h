#pragma once
// The JSON API of swingsim serve (docs/serve.md), without HTTP: each call takes a request
// body and returns the status and the JSON to send. It calls the library as the command line
// and Python do (loaders, makeSwingSetup, simulateSwing, runSweep, the report's JSON and SVG)
// and has no physics of its own. Bad input is 400 with {"error", "key", "message"}: the
// loaders' `key: expected (got V)` text and the key, for the page to show beside its field;
// a swing that fails (RunError) is 422 {"error"}. Every call is safe from several threads.
#include <string>

#include "serve/leg_request.h"
#include "serve/shipped_files.h"

namespace swingsim {

struct ApiReply {
  int status = 200;
  std::string body;  ///< JSON text
};

class ServeApi {
 public:
  ServeApi(ShippedFiles files, ServeLimits limits);

  /// GET /api/files: {"participants": [NAME], "knee_models": [NAME], "editable_keys": [KEY],
  /// "limits": {...}}.
  ApiReply listFiles() const;
  /// POST /api/participant (a leg request; with participant_yaml it is the upload): {"name",
  /// "fields": {KEY: value in file units}, "knee_model", "knee_settings",
  /// "drive", "max_lowering_m", "participant_yaml", "knee_yaml", "knee_states"} (the two
  /// YAML texts are the export, loadable by the command line; knee_states: a microprocessor
  /// knee's states with their stiffness, damping and equilibrium, else empty).
  ApiReply describeParticipant(const std::string& body) const;
  /// POST /api/simulate: `swingsim simulate --json`'s content plus "knee_model",
  /// "stick_figure_svg" (the report's animated figure, null without a swing end) and
  /// "trajectory" (samples about 10 ms apart, ground-frame landmarks in m).
  ApiReply simulate(const std::string& body) const;
  /// POST /api/sweep (a leg request plus "lowering_step_m", default 0.01, and
  /// "lowering_max_m", default 0.2): {"lowerings_m", "swing_times_s", "fastest_lowering_m",
  /// "fastest_swing_time_s", "symmetry", "figure_svg", "sweep": `swingsim sweep --json`'s
  /// participant}. Refused (400) above limits.maxSweepPoints lowerings.
  ApiReply sweep(const std::string& body) const;

  const ServeLimits& getLimits() const { return limits_; }

 private:
  ShippedFiles files_;
  ServeLimits limits_;
};

}  // namespace swingsim
