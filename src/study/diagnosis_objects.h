#pragma once
// A diagnosis study whose parts are objects rather than files (Python's swingsim.diagnose on
// a study built in Python): the study's settings from YAML text, and for a swing study the
// participant, base knee model and any record given in memory; what is not given is read
// from the study's paths as loadDiagnosisPlant reads it.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "identify/diagnosis_engine.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "model/swing_record.h"
#include "study/diagnosis_size.h"
#include "study/diagnosis_study.h"

namespace swingsim {

/// The objects that stand for a swing study's files; nullopt / absent: read the file.
struct SwingStudyObjects {
  std::optional<Participant> participant;
  std::optional<KneeModel> baseModel;
  /// Records by entry name (StudyRecord::displayName): each replaces its entry's file.
  std::map<std::string, SwingRecord> records;
};

/// A study from YAML text, `source` naming it in messages (relative paths resolve against
/// its folder); unknown keys refused, as loadDiagnosisStudy. Throws InputError.
DiagnosisStudy parseDiagnosisStudy(const std::string& text, const std::string& source);

/// The plant of a swing-diagnosis study, with `objects` in place of the files they stand
/// for; each record is checked as a file's is (moment units, a hip moment for drive:
/// hip_moment). With `limit`, the size is announced and held to it. Throws InputError (a
/// given record whose name no entry has, too).
std::unique_ptr<DiagnosisPlant> makeSwingDiagnosisPlant(const DiagnosisStudy& study, SwingStudyObjects objects,
                                                        const DiagnosisRowLimit* limit = nullptr);

}  // namespace swingsim
