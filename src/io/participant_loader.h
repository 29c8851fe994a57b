#pragma once
// Loads participants/*.yaml (Burkett 2004 Table 2 plus our documented assumptions).
#include <string>

#include "model/leg_parameters.h"

namespace swingsim {

/// Reads and checks a participant file. Throws InputError `file:line: key: ... (got V)`
/// for unknown or missing keys, wrong types, non-finite or impossible values (negative
/// mass/length/inertia, a COM outside its segment, a non-increasing hip-moment table).
Participant loadParticipant(const std::string& path);
/// Same, from YAML text (tests, fuzzers); relative paths resolve against `path`'s folder.
Participant parseParticipant(const std::string& text, const std::string& path);

}  // namespace swingsim
