// The hip path: the hip joint centre from the measured pelvis and the hip's offset in the
// pelvis frame, smoothed by the GCV quintic spline, checked against a known smooth motion
// whose position, velocity and acceleration are written here in closed form.
#include "leg/hip_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/input_error.h"

namespace swingsim {
namespace {

// A walking-like pelvis: forward at 1.3 m/s, bobbing 2 cm at 2 steps/s, tilting 0.1 rad.
constexpr double kSpeed = 1.3, kBob = 0.02, kOmega = 4 * 3.141592653589793, kTilt = 0.1;
constexpr double kOffsetX = 0.05, kOffsetY = -0.08;  // m, hip centre in the pelvis frame

ThighKinematics makePelvis(int samples, double dt) {
  ThighKinematics k;
  k.path = "pelvis.mot";
  for (int i = 0; i < samples; ++i) {
    const double t = dt * i;
    k.time.push_back(t);
    k.hipFlexion.push_back(0.3 * std::sin(5 * t));
    k.pelvisX.push_back(kSpeed * t);
    k.pelvisY.push_back(0.95 + kBob * std::sin(kOmega * t));
    k.pelvisTilt.push_back(kTilt * std::sin(kOmega * t));
  }
  return k;
}

// The hip centre in closed form: p = (X, Y) + R(tilt) o, differentiated by hand.
struct Exact {
  double x, y, vx, vy, ax, ay;
};
Exact exactHip(double t) {
  const double th = kTilt * std::sin(kOmega * t), thd = kTilt * kOmega * std::cos(kOmega * t),
               thdd = -kTilt * kOmega * kOmega * std::sin(kOmega * t);
  const double c = std::cos(th), s = std::sin(th);
  // R o = (c ox - s oy, s ox + c oy); d/dt = thd (-s ox - c oy, c ox - s oy).
  const double rx = c * kOffsetX - s * kOffsetY, ry = s * kOffsetX + c * kOffsetY;
  Exact e;
  e.x = kSpeed * t + rx;
  e.y = 0.95 + kBob * std::sin(kOmega * t) + ry;
  e.vx = kSpeed - thd * ry;
  e.vy = kBob * kOmega * std::cos(kOmega * t) + thd * rx;
  e.ax = -thdd * ry - thd * thd * rx;
  e.ay = -kBob * kOmega * kOmega * std::sin(kOmega * t) + thdd * rx - thd * thd * ry;
  return e;
}

TEST(HipPath, FollowsTheHipCentreAndItsDerivatives) {
  const ThighKinematics k = makePelvis(61, 0.01);  // 100 Hz over 0.6 s, noise-free
  ASSERT_TRUE(HipPath::hasPelvis(k));
  const HipPath path(k, std::array<double, 2>{kOffsetX, kOffsetY});
  // Bounds: the GCV spline through noise-free samples leaves a residual far below a marker's
  // 1 mm; its derivatives lose accuracy near the ends (end conditions), so they are judged
  // inside, 0.05 s from either end, to 1 % of the motion's scale (v ~ 1.3 m/s, a ~ 3 m/s^2).
  constexpr double kPositionTol = 1e-4;      // m
  constexpr double kVelocityTol = 0.013;     // m/s
  constexpr double kAccelerationTol = 0.05;  // m/s^2
  for (double t = 0.05; t <= 0.55; t += 0.01) {
    const Exact e = exactHip(t);
    const auto p = path.calcPosition(t), v = path.calcVelocity(t), a = path.calcAcceleration(t);
    EXPECT_NEAR(p[0], e.x, kPositionTol) << t;
    EXPECT_NEAR(p[1], e.y, kPositionTol) << t;
    EXPECT_NEAR(v[0], e.vx, kVelocityTol) << t;
    EXPECT_NEAR(v[1], e.vy, kVelocityTol) << t;
    EXPECT_NEAR(a[0], e.ax, kAccelerationTol) << t;
    EXPECT_NEAR(a[1], e.ay, kAccelerationTol) << t;
  }
  // The samples are the rotated offset, not the pelvis origin.
  EXPECT_NEAR(path.getSample(0)[1], 0.95 + kOffsetY, 1e-15);
  EXPECT_LT(path.getFitRms(), kPositionTol);
}

TEST(HipPath, NoPelvisMeansAFixedHip) {
  ThighKinematics k = makePelvis(10, 0.01);
  k.pelvisX.clear();
  k.pelvisY.clear();
  k.pelvisTilt.clear();
  EXPECT_FALSE(HipPath::hasPelvis(k));
}

TEST(HipPath, PelvisWithoutHipOffsetNamesTheKeyAndTheImporter) {
  const ThighKinematics k = makePelvis(20, 0.01);
  try {
    HipPath path(k, std::nullopt, "participants/runner.yaml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("participants/runner.yaml: hip_offset_in_pelvis_m"), std::string::npos) << m;
    EXPECT_NE(m.find("swingsim import-osim"), std::string::npos) << m;
  }
}

TEST(HipPath, PelvisColumnOfTheWrongLengthIsRejected) {
  ThighKinematics k = makePelvis(20, 0.01);
  k.pelvisTilt.pop_back();
  try {
    HipPath path(k, std::array<double, 2>{0, 0});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pelvis.mot: pelvis_tilt: expected one value per time (20) (got 19)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace swingsim
