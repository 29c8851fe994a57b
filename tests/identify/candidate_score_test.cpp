#include "identify/candidate_score.h"

#include <gtest/gtest.h>

#include <cmath>

#include "two_candidate_plant.h"

namespace swingsim {
namespace {

// The informative candidate: its value, a 95 % interval from its standard error (0.1) inflated
// by the residual's autocorrelation (none to speak of here: white noise), and where the error fell.
TEST(CandidateScore, ScoresAnInformativeCandidateWithItsInterval) {
  const TwoCandidatePlant plant;
  const PlantFit current = plant.fit(*plant.baseModel());
  PlantFit best;
  const CandidateScore c = scoreCandidate(plant, current, EffectId::kInertia, EffectSelectionSettings{}, &best);
  EXPECT_TRUE(c.notApplicable.empty());
  EXPECT_EQ(c.effect, "inertia");
  EXPECT_TRUE(c.informative);
  ASSERT_EQ(c.parameters.size(), 1u);
  EXPECT_EQ(c.parameters[0].value, 1.0);
  const double halfWidth = c.parameters[0].upper - c.parameters[0].value;
  EXPECT_NEAR(c.parameters[0].value - c.parameters[0].lower, halfWidth, 1e-12);
  EXPECT_GT(halfWidth, 1.9 * 0.1);  // at least 1.96 SE, inflated only by autocorrelation
  EXPECT_LT(halfWidth, 3.0 * 0.1);
  EXPECT_GT(c.likelihoodRatio, 0.0);
  EXPECT_EQ(c.where, "all (100 % of the error fall)");
  EXPECT_EQ(best.rss, plant.fit(*plant.addEffect(*current.model, EffectId::kInertia, 0)).rss);
}

// A parameter whose interval is a million physical ranges carries no information: no
// interval, and the note says so.
TEST(CandidateScore, ACandidateWithoutInformationGetsNoInterval) {
  const TwoCandidatePlant plant;
  const PlantFit current = plant.fit(*plant.baseModel());
  const CandidateScore c =
      scoreCandidate(plant, current, EffectId::kOrificeQuadratic, EffectSelectionSettings{}, nullptr);
  EXPECT_FALSE(c.informative);
  ASSERT_EQ(c.parameters.size(), 1u);
  EXPECT_TRUE(std::isnan(c.parameters[0].lower));
  EXPECT_EQ(c.parameters[0].intervalNote, kNoInformation);
}

// A candidate the plant refuses is not fitted: it comes back with the plant's reason.
TEST(CandidateScore, ARefusedCandidateIsNotFitted) {
  const TwoCandidatePlant plant;
  const PlantFit withInertia = plant.fit(*plant.addEffect(*plant.baseModel(), EffectId::kInertia, 0));
  const CandidateScore c = scoreCandidate(plant, withInertia, EffectId::kInertia, EffectSelectionSettings{}, nullptr);
  EXPECT_EQ(c.notApplicable, "already in the model");
  EXPECT_TRUE(c.parameters.empty());
  EXPECT_EQ(c.model, nullptr);
}

}  // namespace
}  // namespace swingsim
