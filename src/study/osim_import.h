#pragma once
// A participant from one leg of a scaled OpenSim model, as `swingsim import-osim` and
// Python's swingsim.import_osim() make it (io/osim_model.h; docs/import-osim.md): checked by
// the participant loader before anything is written.
#include <functional>
#include <optional>
#include <string>

#include "io/osim_model.h"
#include "model/prosthesis_parts.h"

namespace swingsim {

/// The project's default knee for an imported participant: the damping table the Burkett
/// participants use (models/damping-table-default.yaml in the source tree).
std::string defaultImportKneePath();

/// Catalogue parts named for an import (each optional), and the catalogue (nullopt: the
/// shipped one, io/parts_catalogue_loader.h).
struct ImportPartNames {
  std::optional<std::string> knee, pylon, ankle, foot, catalogue;
  /// The id named for `category`.
  std::optional<std::string>& of(PartCategory category);
  const std::optional<std::string>& of(PartCategory category) const;
};
/// The parts `names` names, each checked against its catalogue; an InputError names the
/// argument as `label(key)` gives it, key one of knee, pylon, ankle, foot, catalogue
/// ("--knee-part", "import_osim(): knee_part"). nullopt: no part named.
std::optional<ProsthesisPartsChoice> chooseImportParts(const ImportPartNames& names,
                                                       const std::function<std::string(const std::string&)>& label);

/// An imported participant: its YAML text (paths relative to the folder given) and name.
struct ImportedParticipantYaml {
  std::string text;
  std::string name;
};

/// The participant of `modelPath`'s leg (options.side) as YAML for a file in `folder`, its
/// numbers' sources in its leading comments. The knee model (options.kneeModelPath, made
/// absolute) must load. Throws InputError naming the model when the loader would refuse it.
ImportedParticipantYaml importOsimParticipant(const std::string& modelPath, OsimImportOptions options,
                                              const std::string& folder);
/// Same, from the model's XML text (swingsim serve's upload); `label` names it in messages.
ImportedParticipantYaml importOsimParticipantText(const std::string& modelText, const std::string& label,
                                                  OsimImportOptions options, const std::string& folder);

}  // namespace swingsim
