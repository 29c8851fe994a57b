#include "study/osim_import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iterator>
#include <utility>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/parts_catalogue_loader.h"

namespace swingsim {
namespace {

// The name the imported participant is checked under, and a message without it and its
// line ("imported-participant.yaml:20: segments..." -> "segments...").
const std::string kImportedName = "imported-participant.yaml";
std::string dropImportedPrefix(const std::string& message) {
  const auto at = message.find(kImportedName + ":");
  if (at == std::string::npos) return message;
  std::size_t rest = at + kImportedName.size() + 1;
  while (rest < message.size() && std::isdigit(static_cast<unsigned char>(message[rest]))) ++rest;
  if (message.compare(rest, 2, ": ") == 0) rest += 2;
  return message.substr(rest);
}

// The participant of `model` (read from `label`) as YAML text, checked by the loader.
ImportedParticipantYaml formatImported(const OsimModel& model, const std::string& label, OsimImportOptions o,
                                       const std::string& folder) {
  o.kneeModelPath = std::filesystem::absolute(o.kneeModelPath).lexically_normal().string();
  loadKneeModel(o.kneeModelPath);  // a knee model that does not load is refused before anything is written
  const OsimParticipant imported = calcOsimParticipant(model, o);
  const std::string text = formatParticipantYaml(imported.participant, folder, imported.provenance);
  // What is written loads as it is: the loader's checks apply here, before any file is
  // written. The model's own checks (io/osim_model_checks.h) come first and name its
  // element; one the loader still refuses is named by the model, not by a YAML not written.
  try {
    parseParticipant(text, folder + "/" + kImportedName);
  } catch (const InputError& e) {
    throw InputError(label + ": the participant imported from it is refused: " + dropImportedPrefix(e.what()) +
                     " (in the participant YAML, not written)");
  }
  return {text, imported.participant.name};
}

}  // namespace

std::optional<std::string>& ImportPartNames::of(PartCategory category) {
  switch (category) {
    case PartCategory::kKnee:
      return knee;
    case PartCategory::kPylon:
      return pylon;
    case PartCategory::kAnkle:
      return ankle;
    case PartCategory::kFoot:
      break;
  }
  return foot;
}

const std::optional<std::string>& ImportPartNames::of(PartCategory category) const {
  return const_cast<ImportPartNames&>(*this).of(category);
}

std::optional<ProsthesisPartsChoice> chooseImportParts(const ImportPartNames& names,
                                                       const std::function<std::string(const std::string&)>& label) {
  if (std::none_of(std::begin(kPartCategories), std::end(kPartCategories),
                   [&](PartCategory category) { return names.of(category).has_value(); })) {
    if (names.catalogue)
      throw InputError(label("catalogue") + ": names no part (give a knee, pylon, ankle or foot part)");
    return std::nullopt;
  }
  ProsthesisPartsChoice c;
  c.cataloguePath =
      std::filesystem::absolute(names.catalogue.value_or(defaultPartsCataloguePath())).lexically_normal().string();
  const PartsCatalogue catalogue = loadPartsCatalogue(c.cataloguePath);
  for (PartCategory category : kPartCategories) {
    const std::optional<std::string>& given = names.of(category);
    if (!given) continue;
    const std::string problem = checkCataloguePart(catalogue, *given, category);
    if (!problem.empty())
      throw InputError(label(partCategoryKey(category)) + ": " + problem + " (got '" + *given + "')");
    partId(c, category) = *given;
  }
  return c;
}

std::string defaultImportKneePath() { return std::string(SWINGSIM_SOURCE_DIR) + "/models/damping-table-default.yaml"; }

ImportedParticipantYaml importOsimParticipant(const std::string& modelPath, OsimImportOptions o,
                                              const std::string& folder) {
  return formatImported(loadOsimModel(modelPath), modelPath, std::move(o), folder);
}

ImportedParticipantYaml importOsimParticipantText(const std::string& modelText, const std::string& label,
                                                  OsimImportOptions o, const std::string& folder) {
  return formatImported(parseOsimModel(modelText, label), label, std::move(o), folder);
}

}  // namespace swingsim
