#pragma once
// `swingsim generate STUDY.yaml`: synthetic measurement data from a model. The study's
// `kind:` selects the generator (cylinder-bench: bench records of a Mauch cylinder;
// swing-kinematics: swing records of a participant and knee model), each with hidden effects
// the fitted models do not know, noise and a seed.
#include <optional>
#include <string>

namespace swingsim {

/// Writes the files the study at `studyPath` describes, into `outDir` if given (--out), else
/// the study's output_dir; a table of what was written on stdout. Everything is computed
/// before the first file is written. Throws InputError (file, line, key).
void runGenerate(const std::string& studyPath, const std::optional<std::string>& outDir);

}  // namespace swingsim
