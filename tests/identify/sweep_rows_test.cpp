#include "identify/sweep_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "study/sweep_study.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;
constexpr double kRoundOff = 1e-12;  // relative: a 2x2 Cholesky solve

MeasuredSwingTime row(const std::string& who, double lowering, double time, double sd, int line) {
  MeasuredSwingTime r;
  r.participant = who;
  r.lowering = lowering;
  r.swingTime = time;
  r.sd = sd;
  r.line = line;
  return r;
}

// Lowered rows come out in order of lowering; each error carries the standard row's share
// (T_k / T_0) se_0; the whitening turns the rows' covariance into the identity.
TEST(SweepRows, WhiteningCarriesTheStandardRowsShare) {
  SweepParticipantRows p;
  p.standard = row("P1", 0.0, 0.40, 0.01, 2);
  p.standardRowError = 0.01;
  p.lowered = {row("P1", 0.10, 0.44, 0.02, 4), row("P1", 0.05, 0.42, 0.03, 3)};
  p.standardErrors = {0.02, 0.03};
  whitenSweepRows(p, true);
  ASSERT_EQ(p.lowered.size(), 2u);
  EXPECT_EQ(p.lowered[0].lowering, 0.05);
  const double shared0 = 0.42 / 0.40 * 0.01, shared1 = 0.44 / 0.40 * 0.01;
  EXPECT_NEAR(p.standardErrors[0], std::sqrt(0.03 * 0.03 + shared0 * shared0), kRoundOff);
  EXPECT_NEAR(p.standardErrors[1], std::sqrt(0.02 * 0.02 + shared1 * shared1), kRoundOff);
  Eigen::Matrix2d cov;
  cov << 0.03 * 0.03 + shared0 * shared0, shared0 * shared1, shared0 * shared1, 0.02 * 0.02 + shared1 * shared1;
  const Eigen::MatrixXd identity = p.whitening * cov * p.whitening.transpose();
  EXPECT_TRUE(identity.isApprox(Eigen::Matrix2d::Identity(), 1e-10)) << identity;
  // Correlated rows are worth fewer than two independent ones.
  EXPECT_GT(p.effectiveRows, 1.0);
  EXPECT_LT(p.effectiveRows, 2.0);
}

TEST(SweepRows, WithoutAStandardRowTheRowsAreIndependent) {
  SweepParticipantRows p;
  p.lowered = {row("P1", 0.10, 0.44, 0.02, 4), row("P1", 0.05, 0.42, 0.02, 3)};
  p.standardErrors = {0.02, 0.02};
  whitenSweepRows(p, false);
  EXPECT_EQ(p.standardErrors, (std::vector<double>{0.02, 0.02}));
  EXPECT_NEAR(p.effectiveRows, 2.0, kRoundOff);
}

TEST(SweepRows, AssignsRowsAndNamesTheFileAndLineOfABadOne) {
  const SweepStudy study = loadSweepStudy(kRoot + "/studies/burkett2004.yaml");
  ASSERT_GE(study.participants.size(), 2u);
  const std::string who = study.participants[1].name;
  std::vector<bool> hasStandard;
  std::vector<std::string> notes;
  const auto rows = assignSweepRows(study,
                                    {row(who, 0.0, 0.4, 0.01, 2), row(who, 0.05, 0.42, 0.01, 3),
                                     row(who, 5.0, 0.5, 0.01, 4)},  // 5 m: beyond any shank
                                    "m.csv", 0.0, hasStandard, notes);
  ASSERT_EQ(rows.size(), study.participants.size());
  EXPECT_TRUE(hasStandard[1]);
  EXPECT_FALSE(hasStandard[0]);
  EXPECT_EQ(rows[1].lowered.size(), 1u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].rfind("m.csv:4: ", 0), 0u) << notes[0];
  try {
    assignSweepRows(study, {row("nobody", 0.0, 0.4, 0.01, 7)}, "m.csv", 0.0, hasStandard, notes);
    FAIL() << "a row naming no participant was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("m.csv:7: participant: expected the name of a participant", 0), 0u)
        << e.what();
  }
  // No sd_s and no default standard error: refused.
  EXPECT_THROW(assignSweepRows(study, {row(who, 0.0, 0.4, std::numeric_limits<double>::quiet_NaN(), 9)}, "m.csv", 0.0,
                               hasStandard, notes),
               InputError);
}

}  // namespace
}  // namespace swingsim
