// swingsim serve's OpenSim calls (serve/serve_api.h): an uploaded .osim made a participant
// by import-osim's sequence, and the page's leg exported as export-osim and simulate write it.
#include <algorithm>
#include <optional>

#include "core/input_error.h"
#include "io/participant_loader.h"
#include "io/trajectory_writer.h"
#include "serve/serve_api.h"
#include "study/osim_export.h"
#include "study/osim_import.h"
#include "study/simulate_run.h"

namespace swingsim {
namespace {

// "side": "r" or "l" (default r).
char readSide(const Json& body) {
  if (!body.contains("side")) return 'r';
  const Json& v = body["side"];
  if (!v.is_string() || (v != "r" && v != "l")) throw InputError("side: expected r or l (got " + v.dump() + ")");
  return v.get<std::string>().front();
}

std::optional<double> readOptionalPositive(const Json& body, const std::string& key) {
  if (!body.contains(key) || body[key].is_null()) return std::nullopt;
  const Json& v = body[key];
  if (!v.is_number() || !(v.get<double>() > 0) || !(v.get<double>() <= kMaxSegmentMass))
    throw InputError(key + ": expected a positive mass up to " + formatNumber(kMaxSegmentMass) + " kg (got " +
                     v.dump() + ")");
  return v.get<double>();
}

// The upload's file name for messages: its last path part, at most 100 bytes cut at a UTF-8
// character's start, control characters as '_'.
std::string readUploadLabel(const Json& body) {
  std::string label =
      body.contains("file_name") && body["file_name"].is_string() ? body["file_name"].get<std::string>() : "";
  label = label.substr(label.find_last_of("/\\") == std::string::npos ? 0 : label.find_last_of("/\\") + 1);
  for (char& c : label)
    if (static_cast<unsigned char>(c) < 0x20) c = '_';
  std::size_t end = std::min<std::size_t>(label.size(), 100);
  while (end > 0 && end < label.size() && (static_cast<unsigned char>(label[end]) & 0xC0) == 0x80)
    --end;  // not inside a character
  return end == 0 ? "upload.osim" : label.substr(0, end);
}

}  // namespace

ApiReply ServeApi::importOsim(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const Json json = readRequestBody(body);
    if (!json.is_object() || !json.contains("osim_text") || !json["osim_text"].is_string())
      throw InputError("osim_text: expected the text of an OpenSim model file (.osim)");
    OsimImportOptions o;
    o.side = readSide(json);
    if (json.contains("knee") && !json["knee"].is_string())
      throw InputError("knee: expected a shipped knee model's name (got " + json["knee"].dump() + ")");
    o.kneeModelPath = files_.findKneePath(json.value("knee", std::string("damping-table-default")));
    o.shankMass = readOptionalPositive(json, "shank_mass_kg");
    o.footMass = readOptionalPositive(json, "foot_mass_kg");
    // Catalogue parts by id, from the shipped catalogue only (a request names no server path).
    ImportPartNames parts;
    for (PartCategory category : kPartCategories) {
      const std::string key = std::string(partCategoryKey(category)) + "_part";
      if (!json.contains(key)) continue;
      if (!json[key].is_string())
        throw InputError(key + ": expected a part's catalogue id (got " + json[key].dump() + ")");
      parts.of(category) = json[key].get<std::string>();
    }
    o.parts = chooseImportParts(parts, [](const std::string& key) { return key + "_part"; });
    // Paths relative to the participants folder: knee_model is ../models/NAME.yaml, as an upload's must be.
    const ImportedParticipantYaml imported = importOsimParticipantText(
        json["osim_text"].get<std::string>(), readUploadLabel(json), o, files_.getParticipantsDir());
    return Json{{"participant_yaml", imported.text}, {"name", imported.name}};
  }));
}

ApiReply ServeApi::exportOsim(const std::string& body) const {
  return hideServerPaths(answerOrError([&] {
    const Json json = readRequestBody(body);
    checkRequestKeys(json, {"side"});
    const LegRequest request = readLegRequest(json);
    const char side = readSide(json);
    Leg leg = loadLeg(request, files_, limits_);
    const std::string stem = makeTrajectoryFileStem(leg.participant.name, request.lowering);
    const std::optional<AddedMass> added =
        request.added.mass > 0 ? std::optional<AddedMass>(request.added) : std::nullopt;
    const std::string osim = formatParticipantOsim(leg.participant, leg.knee,
                                                   OsimExportOptions{side, request.lowering, added}, stem + ".sto");
    const SwingOptions options = makeServeSwingOptions(limits_, ServeSwing::kAsSimulate);  // so the .sto is simulate's
    const SwingResult r =
        runSimulate(std::move(leg.participant), leg.knee, request.lowering, request.added, options).result;
    return Json{{"osim_file_name", stem + ".osim"},
                {"osim_text", osim},
                {"sto_file_name", stem + ".sto"},
                {"sto_text", formatTrajectorySto(r.trajectory, stem, side)}};
  }));
}

}  // namespace swingsim
