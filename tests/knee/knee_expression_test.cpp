#include "knee/knee_expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "core/units.h"
#include "knee/knee_added_effects.h"

namespace swingsim {
namespace {

// Every state variable carries its unit: the same state seen in deg and in rad.
TEST(KneeExpression, EveryVariableInItsUnit) {
  const KneeKinematics k{0.5, -2.0, 0.3, 1.5, 0.25};
  auto eval = [&](const std::string& e) {
    return KneeExpressionMoment({"x", e + " + 0 * a", {{"a", "", 0}}}).calcMoment(k, nullptr);
  };
  EXPECT_DOUBLE_EQ(eval("knee_deg"), 0.5 * kRadToDeg);
  EXPECT_DOUBLE_EQ(eval("knee_rad"), 0.5);
  EXPECT_DOUBLE_EQ(eval("knee_rate_deg_s"), -2.0 * kRadToDeg);
  EXPECT_DOUBLE_EQ(eval("knee_rate_rad_s"), -2.0);
  EXPECT_DOUBLE_EQ(eval("hip_deg"), 0.3 * kRadToDeg);
  EXPECT_DOUBLE_EQ(eval("hip_rad"), 0.3);
  EXPECT_DOUBLE_EQ(eval("hip_rate_deg_s"), 1.5 * kRadToDeg);
  EXPECT_DOUBLE_EQ(eval("hip_rate_rad_s"), 1.5);
  EXPECT_DOUBLE_EQ(eval("time_s"), 0.25);
}

// A cushion against extension near full extension: written as in docs/diagnosis.md, it is
// the moment computed by hand (positive, flexing, while the knee extends below 15 deg).
TEST(KneeExpression, ACushionIsTheMomentByHand) {
  const KneeExpressionMoment cushion({"cushion",
                                      "-c * knee_rate_rad_s * (knee_rate_rad_s < 0 ? 1 : 0) * (knee_deg < 15 ? 1 : 0)",
                                      {{"c", "N m s/rad", 2.0}}});
  EXPECT_DOUBLE_EQ(cushion.calcMoment({10 * kDegToRad, -3.0}, nullptr), 6.0);
  EXPECT_DOUBLE_EQ(cushion.calcMoment({10 * kDegToRad, 3.0}, nullptr), 0.0);   // flexing
  EXPECT_DOUBLE_EQ(cushion.calcMoment({20 * kDegToRad, -3.0}, nullptr), 0.0);  // above 15 deg
  EXPECT_FALSE(cushion.isPassive());
  EXPECT_EQ(cushion.name(), "cushion");
}

TEST(KneeExpression, ErrorsSayWhatAndWhere) {
  auto error = [](const KneeExpressionParams& p) {
    try {
      checkKneeExpression(p);
    } catch (const KneeExpressionError& e) {
      return describeKneeExpressionError(p.expression, e);
    }
    return std::string();
  };
  const std::string typo = error({"x", "-c * knee_rte_rad_s", {{"c", "", 1}}});
  EXPECT_NE(typo.find("knee_rte_rad_s"), std::string::npos) << typo;
  EXPECT_NE(typo.find("character 6"), std::string::npos) << typo;
  EXPECT_NE(typo.find("knee_rate_deg_s"), std::string::npos) << "the variables are listed: " << typo;
  EXPECT_FALSE(error({"x", "-c * (knee_rad", {{"c", "", 1}}}).empty());
  EXPECT_NE(error({"x", "-2 * knee_rad", {{"c", "", 1}}}).find("not used"), std::string::npos);
  EXPECT_NE(error({"x", "-knee_deg * knee_rad", {{"knee_deg", "", 1}}}).find("state variable"), std::string::npos);
  EXPECT_NE(error({"x", "-c * c2", {{"c", "", 1}, {"c", "", 2}}}).find("twice"), std::string::npos);
  EXPECT_NE(error({"x", "-c", {{"2c", "", 1}}}).find("letters"), std::string::npos);
  EXPECT_NE(error({"x", "  ", {{"c", "", 1}}}).find("empty"), std::string::npos);
  EXPECT_THROW(KneeExpressionMoment({"x", "c * knee_rad", {{"c", "", NAN}}}), KneeExpressionError);
}

TEST(KneeExpression, ANonFiniteMomentIsAnError) {
  const KneeExpressionMoment m({"x", "c / knee_rad", {{"c", "", 1}}});
  EXPECT_THROW(m.calcMoment({0.0, 0.0}, nullptr), std::domain_error);
}

// Clones are independent parsers: evaluated from several threads at once they agree with
// one thread's answer (the law's own lock serializes calls on one object).
TEST(KneeExpression, ClonesEvaluateInParallel) {
  const KneeExpressionMoment law({"x", "-c * knee_rate_rad_s - k * sin(knee_rad)", {{"c", "", 0.7}, {"k", "", 3}}});
  std::vector<double> sums(4, 0.0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < sums.size(); ++t)
    threads.emplace_back([&, t] {
      const auto mine = law.clone();
      for (int i = 0; i < 2000; ++i)
        sums[t] += mine->calcMoment({i * 1e-3, 1.0 - i * 1e-3}, nullptr) + law.calcMoment({0.1, 0.2}, nullptr);
    });
  for (auto& th : threads) th.join();
  double expected = 0;
  for (int i = 0; i < 2000; ++i)
    expected += -0.7 * (1.0 - i * 1e-3) - 3 * std::sin(i * 1e-3) + (-0.7 * 0.2 - 3 * std::sin(0.1));
  for (double s : sums) EXPECT_NEAR(s, expected, 1e-9 * std::abs(expected));
}

// The knee's added effects make one law per expression.
TEST(KneeExpression, AddedEffectsAddOneLawEach) {
  KneeAddedEffectsParams p;
  p.expressions = {{"a", "-c * knee_rad", {{"c", "", 1}}}, {"b", "-d * knee_rate_rad_s", {{"d", "", 2}}}};
  KneeLawSum sum;
  addKneeExpressionLaws(sum, p);
  ASSERT_EQ(sum.size(), 2u);
  EXPECT_DOUBLE_EQ(sum.calcMoment({0.5, 1.0}, nullptr), -0.5 - 2.0);
}

}  // namespace
}  // namespace swingsim
