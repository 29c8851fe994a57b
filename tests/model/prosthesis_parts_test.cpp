// The shank and foot that catalogue parts make: checked against an independent sum over
// point masses (each part with an inertia as a dumbbell of the same mass and inertia, the
// pylon as many small slices), not against the parallel-axis formula the code uses.
#include "model/prosthesis_parts.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace swingsim {
namespace {

using ::testing::HasSubstr;

struct PointMass {
  double mass, at;  // kg; m below the knee axis
};

// Mass, COM and inertia about the COM of a cloud of point masses on a line.
struct Sums {
  double mass = 0, com = 0, inertia = 0;
};
Sums sumPoints(const std::vector<PointMass>& points) {
  Sums s;
  for (const PointMass& p : points) {
    s.mass += p.mass;
    s.com += p.mass * p.at;
  }
  s.com /= s.mass;
  for (const PointMass& p : points) s.inertia += p.mass * (p.at - s.com) * (p.at - s.com);
  return s;
}

// Two halves at +-sqrt(I/m) from the COM: the same mass, COM and inertia on the line.
void addDumbbell(std::vector<PointMass>& points, double mass, double com, double inertia) {
  const double r = std::sqrt(inertia / mass);
  points.push_back({mass / 2, com - r});
  points.push_back({mass / 2, com + r});
}

ProsthesisPart part(PartCategory c, double mass, double length) {
  ProsthesisPart p;
  p.id = "p";
  p.category = c;
  p.mass = mass;
  p.length = length;
  return p;
}

TEST(ProsthesisParts, ShankMatchesAPointMassSumOfItsParts) {
  ProsthesisPart knee = part(PartCategory::kKnee, 2.2455, 0.161);
  knee.com = 0.059;
  knee.inertia = 0.0092;
  const ProsthesisPart pylon = part(PartCategory::kPylon, 0.20, 0.40);  // 0.5 kg/m
  ProsthesisPart ankle = part(PartCategory::kAnkle, 1.739, 0.1056);
  ankle.com = 0.045;
  ankle.inertia = 0.0052;
  const double length = 0.47;
  const SegmentParams s = assembleShank({&knee, &pylon, &ankle}, length);

  std::vector<PointMass> points;
  addDumbbell(points, knee.mass, 0.059, 0.0092);
  addDumbbell(points, ankle.mass, length - 0.045, 0.0052);
  const double top = 0.161, bottom = length - 0.1056;
  const int slices = 20000;
  const double sliceMass = 0.5 * (bottom - top) / slices;
  for (int i = 0; i < slices; ++i) points.push_back({sliceMass, top + (i + 0.5) * (bottom - top) / slices});
  const Sums expected = sumPoints(points);

  // The reference sums 20000 slices: its own rounding is about 1e-12.
  EXPECT_NEAR(s.mass, expected.mass, 1e-10);
  EXPECT_NEAR(length - s.comFromDistal, expected.com, 1e-10);
  EXPECT_NEAR(s.inertia, expected.inertia, 1e-8);  // the slices' own inertia, m L^2 / (12 N^2), is left out
  EXPECT_DOUBLE_EQ(s.length, length);
}

TEST(ProsthesisParts, PylonMassFollowsTheSpanItCovers) {
  const ProsthesisPart knee = part(PartCategory::kKnee, 1.0, 0.10);
  const ProsthesisPart pylon = part(PartCategory::kPylon, 0.15, 0.30);
  const SegmentParams shorter = assembleShank({&knee, &pylon, nullptr}, 0.40);
  const SegmentParams longer = assembleShank({&knee, &pylon, nullptr}, 0.50);
  EXPECT_NEAR(shorter.mass, 1.0 + 0.15, 1e-12);          // a 0.30 m span: the published tube
  EXPECT_NEAR(longer.mass - shorter.mass, 0.05, 1e-12);  // 0.10 m more at 0.5 kg/m
  // Without a COM or an inertia the knee is a uniform rod over its height.
  const SegmentParams kneeOnly = assembleShank({&knee, nullptr, nullptr}, 0.40);
  EXPECT_NEAR(0.40 - kneeOnly.comFromDistal, 0.05, 1e-12);
  EXPECT_NEAR(kneeOnly.inertia, 1.0 * 0.01 / 12, 1e-15);
}

TEST(ProsthesisParts, PartsThatDoNotFitAreRefusedWithTheirSizes) {
  const ProsthesisPart knee = part(PartCategory::kKnee, 1.0, 0.30);
  const ProsthesisPart ankle = part(PartCategory::kAnkle, 1.0, 0.15);
  try {
    assembleShank({&knee, nullptr, &ankle}, 0.40);
    FAIL() << "the units fill more than the shank";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("0.3 m + 0.15 m"));
    EXPECT_THAT(e.what(), HasSubstr("0.4 m"));
  }
  ProsthesisPart pylon = part(PartCategory::kPylon, 0.1, 0.2);
  pylon.id = "short-tube";
  pylon.maxLength = 0.2;
  EXPECT_THROW(assembleShank({nullptr, &pylon, nullptr}, 0.25), std::invalid_argument);
  EXPECT_NO_THROW(assembleShank({nullptr, &pylon, nullptr}, 0.20));
  EXPECT_THROW(assembleShank({}, 0.4), std::invalid_argument);
}

TEST(ProsthesisParts, FootComFromToeOrAnkleDescribesOnePoint) {
  ProsthesisPart foot = part(PartCategory::kFoot, 0.824, 0.26);
  const SegmentParams fromAnkle = assembleFoot(foot, 0.18, FootComFrom::kAnkle);
  const SegmentParams fromToe = assembleFoot(foot, 0.18, FootComFrom::kToe);
  EXPECT_NEAR(fromAnkle.comFromDistal, 0.06, 1e-15);  // the assumption: a third of ankle-to-toe
  EXPECT_NEAR(fromToe.comFromDistal, 0.12, 1e-15);
  EXPECT_NEAR(fromAnkle.inertia, 0.824 * 0.26 * 0.26 / 12, 1e-15);
  foot.com = 0.25;  // beyond the toe of a 0.18 m ankle-to-toe foot
  EXPECT_THROW(assembleFoot(foot, 0.18, FootComFrom::kAnkle), std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
