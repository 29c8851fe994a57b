// Burkett's measured swing times as a target: calibration of a sweep's participants to
// Table 3 (model or measured), Table 4 as validation beside Burkett's model, and the
// leave-one-participant-out prediction.
#include "sweep/measured_validation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "study/sweep_study.h"
#include "sweep/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

// P1, P2 and P3 at Table 4's lowerings only (a coarse grid keeps it fast).
SweepStudy studyOf(CalibrationTarget target) {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.participants.resize(3);
  s.loweringStep = 0.25;  // only 0 m on the grid; Table 4's lowerings come from include_published
  s.addedMasses = {0.0};
  s.includePublishedLowerings = true;
  s.calibrateTo = target;
  return s;
}

double simulateAt(const SweepStudy& study, Participant p, double scale, double lowering) {
  p.hipMoment.timeScale = scale;
  const SwingSetup setup = makeSwingSetup(p, study.kneeModels.at(p.kneeModelPath), lowering);
  return simulateSwing(setup, study.swing).swingTime;
}

TEST(MeasuredValidation, CalibratesToTheMeasuredColumnAndSaysWhereNoTimeScaleReachesIt) {
  SweepStudy study = studyOf(CalibrationTarget::kMeasured);
  const double storedP2 = study.participants[1].hipMoment.timeScale;
  const auto calibrations = calibrateSweepParticipants(study);
  ASSERT_EQ(calibrations.size(), 3u);
  for (std::size_t i : {std::size_t{0}, std::size_t{2}}) {
    const auto& c = calibrations[i];
    ASSERT_TRUE(c.ok) << c.participant << ": " << c.failure;
    EXPECT_EQ(c.targetTime, findPublished(c.participant)->table3Measured);
    EXPECT_EQ(study.participants[i].hipMoment.timeScale, c.timeScale);
    // Independently of the calibration's own bookkeeping: the swing at the standard location.
    EXPECT_NEAR(simulateAt(study, study.participants[i], c.timeScale, 0.0), c.targetTime, 1e-4) << c.participant;
  }
  // P2's measured 0.385 s is faster than any time scale in range makes his swing.
  EXPECT_FALSE(calibrations[1].ok);
  EXPECT_NE(calibrations[1].failure.find("outside"), std::string::npos) << calibrations[1].failure;
  EXPECT_EQ(study.participants[1].hipMoment.timeScale, storedP2);
}

TEST(MeasuredValidation, Table4ErrorsAndTheLeaveOneOutPredictionAreWhatTheSwingsGive) {
  SweepStudy study = studyOf(CalibrationTarget::kMeasured);
  SweepResults results;
  results.calibrations = calibrateSweepParticipants(study);
  const SweepResults swept = runSweep(study, 0);
  results.study = swept.study;
  results.participants = swept.participants;
  results.calibratedTo = study.calibrateTo;
  validateOnTable4(study, results);
  ASSERT_EQ(results.table4.size(), 3u);
  const Table4Validation& p1 = results.table4[0];
  const PublishedParticipant& pub = *findPublished("P1");
  ASSERT_EQ(p1.rows.size(), pub.table4.size());
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < p1.rows.size(); ++k) {
    const Table4Row& r = p1.rows[k];
    EXPECT_EQ(r.measured, pub.table4[k].measuredProsthetic);
    EXPECT_EQ(r.model, pub.table4[k].model);
    ASSERT_FALSE(std::isnan(r.ours)) << r.lowering;
    if (r.lowering > 0) {
      sum += (r.ours - r.measured) * (r.ours - r.measured);
      ++n;
    }
  }
  EXPECT_NEAR(p1.rmseOurs, std::sqrt(sum / n), 1e-12);
  EXPECT_TRUE(p1.calibrated);
  EXPECT_FALSE(results.table4[1].calibrated);  // P2
  // P1's leave-one-out scale is the mean of the other calibrated participants': P3 alone.
  const double p3Scale = results.calibrations[2].timeScale;
  EXPECT_NEAR(p1.rows[0].oursLeaveOneOut, simulateAt(study, study.participants[0], p3Scale, 0.0), 1e-12);
  // P2 was not calibrated: no leave-one-out prediction for him.
  EXPECT_TRUE(std::isnan(results.table4[1].rows[0].oursLeaveOneOut));
}

TEST(MeasuredValidation, StudyKeyIsCheckedAndStoredIsTheDefault) {
  const std::string head = "kind: knee-axis-sweep\nname: t\nparticipants: [../participants/p1.yaml]\n";
  EXPECT_EQ(parseSweepStudy(head, "studies/t.yaml").calibrateTo, CalibrationTarget::kStored);
  EXPECT_EQ(parseSweepStudy(head + "calibrate_to: measured\n", "studies/t.yaml").calibrateTo,
            CalibrationTarget::kMeasured);
  try {
    parseSweepStudy(head + "calibrate_to: measurd\n", "studies/t.yaml");
    FAIL() << "accepted a misspelled calibrate_to";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("calibrate_to"), std::string::npos) << what;
    EXPECT_NE(what.find("measurd"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace swingsim
