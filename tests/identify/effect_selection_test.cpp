// The model-kind independent step of the diagnosis: which accepted candidates form an
// ambiguity group with the chosen one, and how the group is recorded.
#include "identify/effect_selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace swingsim {
namespace {

TEST(EffectSelection, AmbiguityGroupHoldsTheAcceptedCandidatesTheChosenOneAddsNothingTo) {
  const std::vector<std::string> names = {"a", "b", "c", "d", "e"};
  std::vector<EffectScore> s(names.size());
  s[0].accepted = true;   // chosen
  s[1].accepted = true;   // chosen adds nothing on top of b: ambiguous
  s[2].accepted = true;   // chosen adds something significant on top of c: not ambiguous
  s[3].accepted = false;  // not accepted: never asked
  s[4].accepted = true;   // joint refit failed: left out
  std::vector<EffectScore*> scores;
  for (auto& x : s) scores.push_back(&x);
  std::vector<std::size_t> asked;
  const auto group = findAmbiguityGroup(scores, names, 0, 0.01, [&](std::size_t j) -> std::optional<double> {
    asked.push_back(j);
    if (j == 1) return 0.4;
    if (j == 2) return 1e-6;
    return std::nullopt;
  });
  EXPECT_EQ(group, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(asked, (std::vector<std::size_t>{1, 2, 4}));
  // p exactly at alpha: the chosen effect is not significant on top of j.
  const auto edge = findAmbiguityGroup(scores, names, 0, 0.4, [](std::size_t j) -> std::optional<double> {
    return j == 1 ? std::optional<double>(0.4) : std::nullopt;
  });
  EXPECT_EQ(edge, (std::vector<std::string>{"a", "b"}));
}

// A candidate whose likelihood ratio turned into NaN (a residual with a NaN) has a NaN p and
// BIC: it is never significant nor accepted, and the finite one is chosen.
TEST(EffectSelection, ANanStatisticNeverPassesTheAcceptanceRule) {
  std::vector<EffectScore> s(2);
  for (auto& c : s) {
    c.bicImproves = c.validationImproves = c.physical = true;
    c.deltaBic = -50;
    c.pValue = 1e-12;
  }
  const LrTest nan = calcLrTest(10.0, std::nan(""), {{0.1, std::nan(""), 0.3}}, 1);
  s[0].pValue = nan.p;
  s[0].deltaBic = nan.deltaBic;
  EXPECT_TRUE(std::isnan(s[0].pValue));
  std::vector<EffectScore*> scores{&s[0], &s[1]};
  EXPECT_EQ(applyAcceptanceRule(scores, 0.01), 1);
  EXPECT_FALSE(s[0].significant);
  EXPECT_FALSE(s[0].accepted);
  EXPECT_TRUE(s[1].accepted);
}

// A candidate without information in these records is never accepted, however its
// statistics look; the informative one is chosen.
TEST(EffectSelection, ACandidateWithoutInformationIsNeverAccepted) {
  std::vector<EffectScore> s(2);
  for (auto& c : s) {
    c.bicImproves = c.validationImproves = c.physical = true;
    c.pValue = 1e-12;
  }
  s[0].deltaBic = -80;
  s[0].informative = false;
  s[1].deltaBic = -50;
  std::vector<EffectScore*> scores{&s[0], &s[1]};
  EXPECT_EQ(applyAcceptanceRule(scores, 0.01), 1);
  EXPECT_FALSE(s[0].accepted);
  EXPECT_TRUE(s[1].accepted);
}

TEST(EffectSelection, RecordAmbiguityKeepsGroupsOfTwoOrMoreWithAdvice) {
  std::vector<std::vector<std::string>> ambiguous;
  std::vector<std::string> advice;
  auto separatedBy = [](const std::string& e) { return "data for " + e; };
  recordAmbiguity({"a"}, separatedBy, ambiguous, advice);
  EXPECT_TRUE(ambiguous.empty());
  EXPECT_TRUE(advice.empty());
  recordAmbiguity({"a", "b"}, separatedBy, ambiguous, advice);
  ASSERT_EQ(ambiguous.size(), 1u);
  EXPECT_EQ(ambiguous[0], (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(advice.size(), 1u);
  EXPECT_EQ(advice[0], formatAmbiguityAdvice({"a", "b"}, {"data for a", "data for b"}));
  EXPECT_NE(advice[0].find("data for b"), std::string::npos);
}

}  // namespace
}  // namespace swingsim

namespace swingsim {
namespace {

// A residual of n samples of alternating sign and size `a`: lag-1 autocorrelation -1,
// clamped to 0, so n_eff = n.
std::vector<double> alternating(std::size_t n, double a) {
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = i % 2 ? -a : a;
  return r;
}

TEST(EffectSelection, ARecordThePooledFitMakesSignificantlyWorseFailsTheRecordRule) {
  // Record 0 falls from 2 to 1; record 1 rises by a factor 1.5 in RSS: 200 ln 1.5 = 81 >
  // chi^2_1(0.99) = 6.63.
  EffectScore c;
  applyRecordRule(c, {alternating(200, 2.0), alternating(200, 1.0)},
                  {alternating(200, 1.0), alternating(200, std::sqrt(1.5))}, 1, 0.01);
  EXPECT_FALSE(c.noRecordWorse);
  ASSERT_EQ(c.trainRecordWorsening.size(), 2u);
  EXPECT_NEAR(c.trainRecordWorsening[1], 200 * std::log(1.5), 1e-9);
  EXPECT_NEAR(c.trainRecordRmse[0], 1.0, 1e-12);
  EXPECT_NEAR(c.currentTrainRecordRmse[1], 1.0, 1e-12);
  // A rise of 1 % in RSS (200 ln 1.01 = 2.0) is within what noise does.
  applyRecordRule(c, {alternating(200, 2.0), alternating(200, 1.0)},
                  {alternating(200, 1.0), alternating(200, std::sqrt(1.01))}, 1, 0.01);
  EXPECT_TRUE(c.noRecordWorse);
  // One training record: the pooled test is its own, and the rule says nothing more.
  applyRecordRule(c, {alternating(200, 1.0)}, {alternating(200, 2.0)}, 1, 0.01);
  EXPECT_TRUE(c.noRecordWorse);
  // And the acceptance rule reads it.
  c.informative = c.significant = c.bicImproves = c.validationImproves = c.physical = true;
  c.pValue = 1e-9;
  c.noRecordWorse = false;
  EXPECT_EQ(applyAcceptanceRule({&c}, 0.01), -1);
  c.noRecordWorse = true;
  c.recordsAgree = false;
  EXPECT_EQ(applyAcceptanceRule({&c}, 0.01), -1);
  c.recordsAgree = true;
  EXPECT_EQ(applyAcceptanceRule({&c}, 0.01), 0);
}

}  // namespace
}  // namespace swingsim
