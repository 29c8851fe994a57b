#include "study/diagnosis_objects.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "io/swing_record_csv.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
const std::string kStudy = kRoot + "/studies/diagnose-demo-swing.yaml";

// Every part given as an object (the participant, the knee, the three records read from the
// study's own files): the plant runs the base model along the same records to the same
// numbers as the plant loadDiagnosisPlant reads from the files.
TEST(SwingDiagnosisObjects, ObjectsGiveThePlantTheFilesGive) {
  const DiagnosisStudy study = loadDiagnosisStudy(kStudy);
  SwingStudyObjects objects;
  objects.participant = loadParticipant(study.participantPath);
  objects.baseModel = loadKneeModel(study.baseModelPath);
  for (const auto* entries : {&study.train, &study.validate})
    for (const StudyRecord& entry : *entries) objects.records[entry.displayName()] = readSwingRecord(entry.path);
  const auto fromObjects = makeSwingDiagnosisPlant(study, std::move(objects));
  const auto fromFiles = loadDiagnosisPlant(study, 8);
  const Comparison a = fromObjects->compare(*fromObjects->baseModel());
  const Comparison b = fromFiles->compare(*fromFiles->baseModel());
  ASSERT_EQ(a.records.size(), 3u);
  ASSERT_EQ(a.records.size(), b.records.size());
  for (std::size_t i = 0; i < a.records.size(); ++i) {
    EXPECT_EQ(a.records[i].stem, b.records[i].stem);
    EXPECT_EQ(a.records[i].training, b.records[i].training);
    EXPECT_EQ(a.records[i].measured, b.records[i].measured);
    EXPECT_EQ(a.records[i].predicted, b.records[i].predicted);
  }
}

// A record in memory replaces its entry's file: an offset measurement shows in the plant.
TEST(SwingDiagnosisObjects, ARecordInMemoryReplacesItsFile) {
  const DiagnosisStudy study = loadDiagnosisStudy(kStudy);
  SwingRecord shifted = readSwingRecord(study.train.front().path);
  constexpr double kOffset = 0.05;  // rad, about 3 deg
  for (double& k : shifted.kneeFlexion) k += kOffset;
  SwingStudyObjects objects;
  objects.records[study.train.front().displayName()] = shifted;
  const auto plant = makeSwingDiagnosisPlant(study, std::move(objects));
  const auto files = loadDiagnosisPlant(study, 8);
  const RecordComparison a = plant->compare(*plant->baseModel()).records.front();
  const RecordComparison b = files->compare(*files->baseModel()).records.front();
  ASSERT_EQ(a.measured.size(), b.measured.size());
  EXPECT_NEAR(a.measured.front() - b.measured.front(), kOffset * 180 / 3.14159265358979323846, 1e-9);
}

TEST(SwingDiagnosisObjects, ARecordNoEntryNamesIsRefused) {
  const DiagnosisStudy study = loadDiagnosisStudy(kStudy);
  SwingStudyObjects objects;
  objects.records["nobody"] = readSwingRecord(study.train.front().path);
  EXPECT_THAT([&] { makeSwingDiagnosisPlant(study, std::move(objects)); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("no entry named 'nobody'")));
}

TEST(SwingDiagnosisObjects, ARecordWithoutTheHipMomentTheDriveNeedsIsNamed) {
  const DiagnosisStudy study = loadDiagnosisStudy(kStudy);
  SwingRecord record = readSwingRecord(study.train.front().path);
  record.hipMoment.clear();
  SwingStudyObjects objects;
  objects.records[study.train.front().displayName()] = record;
  EXPECT_THAT([&] { makeSwingDiagnosisPlant(study, std::move(objects)); },
              ::testing::ThrowsMessage<InputError>(::testing::AllOf(::testing::HasSubstr("record normal"),
                                                                    ::testing::HasSubstr("no hip moment column"))));
}

TEST(SwingDiagnosisObjects, ParseNamesTheSourceAndRefusesUnknownKeys) {
  EXPECT_THAT([] { parseDiagnosisStudy("kind: swing-diagnosis\nbogus: 1\n", "python-study.yaml (edited in Python)"); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("python-study.yaml (edited in Python)")));
  EXPECT_THAT([&] { makeSwingDiagnosisPlant(loadDiagnosisStudy(kRoot + "/studies/diagnose-demo-cylinder.yaml"), {}); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("swing-diagnosis")));
}

}  // namespace
}  // namespace swingsim
