// The measured thigh angle as a smoothing spline (leg/thigh_motion.h): rate and
// acceleration are the exact derivatives of the angle, the smoothing removes noise and says
// how much (getFitRms), and unusable samples are refused with where and what. (That the
// spline follows a known motion is tests/swing/thigh_drive_test.cpp.)
#include "leg/thigh_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/input_error.h"

namespace swingsim {
namespace {

// n samples at 100 Hz of 0.5 sin(4 t), plus +-noise alternating sample to sample.
ThighKinematics sineSamples(int n, double noise = 0) {
  ThighKinematics k;
  k.path = "thigh.csv";
  for (int i = 0; i < n; ++i) {
    const double t = 0.01 * i;
    k.time.push_back(t);
    k.hipFlexion.push_back(0.5 * std::sin(4 * t) + (i % 2 ? noise : -noise));
  }
  return k;
}

std::string errorOf(const ThighKinematics& k) {
  try {
    ThighMotion m(k);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ThighMotion, RateAndAccelerationAreTheAnglesDerivatives) {
  const ThighMotion m(sineSamples(50));
  constexpr double h = 1e-5;               // s, central-difference step
  constexpr double kDifferenceTol = 1e-6;  // the central difference's h^2 error and round-off, relative
  for (double t = 0.02; t < 0.47; t += 0.031) {
    const double rate = (m.calcAngle(t + h) - m.calcAngle(t - h)) / (2 * h);
    const double acc = (m.calcRate(t + h) - m.calcRate(t - h)) / (2 * h);
    EXPECT_NEAR(m.calcRate(t), rate, kDifferenceTol * 2) << t;
    EXPECT_NEAR(m.calcAcceleration(t), acc, kDifferenceTol * 8) << t;
  }
  EXPECT_DOUBLE_EQ(m.getEndTime(), 0.49);
  EXPECT_EQ(m.getKinematics().path, "thigh.csv");
  EXPECT_EQ(m.getKinematics().time.size(), 50u);
}

TEST(ThighMotion, SmoothingRemovesNoiseAndReportsIt) {
  constexpr double kNoise = 2e-3;  // rad, about 0.1 deg: marker noise
  const ThighMotion clean(sineSamples(60));
  const ThighMotion noisy(sineSamples(60, kNoise));
  EXPECT_LT(clean.getFitRms(), 1e-5) << "a smooth motion is followed";
  // Cross-validation takes most of an alternating noise out: the fit misses the samples by
  // nearly the noise, and stays nearer the motion than the samples are.
  EXPECT_GT(noisy.getFitRms(), 0.5 * kNoise);
  EXPECT_LT(noisy.getFitRms(), 1.5 * kNoise);
  for (double t = 0.1; t < 0.5; t += 0.05)
    EXPECT_LT(std::fabs(noisy.calcAngle(t) - 0.5 * std::sin(4 * t)), kNoise) << t;
  const ThighMotion copy = noisy;
  EXPECT_EQ(copy.calcAngle(0.123), noisy.calcAngle(0.123)) << "a copy is the same function";
}

TEST(ThighMotion, UnusableSamplesAreRefusedWithWhereAndWhat) {
  ThighKinematics k = sineSamples(10);
  k.hipFlexion.pop_back();
  EXPECT_EQ(errorOf(k), "thigh.csv: expected one hip flexion per time (10), found 9");
  EXPECT_EQ(errorOf(sineSamples(5)),
            "thigh.csv: expected at least 6 thigh angle samples to prescribe the thigh, found 5");
  k = sineSamples(10);
  k.path.clear();
  for (double& t : k.time) t += 0.02;
  EXPECT_EQ(errorOf(k), "thigh kinematics: the first sample must be toe-off at time 0 s (found 0.02 s)");
  k = sineSamples(10);
  k.hipFlexion[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(errorOf(k), "thigh.csv: sample 4 is not finite");
  k = sineSamples(10);
  k.time[6] = k.time[5];
  EXPECT_EQ(errorOf(k), "thigh.csv: times must strictly increase (found 0.05 s after 0.05 s)");
  EXPECT_EQ(errorOf(sineSamples(6)), "") << "kMinSamples is enough";
}

}  // namespace
}  // namespace swingsim
