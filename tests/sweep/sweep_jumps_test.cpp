// The sweep on a leg whose swing time jumps (sweep/swing_time_jumps.h through runSweep): Burkett's
// P3 without knee friction, whose knee rebounds past the zone of stability at small lowerings
// and not at large ones (docs/burkett2004.md, the terminal-impact check). Each answer is checked
// against a swing simulated on its own at the lowering it names: no symmetry lowering is claimed
// where the leg swings another time.
#include <gtest/gtest.h>

#include <cmath>

#include "io/json_file.h"
#include "report/sweep_report.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

constexpr double kClaimTol = 0.005;  // s: a claimed swing time must be what the leg swings there

SweepStudy reboundingStudy(std::optional<double> soundTime) {
  SweepStudy s = loadSweepStudy("studies/burkett2004.yaml");
  s.participants = {s.participants[2]};
  Participant& p = s.participants[0];
  EXPECT_EQ(p.name, "P3");
  p.kneeFriction = 0;  // without friction the knee rebounds off its stop
  p.soundLimbSwingTime = soundTime;
  s.addedMasses = {0.0};
  s.addedMassDistances.clear();
  s.includePublishedLowerings = false;
  return s;
}

double swingTimeAt(const SweepStudy& s, double lowering) {
  const Participant& p = s.participants[0];
  return simulateSwing(makeSwingSetup(p, findStudyKneeModel(s, p), lowering), s.swing).swingTime;
}

const ParticipantSweep& plainSweep() {
  static const SweepResults r = runSweep(reboundingStudy(std::nullopt), 0);
  return r.participants[0];
}

// The last grid pair before the jump and the first after it, for sound-limb times inside a piece.
std::pair<const SweepPoint*, const SweepPoint*> gridPairAround(double lowering, int side) {
  const auto& pts = plainSweep().points;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k)
    if (pts[k].lowering < lowering && pts[k + 1].lowering > lowering)
      return side < 0 ? std::make_pair(&pts[k - 1], &pts[k]) : std::make_pair(&pts[k + 1], &pts[k + 2]);
  return {nullptr, nullptr};
}

TEST(SweepJumps, TheReboundIsFoundNarrowedAndNamed) {
  const ParticipantSweep& ps = plainSweep();
  ASSERT_EQ(ps.jumps.size(), 1u);
  const SwingTimeJump& j = ps.jumps[0];
  EXPECT_LE(j.above.lowering - j.below.lowering, kJumpBracket * (1 + 1e-9));
  EXPECT_EQ(j.below.bounces, 1);
  EXPECT_EQ(j.above.bounces, 0);
  EXPECT_NE(j.describeCause().find("deg past the zone"), std::string::npos) << j.describeCause();
  // The jump is real: swings simulated on their own at both sides keep the two times, while
  // the knee's first entry into the zone (the continuous companion) barely moves.
  const SweepStudy s = reboundingStudy(std::nullopt);
  EXPECT_NEAR(swingTimeAt(s, j.below.lowering), j.below.swingTime, 1e-9);
  EXPECT_NEAR(swingTimeAt(s, j.above.lowering), j.above.swingTime, 1e-9);
  EXPECT_GT(j.below.swingTime - j.above.swingTime, 0.05);
  EXPECT_LT(std::fabs(*j.below.firstZoneEntry - *j.above.firstZoneEntry), 0.001);
}

TEST(SweepJumps, ASoundLimbTimeInsideTheJumpIsNotReached) {
  const SwingTimeJump& j = plainSweep().jumps.at(0);
  const double sound = 0.5 * (j.below.swingTime + j.above.swingTime);
  const SweepResults r = runSweep(reboundingStudy(sound), 0);
  const SymmetryLowering& sym = r.participants[0].symmetry;
  EXPECT_FALSE(sym.reached);
  EXPECT_TRUE(sym.acrossJump);
  // The closest point is a real swing at that lowering.
  EXPECT_NEAR(swingTimeAt(reboundingStudy(sound), sym.lowering), sym.prostheticTime, kClaimTol);
  const std::string text = formatSweepTables(reboundingStudy(sound), r);
  EXPECT_NE(text.find("not reached: the swing jumps from"), std::string::npos) << text;
  const Json json = Json::parse(formatSweepJson(r));
  const Json& participant = json["participants"][0];
  ASSERT_EQ(participant["swing_time_jumps"].size(), 1u);
  EXPECT_NE(participant["swing_time_jumps"][0]["cause"].get<std::string>().find("past the zone"), std::string::npos);
  EXPECT_TRUE(participant["symmetry"]["across_jump"].get<bool>());
}

TEST(SweepJumps, ASoundLimbTimeInsideAPieceIsReachedWhereTheLegSwingsIt) {
  const double jumpAt = plainSweep().jumps.at(0).calcLowering();
  for (int side : {-1, 1}) {
    const auto [a, b] = gridPairAround(jumpAt, side);
    ASSERT_TRUE(a && b && a->ok && b->ok);
    const double sound = 0.5 * (a->result.swingTime + b->result.swingTime);
    const SweepResults r = runSweep(reboundingStudy(sound), 0);
    const SymmetryLowering& sym = r.participants[0].symmetry;
    ASSERT_TRUE(sym.reached) << "side " << side;
    EXPECT_GT(sym.lowering, a->lowering);
    EXPECT_LT(sym.lowering, b->lowering);
    EXPECT_NEAR(swingTimeAt(reboundingStudy(sound), sym.lowering), sound, kClaimTol) << "at " << sym.lowering << " m";
  }
}

}  // namespace
}  // namespace swingsim
