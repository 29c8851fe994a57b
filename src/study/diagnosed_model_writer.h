#pragma once
// `swingsim diagnose --save-model FILE`: the base model with the accepted effects at their
// fitted values, as files the other commands read (the cylinder: a knee model YAML; the
// swing: a knee model YAML and, beside it, FILE-participant.yaml with the participant-level
// effects).
#include <string>
#include <vector>

#include "identify/diagnosis_engine.h"
#include "study/diagnosis_study.h"

namespace swingsim {

/// Writes the diagnosed model of `study` (whose plant is `plant`) to `path`; returns the
/// paths written. `command` names the run in the files' header. Throws InputError where the
/// base files cannot carry the effects.
std::vector<std::string> saveDiagnosedModel(const DiagnosisStudy& study, const DiagnosisPlant& plant,
                                            const Diagnosis& diagnosis, const std::string& path,
                                            const std::string& command);

}  // namespace swingsim
