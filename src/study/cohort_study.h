#pragma once
// Study YAML of kind cohort-sweep (studies/cohort-example.yaml, docs/cohort.md): how many
// participants to draw, the seed, the template participant, one distribution with its
// source per cohort property (sweep/cohort_sampling.h), and the lowering grid and
// integrator of the knee-axis sweep (the same maps as a knee-axis-sweep study).
#include <functional>
#include <string>

#include "sweep/cohort_run.h"

namespace swingsim {

/// True if the YAML file at `path` says `kind: cohort-sweep` (a file that cannot be read
/// or has no kind is not; its reader then says why).
bool isCohortStudyFile(const std::string& path);

/// Reads a cohort-sweep study and draws its participants. Throws InputError
/// (`file:line: key: what is wrong (got VALUE)`). `beforeDrawing`, if set, is called with
/// the checked study before any participant is drawn (drawing 100,000 takes a minute): a run
/// announces its size and refuses one above its limit there.
Cohort loadCohortStudy(const std::string& path, const std::function<void(const Cohort&)>& beforeDrawing = {});
/// Same, from YAML text (tests); paths resolve against `path`'s folder.
Cohort parseCohortStudy(const std::string& text, const std::string& path);

}  // namespace swingsim
