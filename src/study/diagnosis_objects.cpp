#include "study/diagnosis_objects.h"

#include "core/input_error.h"
#include "identify/swing_plant.h"
#include "io/moment_units_check.h"
#include "io/yaml_reader.h"

namespace swingsim {
namespace {

// A record checked as loadDiagnosisPlant checks a file's: units of its moments, and the hip
// moment a hip-moment drive needs. `where` names it (its file, or its entry for one in memory).
void checkSwingRecord(const DiagnosisStudy& study, const SwingRecord& r, double bodyMass, const std::string& where,
                      const std::string& momentSource) {
  checkMomentUnits(r, bodyMass, momentSource, where);
  if (study.drive == SwingDrive::kHipMoment && r.hipMoment.empty())
    throw InputError(where +
                     ": no hip moment column (hip_moment_Nm, or motion_columns: hip_moment), which the swing "
                     "diagnosis with drive: hip_moment needs (with only angles measured, set drive: thigh_kinematics)");
}

// The entry's record: the one given in memory under its name, else read from its file.
SwingRecord takeRecord(const DiagnosisStudy& study, const StudyRecord& entry, SwingStudyObjects& objects,
                       std::vector<std::string>& notes, double bodyMass) {
  const auto given = objects.records.find(entry.displayName());
  if (given != objects.records.end()) {
    SwingRecord r = std::move(given->second);
    objects.records.erase(given);
    r.stem = entry.displayName();
    const std::string where = study.path + ": record " + r.stem;
    checkSwingRecord(study, r, bodyMass, where, where);
    return r;
  }
  SwingRecord r = readStudyRecord(study, entry, notes);
  checkSwingRecord(study, r, bodyMass, entry.path,
                   entry.inverseDynamicsPath.empty() ? entry.path : entry.inverseDynamicsPath);
  return r;
}

}  // namespace

DiagnosisStudy parseDiagnosisStudy(const std::string& text, const std::string& source) {
  YamlMap yaml = YamlMap::loadString(text, source);
  DiagnosisStudy s = readDiagnosisStudy(yaml);
  yaml.finish();
  return s;
}

std::unique_ptr<DiagnosisPlant> makeSwingDiagnosisPlant(const DiagnosisStudy& study, SwingStudyObjects objects,
                                                        const DiagnosisRowLimit* limit) {
  if (study.plant != PlantKind::kSwing)
    throw InputError(study.path + ": kind: records in memory need a swing-diagnosis study");
  SwingBase base;
  base.participant = objects.participant ? std::move(*objects.participant) : loadParticipant(study.participantPath);
  base.knee = objects.baseModel ? std::move(*objects.baseModel) : loadKneeModel(study.baseModelPath);
  base.drive = study.drive;
  base.movingHip = study.movingHip;
  std::vector<SwingRecord> train, validate;
  for (const StudyRecord& entry : study.train)
    train.push_back(takeRecord(study, entry, objects, base.notes, base.participant.bodyMass));
  for (const StudyRecord& entry : study.validate)
    validate.push_back(takeRecord(study, entry, objects, base.notes, base.participant.bodyMass));
  if (!objects.records.empty())
    throw InputError(study.path + ": train: no entry named '" + objects.records.begin()->first +
                     "' for the record given");
  std::uint64_t rows = 0;
  for (const auto* records : {&train, &validate})
    for (const auto& r : *records) rows += r.time.size();
  if (limit) announceDiagnosisSize(study.name, study.path, study.plant, rows, train.size() + validate.size(), *limit);
  return std::make_unique<SwingPlant>(std::move(base), std::move(train), std::move(validate),
                                      study.integratorTolerance);
}

}  // namespace swingsim
