#include "numerics/profile_likelihood.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "numerics/residual_analysis.h"

namespace swingsim {
namespace {

// 30 bisections of a bracket a few standard errors wide: ~1e-9 of it.
constexpr double kBisectionTolerance = 1e-7;

// A straight line y = a + b x with noise. With the intercept profiled out (a = ybar - b xbar)
// the RSS at a held slope b is RSS_min + Sxx (b - bhat)^2, so the interval n ln(RSS(b) /
// RSS_best) <= c has the closed form bhat +- sqrt((RSS_best e^{c/n} - RSS_min) / Sxx).
struct Line {
  std::vector<double> x, y;
  double xbar = 0, ybar = 0, sxx = 0, sxy = 0;
  explicit Line(double slope) {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> noise(0.0, 0.5);
    for (int i = 0; i < 40; ++i) {
      x.push_back(0.1 * i);
      y.push_back(1.0 + slope * x.back() + noise(rng));
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      xbar += x[i] / x.size();
      ybar += y[i] / y.size();
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      sxx += (x[i] - xbar) * (x[i] - xbar);
      sxy += (x[i] - xbar) * (y[i] - ybar);
    }
  }
  double slope() const { return sxy / sxx; }
  double rssAt(double b) const {  // the intercept refitted
    double s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s += std::pow(y[i] - ybar - b * (x[i] - xbar), 2);
    return s;
  }
  double n() const { return static_cast<double>(x.size()); }
};

TEST(ProfileLikelihood, LinearSlopeMatchesTheClosedForm) {
  const Line line(0.8);
  const double bhat = line.slope(), rss = line.rssAt(bhat), c = calcChiSquaredQuantile(0.95, 1);
  const double half = std::sqrt(rss * (std::exp(c / line.n()) - 1) / line.sxx);
  const ProfileInterval p =
      calcProfileInterval([&](double b) { return line.rssAt(b); }, bhat, rss, line.n(), -100, 100, 0.01);
  EXPECT_NEAR(p.lower, bhat - half, kBisectionTolerance);
  EXPECT_NEAR(p.upper, bhat + half, kBisectionTolerance);
  EXPECT_FALSE(p.lowerAtBound);
  EXPECT_FALSE(p.upperAtBound);
}

// The slope held by a physical bound b >= 1 above its free estimate (about 0.8): the best
// fit sits on the bound; the interval is one-sided [1, upper], upper from the closed form
// with RSS_best = RSS(1). The Wald interval 1 +- 1.96 se would cross the bound.
TEST(ProfileLikelihood, ABoundCutsTheIntervalOneSided) {
  const Line line(0.8);
  const double bound = 1.0, bhat = line.slope();
  ASSERT_LT(bhat, bound);
  const double rssBest = line.rssAt(bound), c = calcChiSquaredQuantile(0.95, 1);
  const double upper = bhat + std::sqrt((rssBest * std::exp(c / line.n()) - line.rssAt(bhat)) / line.sxx);
  const ProfileInterval p =
      calcProfileInterval([&](double b) { return line.rssAt(b); }, bound, rssBest, line.n(), bound, 100, 0.01);
  EXPECT_TRUE(p.lowerAtBound);
  EXPECT_DOUBLE_EQ(p.lower, bound);
  EXPECT_FALSE(p.upperAtBound);
  EXPECT_NEAR(p.upper, upper, kBisectionTolerance);
  // Both bounds inside the region: the interval is the whole box.
  const ProfileInterval box =
      calcProfileInterval([&](double b) { return line.rssAt(b); }, bound, rssBest, line.n(), bound, 1.01, 0.01);
  EXPECT_TRUE(box.upperAtBound);
  EXPECT_DOUBLE_EQ(box.upper, 1.01);
}

TEST(ProfileLikelihood, AValueWhereTheModelCannotRunCountsAsOutside) {
  const Line line(0.8);
  const double bhat = line.slope(), rss = line.rssAt(bhat);
  const auto failsAbove = [&](double b) {
    if (b > bhat + 0.01) throw std::runtime_error("cannot run");
    return line.rssAt(b);
  };
  const ProfileInterval p = calcProfileInterval(failsAbove, bhat, rss, line.n(), -100, 100, 0.001);
  EXPECT_NEAR(p.upper, bhat + 0.01, kBisectionTolerance);
  EXPECT_THROW(calcProfileInterval(failsAbove, bhat, rss, line.n(), -100, 100, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
