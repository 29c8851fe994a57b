#pragma once
// The JSON API of swingsim serve (docs/serve.md), without HTTP: each call takes a request
// body and returns the status and the JSON to send. It calls the library as the command line
// and Python do (loaders, makeSwingSetup, simulateSwing, runSweep, the report's JSON and SVG)
// and has no physics of its own. Bad input is 400 with {"error", "key", "message"}: the
// loaders' `key: expected (got V)` text and the key, for the page to show beside its field;
// a swing that fails (RunError) is 422 {"error"}. No answer names the server's data folder.
// Every call is safe from several threads.
#include <atomic>
#include <functional>
#include <string>

#include "serve/api_reply.h"
#include "serve/leg_request.h"
#include "serve/shipped_files.h"

namespace swingsim {

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

  /// POST /api/report (a sweep request): {"file_name", "html"}: the sweep's report.html for
  /// this leg, as `swingsim sweep` writes it (one self-contained page).
  ApiReply report(const std::string& body) const;
  /// POST /api/import_osim {"osim_text", "file_name", "side": "r"|"l", "knee": NAME,
  /// "shank_mass_kg", "foot_mass_kg"}: {"participant_yaml", "name"}, import-osim's participant
  /// (its knee a shipped model), for the page to use as an upload. Nothing is written.
  ApiReply importOsim(const std::string& body) const;
  /// POST /api/export_osim (a leg request plus "side"): {"osim_file_name", "osim_text",
  /// "sto_file_name", "sto_text"}: export-osim's model of the leg (lowering, added mass) and
  /// simulate's trajectory .sto of its swing, which OpenSim plays on it.
  ApiReply exportOsim(const std::string& body) const;
  /// POST /api/tune (a leg request plus "knobs": [{"key", "min", "max", "log_scale"}] and
  /// "targets": {"swing_time_s" (default the sound limb's), "peak_knee_flexion_deg": [min,
  /// max] (default [60, 90]), "min_toe_clearance_m" (default 0.08)}): the setting that brings
  /// the swing time to the target within the hard limits (swingsim tune's method, 24 start
  /// points, at most 10 s of polish, 30 s or 3000 swings in all, then the best so far with
  /// "interrupted"; 503 while limits.maxConcurrentTunes others run):
  /// {"knobs": [{"key", "value", "at_range_end"}], "targets", "feasible", "interrupted",
  /// "identifiable", "identifiability", "evaluations", "seconds", "swing_time_s"}.
  /// `clientGone` (optional), asked before each swing: true once the request's client has
  /// gone (serve/peer_watch.h); the tuning then ends as a stopping server's does, its answer
  /// read by nobody, and its compute slot is free for the next request.
  ApiReply tune(const std::string& body, const std::function<bool()>& clientGone) const;
  ApiReply tune(const std::string& body) const { return tune(body, nullptr); }

  const ServeLimits& getLimits() const { return limits_; }

  /// The server is stopping (SIGTERM, Ctrl-C): a tuning under way ends at its next swing with
  /// the best so far, "interrupted", instead of running to its budget.
  void requestStop() { stopping_ = true; }

 private:
  /// `reply` with the server's data folder taken out of every path in it ("<data>/models/x.yaml"
  /// -> "models/x.yaml"): no answer shows where the server's files are.
  ApiReply hideServerPaths(ApiReply reply) const;

  ShippedFiles files_;
  ServeLimits limits_;
  mutable std::atomic<int> tunesRunning_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace swingsim
