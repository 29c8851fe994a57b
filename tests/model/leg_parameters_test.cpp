#include "model/leg_parameters.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

// The YAML values are decimal literals parsed to the nearest double, and lowering 0 adds
// or subtracts nothing; one subtraction (length - COM) may round once.
constexpr double kExact = 1e-15;

// Burkett 2004 Table 2: length, mass, COM from the distal end (magnitude), Izz, per
// thigh/shank/foot, and Tc.
struct Table2Row {
  const char* file;
  SegmentParams thigh, shank, foot;
  double tc;
};
const Table2Row kTable2[] = {
    {"p1", {0.410, 3.350, 0.284, 0.0264}, {0.515, 0.785, 0.260, 0.0161}, {0.240, 1.030, 0.140, 0.0059}, 10},
    {"p2", {0.435, 5.612, 0.165, 0.0744}, {0.520, 0.905, 0.255, 0.0039}, {0.245, 0.845, 0.145, 0.0073}, 9},
    {"p3", {0.440, 4.137, 0.335, 0.0241}, {0.540, 0.558, 0.280, 0.0033}, {0.240, 1.020, 0.140, 0.0060}, 5},
    {"p4", {0.450, 7.905, 0.310, 0.0795}, {0.530, 1.061, 0.290, 0.0171}, {0.220, 0.459, 0.170, 0.0030}, 15},
};

Participant load(const std::string& stem) {
  return loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/" + stem + ".yaml");
}

TEST(LegParameters, LoweringZeroReproducesBurkettTable2) {
  for (const Table2Row& row : kTable2) {
    SCOPED_TRACE(row.file);
    const Participant p = load(row.file);
    EXPECT_EQ(p.kneeFriction, row.tc);
    const LegGeometry g = calcLegGeometry(p, 0.0);
    EXPECT_EQ(g.thighLength, row.thigh.length);
    EXPECT_EQ(g.thighMass, row.thigh.mass);
    EXPECT_EQ(g.thighInertia, row.thigh.inertia);
    EXPECT_NEAR(g.thighLength - g.thighCom, row.thigh.comFromDistal, kExact);
    EXPECT_EQ(g.shankLength, row.shank.length);
    EXPECT_EQ(g.shankMass, row.shank.mass);
    EXPECT_EQ(g.shankInertia, row.shank.inertia);
    EXPECT_NEAR(g.shankLength - g.shankCom, row.shank.comFromDistal, kExact);
    EXPECT_EQ(g.footLength, row.foot.length);
    EXPECT_EQ(g.footMass, row.foot.mass);
    EXPECT_EQ(g.footInertia, row.foot.inertia);
    // Table 2's foot COM distance is read from the toe (the participant files say so).
    ASSERT_EQ(p.footComFrom, FootComFrom::kToe);
    EXPECT_NEAR(g.footLength - g.footComForward, row.foot.comFromDistal, kExact);
    EXPECT_EQ(g.added.mass, 0.0);
  }
}

TEST(LegParameters, LoweringLengthensThighShortensShankAndMovesComsByTheRule) {
  const double d = 0.1;
  for (const Table2Row& row : kTable2) {
    SCOPED_TRACE(row.file);
    Participant p = load(row.file);
    p.comRule = ComRule::kFixedFromProximal;
    const LegGeometry g = calcLegGeometry(p, d);
    EXPECT_NEAR(g.thighLength, row.thigh.length + d, kExact);
    EXPECT_NEAR(g.shankLength, row.shank.length - d, kExact);
    // Masses, inertias about the COMs and the foot are unchanged.
    EXPECT_EQ(g.thighMass, row.thigh.mass);
    EXPECT_EQ(g.shankMass, row.shank.mass);
    EXPECT_EQ(g.thighInertia, row.thigh.inertia);
    EXPECT_EQ(g.shankInertia, row.shank.inertia);
    EXPECT_EQ(g.footMass, row.foot.mass);
    EXPECT_NEAR(g.footLength - g.footComForward, row.foot.comFromDistal, kExact);
    // Fixed from the proximal joint: the COMs keep their distance from hip and knee, so
    // their distances from the distal ends change by +d (thigh) and -d (shank).
    EXPECT_NEAR(g.thighCom, row.thigh.length - row.thigh.comFromDistal, kExact);
    EXPECT_NEAR(g.shankCom, row.shank.length - row.shank.comFromDistal, kExact);
    EXPECT_NEAR(g.thighLength - g.thighCom, row.thigh.comFromDistal + d, kExact);
    EXPECT_NEAR(g.shankLength - g.shankCom, row.shank.comFromDistal - d, kExact);

    p.comRule = ComRule::kProportional;
    const LegGeometry gp = calcLegGeometry(p, d);
    EXPECT_NEAR(gp.thighCom / gp.thighLength, (row.thigh.length - row.thigh.comFromDistal) / row.thigh.length, kExact);
    EXPECT_NEAR(gp.shankCom / gp.shankLength, (row.shank.length - row.shank.comFromDistal) / row.shank.length, kExact);
  }
}

TEST(LegParameters, LoweringBeyondTheShankThrowsNamingTheParticipant) {
  for (const Table2Row& row : kTable2) {
    SCOPED_TRACE(row.file);
    const Participant p = load(row.file);
    const double tooFar = row.shank.length + 0.01;
    try {
      calcLegGeometry(p, tooFar);
      ADD_FAILURE() << "a lowering longer than the shank was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(p.name));
      EXPECT_THAT(e.what(), HasSubstr(p.path));
      EXPECT_THAT(e.what(), HasSubstr("lowering"));
    }
    // Just past the largest allowed lowering is also refused; the largest itself is not.
    EXPECT_NO_THROW(calcLegGeometry(p, calcMaxLowering(p)));
    EXPECT_THROW(calcLegGeometry(p, calcMaxLowering(p) + 1e-6), InputError);
    EXPECT_THROW(calcLegGeometry(p, -0.01), InputError);
  }
}

}  // namespace
}  // namespace swingsim
