#pragma once
// Study YAML of kind knee-axis-sweep (studies/burkett2004.yaml): the participants, the
// lowering grid, added masses and integrator settings of a knee-axis sweep.
#include <string>

#include "sweep/sweep.h"

namespace swingsim {

/// Reads studies/*.yaml of kind knee-axis-sweep. Throws InputError.
SweepStudy loadSweepStudy(const std::string& path);
/// Same, from YAML text (tests, fuzzers); participant paths resolve against `path`'s folder.
SweepStudy parseSweepStudy(const std::string& text, const std::string& path);
/// The YAML text of a sweep study as a file in folder `baseDir` (paths relative to it).
std::string formatSweepStudyYaml(const SweepStudy& study, const std::string& baseDir);

}  // namespace swingsim
