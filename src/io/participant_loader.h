#pragma once
// The participant file (participants/*.yaml: Burkett 2004 Table 2 plus our documented
// assumptions), read and written through one description of its fields (io/yaml_archive.h).
#include <string>
#include <vector>

#include "model/leg_parameters.h"

namespace swingsim {

/// Plausibility bounds that catch a unit mistake (millimetres for metres, grams for
/// kilograms) where it was made, rather than as a strange swing; the .osim import checks
/// its model against the same (io/osim_model_checks.h).
constexpr double kMaxSegmentLength = 1.5;  ///< m: longer than any thigh, shank or foot
constexpr double kMaxSegmentMass = 150;    ///< kg: heavier than a plausible whole body
constexpr double kMaxBodyMass = 500;       ///< kg

/// Reads and checks a participant file. Throws InputError `file:line: key: ... (got V)`
/// for unknown or missing keys, wrong types, non-finite or impossible values (negative
/// mass/length/inertia, a COM outside its segment, a non-increasing hip-moment table).
Participant loadParticipant(const std::string& path);
/// Same, from YAML text (tests, fuzzers); relative paths resolve against `path`'s folder.
Participant parseParticipant(const std::string& text, const std::string& path);

/// The YAML text of `participant` as a file in folder `baseDir` (its knee_model path is
/// written relative to that folder), with `header` lines as leading comments.
std::string formatParticipantYaml(const Participant& participant, const std::string& baseDir,
                                  const std::string& header = "");

/// A participant to store over an existing file.
struct ParticipantEdit {
  std::string path;         ///< the file to replace (a symlink: its target is replaced)
  Participant participant;  ///< the new content
};
/// Stores every edit through the parsed document, never as text patches: each file's new
/// text (its leading comment block kept; comments elsewhere are not) is written to a
/// temporary file beside it and loaded back; only when every file loads back to what was
/// meant are they renamed into place, keeping each file's permission bits and writing
/// through symlinks. Throws InputError or RunError, and then no file has been changed.
void storeParticipants(const std::vector<ParticipantEdit>& edits);

}  // namespace swingsim
