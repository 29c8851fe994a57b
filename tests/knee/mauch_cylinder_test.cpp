#include "knee/mauch_cylinder.h"
#include "core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace swingsim {
namespace {

constexpr double kDeg = kPi / 180.0;
// tanh(3) = 0.99505: three widths from a switch's centre it is within 0.5 % of its limit.
constexpr double kSwitchTol = 5e-3;
// Round-off in sums of forces of order 1e3 N.
constexpr double kForceTol = 1e-9;

// Chien 2014 Table 1, F90E90, 4-phase model.
MauchCylinderParams table1FourPhase() {
  MauchCylinderParams p;
  p.phases = 4;
  p.coefficients = {
      {-243.72, 29975.3, 17087.9}, {30.95, 2489.92, 928.7}, {-184.5, 10414.6, 501.49}, {-488.12, 563313, 14672.2}};
  return p;
}

MauchCylinderParams twoPhase() {
  MauchCylinderParams p;
  p.phases = 2;
  p.coefficients = {{-260.12, 28599, 17738.7}, {-189.91, 14116, 1415.05}};
  return p;
}

double law(const MauchPhaseCoefficients& c, double x, double xd) { return c.f + c.k * x + c.c * xd; }

TEST(MauchSwitches, LimitsFollowTheSignConvention) {
  const MauchSwitchParams sw;
  const double xd = 20 * sw.velocityWidth, x = 0.01;
  // Flexing (xd > 0): S1 = 1; not latched: S4 (stance flexion) selected.
  auto s = calcMauchSwitches(x, xd, 0.0, sw);
  EXPECT_NEAR(s.s1, 1.0, kSwitchTol);
  EXPECT_NEAR(s.s8, 1.0, kSwitchTol);
  EXPECT_NEAR(s.s4, 1.0, kSwitchTol);
  EXPECT_NEAR(s.s3, 0.0, kSwitchTol);
  // Flexing after hyperextension (S2 = 1): S6.
  s = calcMauchSwitches(x, xd, 1.0, sw);
  EXPECT_NEAR(s.s6, 1.0, kSwitchTol);
  // Extending: S5.
  s = calcMauchSwitches(x, -xd, 0.3, sw);
  EXPECT_NEAR(s.s5, 1.0, kSwitchTol);
  // Hyperextended (x < xhy): S7.
  s = calcMauchSwitches(-0.002, -xd, 0.3, sw);
  EXPECT_NEAR(s.s7, 1.0, kSwitchTol);
}

TEST(MauchSwitches, GatesSumToOneEverywhere) {
  const MauchSwitchParams sw;
  for (double x : {-0.003, 0.0, 4e-5, 5e-4, 0.02}) {
    for (double xd : {-0.2, -1e-4, 0.0, 3e-4, 0.1}) {
      for (double s2 : {0.0, 0.4, 1.0}) {
        const auto s = calcMauchSwitches(x, xd, s2, sw);
        for (int phases : {2, 4}) {
          double sum = 0;
          for (double g : calcPhaseGates(phases, s)) sum += g;
          EXPECT_NEAR(sum, 1.0, 1e-12);
        }
      }
    }
  }
}

// Decision (an ambiguity of Chien et al. 2014, docs/mauch.md): Table 1's phase 2 ("moderate", c = 928.7)
// acts in flexion after hyperextension, its phase 3 ("low", c = 501.49) in extension.
TEST(MauchCylinder, FourPhaseUsesDescribedPhaseForEachGaitEvent) {
  const MauchCylinder cyl(table1FourPhase());
  const auto& c = cyl.params().coefficients;
  const double xd = 0.1, x = 0.01;                                        // 100 mm/s is 200 velocity widths
  EXPECT_NEAR(cyl.calcForce(x, xd, 0.0), law(c[0], x, xd), kForceTol);    // stance flexion
  EXPECT_NEAR(cyl.calcForce(x, xd, 1.0), law(c[1], x, xd), kForceTol);    // swing flexion
  EXPECT_NEAR(cyl.calcForce(x, -xd, 0.0), law(c[2], x, -xd), kForceTol);  // extension
  // Hyperextension, 10 position widths below xhy: S8 ~ 2e-9 leaves ~1e-5 N of phase 3.
  EXPECT_NEAR(cyl.calcForce(-0.005, -xd, 1.0), law(c[3], -0.005, -xd), 1e-4);
  // Swing flexion meets less damping than stance flexion, extension less than swing flexion.
  EXPECT_GT(c[0].c, c[1].c);
  EXPECT_GT(c[1].c, c[2].c);
}

TEST(MauchCylinder, TwoPhaseHighForceIsStanceFlexionOnly) {
  const MauchCylinder cyl(twoPhase());
  const auto& c = cyl.params().coefficients;
  EXPECT_NEAR(cyl.calcForce(0.01, 0.1, 0.0), law(c[0], 0.01, 0.1), kForceTol);
  EXPECT_NEAR(cyl.calcForce(0.01, 0.1, 1.0), law(c[1], 0.01, 0.1), kForceTol);
  EXPECT_NEAR(cyl.calcForce(0.01, -0.1, 0.0), law(c[1], 0.01, -0.1), kForceTol);
}

TEST(MauchCylinder, RegressorRowReproducesForce) {
  for (const auto& params : {table1FourPhase(), twoPhase()}) {
    const MauchCylinder cyl(params);
    const auto beta = cyl.getCoefficientVector();
    for (double x : {-0.001, 1e-4, 0.015}) {
      for (double xd : {-0.05, 2e-4, 0.08}) {
        const auto row = cyl.calcRegressorRow(x, xd, 0.37);
        ASSERT_EQ(row.size(), beta.size());
        double f = 0;
        for (std::size_t i = 0; i < row.size(); ++i) f += row[i] * beta[i];
        EXPECT_NEAR(f, cyl.calcForce(x, xd, 0.37), kForceTol);
      }
    }
  }
}

// Decision: the published x0 = 0.05 read in the unit of xhy (0.005 cm) gives 0.5 mm and
// 0.5 mm/s. Read as 0.05 m it could not serve the position switch: S8 would still be 0.5 at
// full extension and never separate 3 deg of flexion from 3 deg of hyperextension.
TEST(MauchSwitches, DefaultWidthsSeparateBenchConditionsButLiteralMetresCannot) {
  const KneeGeometry g;
  const double flexed = g.calcPistonPosition(3 * kDeg), hyper = g.calcPistonPosition(-3 * kDeg);
  const MauchSwitchParams ours;
  EXPECT_NEAR(calcMauchSwitches(flexed, 0, 0, ours).s8, 1.0, 2 * kSwitchTol);
  EXPECT_NEAR(calcMauchSwitches(hyper, 0, 0, ours).s8, 0.0, 2 * kSwitchTol);
  MauchSwitchParams literal = ours;
  literal.positionWidth = 0.05;
  literal.velocityWidth = 0.05;
  EXPECT_NEAR(calcMauchSwitches(flexed, 0, 0, literal).s8 - calcMauchSwitches(hyper, 0, 0, literal).s8, 0.0, 0.03);
  // Stance flexion at 1 rad/s moves the piston about 24 mm/s: S1 must say "flexing".
  const double stanceXd = g.calcPistonVelocity(10 * kDeg, 1.0);
  EXPECT_GT(calcMauchSwitches(0.005, stanceXd, 0, ours).s1, 1.0 - kSwitchTol);
  EXPECT_LT(calcMauchSwitches(0.005, stanceXd, 0, literal).s1, 0.8);
}

TEST(MauchLatch, SetsInHyperextensionHoldsThroughFlexionResetsInExtension) {
  const MauchSwitchParams sw;
  const double v = 0.05;
  // Extending while hyperextended: S2 rises towards 1 at rate k.
  EXPECT_GT(calcLatchDerivative(-0.002, -v, 0.0, sw), 0.9 * sw.latchRate);
  // Flexing: frozen whatever the position.
  EXPECT_NEAR(calcLatchDerivative(-0.002, v, 0.0, sw), 0.0, 1e-6 * sw.latchRate);
  EXPECT_NEAR(calcLatchDerivative(0.01, v, 1.0, sw), 0.0, 1e-6 * sw.latchRate);
  // Extending above xhy: S2 decays towards 0.
  EXPECT_LT(calcLatchDerivative(0.01, -v, 1.0, sw), -0.9 * sw.latchRate);

  // Along a sampled path: extend into hyperextension, hold, flex to 20 mm, extend back.
  std::vector<double> t, x, xd;
  const double dt = 1 / 361.4;
  for (int i = 0; i < 200; ++i) {
    const double ti = i * dt;
    double xi, vi;
    if (ti < 0.1) {
      xi = 0.004 - 0.06 * ti;
      vi = -0.06;
    } else if (ti < 0.15) {
      xi = -0.002;
      vi = 0;
    } else if (ti < 0.4) {
      xi = -0.002 + 0.088 * (ti - 0.15);
      vi = 0.088;
    } else {
      xi = 0.020 - 0.06 * (ti - 0.4);
      vi = -0.06;
    }
    t.push_back(ti);
    x.push_back(xi);
    xd.push_back(vi);
  }
  const auto s2 = calcLatchHistory(t, x, xd, sw, 0.0);
  auto at = [&](double time) { return s2[static_cast<std::size_t>(time / dt)]; };
  EXPECT_NEAR(at(0.02), 0.0, kSwitchTol);  // extending 2.8 mm above xhy
  EXPECT_NEAR(at(0.14), 1.0, kSwitchTol);  // latched in hyperextension
  EXPECT_NEAR(at(0.39), 1.0, kSwitchTol);  // held through the whole flexion
  EXPECT_NEAR(at(0.5), 0.0, kSwitchTol);   // reset by extension above xhy
  for (double v2 : s2) {
    EXPECT_GE(v2, 0.0);
    EXPECT_LE(v2, 1.0);
  }
}

TEST(MauchLatch, HistoryAgreesWithFineExplicitIntegrationOfEquationSix) {
  // Independent check with a slow latch (k = 40/s) that explicit Euler resolves.
  MauchSwitchParams sw;
  sw.latchRate = 40;
  sw.velocityWidth = 0.01;
  sw.positionWidth = 0.002;
  std::vector<double> t, x, xd;
  for (int i = 0; i <= 400; ++i) {
    const double ti = i * 0.0025;
    t.push_back(ti);
    x.push_back(0.004 * std::cos(2 * kPi * ti));
    xd.push_back(-0.008 * kPi * std::sin(2 * kPi * ti));
  }
  const auto s2 = calcLatchHistory(t, x, xd, sw, 0.2, 50);
  double s = 0.2;
  const int fine = 2000;
  const double h = 0.0025 / fine;
  for (std::size_t i = 1; i < t.size(); ++i) {
    for (int j = 0; j < fine; ++j) {
      const double ti = t[i - 1] + (j + 0.5) * h;
      s += h * calcLatchDerivative(0.004 * std::cos(2 * kPi * ti), -0.008 * kPi * std::sin(2 * kPi * ti), s, sw);
    }
    // Linear interpolation of x, xd between samples costs O(dt^2) per interval.
    ASSERT_NEAR(s2[i], s, 2e-3) << "t = " << t[i];
  }
}

TEST(MauchCylinder, KneeMomentIsForceTimesMomentArmAndLatchIsItsState) {
  const MauchCylinder cyl(table1FourPhase());
  EXPECT_EQ(cyl.numStates(), 1);
  double z = -1;
  cyl.initialStates(&z);
  EXPECT_EQ(z, 1.0);  // swing starts latched (toe-off follows stance hyperextension)
  for (double deg : {-2.0, 5.0, 40.0}) {
    for (double rate : {-4.0, 4.0}) {
      const KneeKinematics k{deg * kDeg, rate};
      const auto& g = cyl.geometry();
      const double x = g.calcPistonPosition(k.flexion), arm = g.calcMomentArm(k.flexion);
      for (double s2 : {0.0, 1.0}) {
        EXPECT_NEAR(cyl.calcMoment(k, &s2), -cyl.calcForce(x, arm * rate, s2) * arm, 1e-9);
        double zdot = 0;
        cyl.calcStateDerivatives(k, &s2, &zdot);
        EXPECT_DOUBLE_EQ(zdot, calcLatchDerivative(x, arm * rate, s2, cyl.params().switches));
      }
    }
  }
}

TEST(MauchCylinder, PureDampingDissipatesThroughTheKnee) {
  MauchCylinderParams p = table1FourPhase();
  for (auto& c : p.coefficients) c.f = c.k = 0;
  const MauchCylinder cyl(p);
  for (double deg = -5; deg <= 70; deg += 5) {
    for (double rate : {-6.0, -0.5, 0.5, 6.0}) {
      const double s2 = 0.5;
      EXPECT_LE(cyl.calcMoment({deg * kDeg, rate}, &s2) * rate, 0.0);
    }
  }
}

TEST(MauchCylinder, RejectsBadParameters) {
  auto p = table1FourPhase();
  p.phases = 3;
  EXPECT_THROW(MauchCylinder{p}, std::invalid_argument);
  p = table1FourPhase();
  p.coefficients.pop_back();
  EXPECT_THROW(MauchCylinder{p}, std::invalid_argument);
  p = table1FourPhase();
  p.switches.positionWidth = 0;
  EXPECT_THROW(MauchCylinder{p}, std::invalid_argument);
  p = table1FourPhase();
  p.coefficients[1].c = std::nan("");
  EXPECT_THROW(MauchCylinder{p}, std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
