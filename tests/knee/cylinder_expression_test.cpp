// A user's cylinder force (knee/cylinder_expression.h) and its place in the Mauch cylinder.
#include "knee/cylinder_expression.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "knee/mauch_cylinder.h"

namespace swingsim {
namespace {

KneeExpressionParams stop(double k) {
  return {"stop", "k * max(0, position_mm - 20)^2 + 0 * speed_m_s", {{"k", "N/mm^2", k}}};
}

TEST(CylinderExpression, TheVariablesAreThePistonsPositionAndSpeedInTwoUnits) {
  const CylinderExpressionForces f(
      {{"units", "a * (position_m * 1000 - position_mm) + speed_mm_s - 1000 * speed_m_s + a", {{"a", "", 7.0}}}});
  EXPECT_NEAR(f.calcForce(0.0123, -0.456), 7.0, 1e-9);
}

TEST(CylinderExpression, ForcesSumAndCopiesEvaluateApart) {
  const CylinderExpressionForces two({stop(3), stop(1)});
  EXPECT_DOUBLE_EQ(two.calcForce(0.025, 0.1), 4 * 25.0);
  EXPECT_DOUBLE_EQ(two.calcForce(0.015, 0.1), 0.0);
  CylinderExpressionForces copy = two;
  double a = 0, b = 0;
  std::thread t1([&] {
    for (int i = 0; i < 2000; ++i) a += two.calcForce(0.021, 0);
  });
  std::thread t2([&] {
    for (int i = 0; i < 2000; ++i) b += copy.calcForce(0.022, 0);
  });
  t1.join();
  t2.join();
  EXPECT_NEAR(a, 2000 * 4.0, 1e-6);
  EXPECT_NEAR(b, 2000 * 16.0, 1e-6);
}

TEST(CylinderExpression, ANonFiniteForceNamesTheExpressionAndTheState) {
  const CylinderExpressionForces f({{"bad", "a / position_mm", {{"a", "", 1.0}}}});
  try {
    f.calcForce(0.0, 0.0);
    ADD_FAILURE() << "a division by zero gave a force";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0 mm"), std::string::npos) << e.what();
  }
}

TEST(CylinderExpression, TheCylinderAddsItToItsForceAndItsKneeMoment) {
  MauchCylinderParams p;
  p.coefficients = {
      {-243.72, 29975.3, 17087.9}, {30.95, 2489.92, 928.7}, {-184.5, 10414.6, 501.49}, {-488.12, 563313, 14672.2}};
  const MauchCylinder plain(p);
  p.effects.expressions = {stop(3)};
  EXPECT_TRUE(p.effects.any());
  const MauchCylinder with(p);
  EXPECT_EQ(with.numCoefficients(), plain.numCoefficients());  // no regression column
  EXPECT_NEAR(with.calcForce(0.024, 0.05, 1.0) - plain.calcForce(0.024, 0.05, 1.0), 3 * 16.0, 1e-9);
  EXPECT_NEAR(with.calcExpressionForce(0.024, 0.05), 48.0, 1e-9);
  p.effects.expressions = {{"bad", "k * knee_deg", {{"k", "", 1.0}}}};
  EXPECT_THROW(MauchCylinder{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
