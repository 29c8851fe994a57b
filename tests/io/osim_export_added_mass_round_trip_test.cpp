// An exported added mass comes back through import-osim as part of the shank (it is welded to
// the tibia): mass, COM and Izz by the hand formulas, and the imported leg swings as the
// simulated leg with the added mass did.
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "io/knee_model_loader.h"
#include "io/osim_model_writer.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

// Numbers written in full; sums and products add a few ulps of 1 m, 1 kg.
constexpr double kRoundTrip = 1e-12;
// Two Simbody models of one leg (a point mass on its own welded body, or folded into the shank)
// integrated at accuracy kAccuracy: their swing times agree to the integration error, far
// below the 0.1 ms the README's convergence study resolves.
constexpr double kAccuracy = 1e-8;
constexpr double kSwingTimeTol = 1e-5;  // s

constexpr double kLowering = 0.03;  // m
const AddedMass kAdded{0.7, 0.22};  // kg, m below the knee

struct RoundTrip {
  Participant p1 = loadParticipant(std::string(SWINGSIM_SOURCE_DIR) + "/participants/p1.yaml");
  LegGeometry exported = calcLegGeometry(p1, kLowering, kAdded);
  Participant back;
  RoundTrip() {
    OsimLegPlacement place;
    place.modelName = p1.name;
    place.bodyMass = p1.bodyMass;
    place.initial = p1.initial;
    place.hipRange = p1.hipRange;
    place.kneeMaxFlexion = 3;
    const OsimModel m = parseOsimModel(formatOsimModel(makeOsimLegModel(exported, place), "h"), "exported.osim");
    OsimImportOptions o;
    o.kneeModelPath = p1.kneeModelPath;
    back = calcOsimParticipant(m, o).participant;
  }
};

TEST(OsimExportAddedMassRoundTrip, TheMassComesBackInTheShankByTheHandFormulas) {
  const RoundTrip r;
  const LegGeometry& g = r.exported;
  const double ms = g.shankMass, ma = kAdded.mass, cs = g.shankCom, d = kAdded.distanceBelowKnee;
  const double com = (ms * cs + ma * d) / (ms + ma);                                              // below the knee
  const double izz = g.shankInertia + ms * (cs - com) * (cs - com) + ma * (d - com) * (d - com);  // parallel axes
  const LegGeometry h = calcLegGeometry(r.back, 0);
  EXPECT_NEAR(h.shankMass, ms + ma, kRoundTrip);
  EXPECT_NEAR(h.shankCom, com, kRoundTrip);
  EXPECT_NEAR(h.shankInertia, izz, kRoundTrip);
  EXPECT_NEAR(h.shankLength, g.shankLength, kRoundTrip);
  EXPECT_NEAR(h.thighMass, g.thighMass, kRoundTrip);
  EXPECT_NEAR(h.footMass, g.footMass, kRoundTrip);
  EXPECT_NEAR(r.back.bodyMass, r.p1.bodyMass + ma, kRoundTrip * 100) << "the model carries the body and the added mass";
}

TEST(OsimExportAddedMassRoundTrip, TheImportedLegSwingsAsTheSimulatedLegWithTheMass) {
  const RoundTrip r;
  SwingOptions options;
  options.accuracy = kAccuracy;
  const KneeModel knee = loadKneeModel(r.p1.kneeModelPath);
  const SwingResult simulated = simulateSwing(makeSwingSetup(r.p1, knee, kLowering, kAdded), options);
  // P1 with the imported leg (the lowered one, with the mass in its shank), nothing added.
  Participant imported = r.p1;
  imported.thigh = r.back.thigh;
  imported.shank = r.back.shank;
  imported.foot = r.back.foot;
  imported.footComFrom = r.back.footComFrom;
  const SwingResult played = simulateSwing(makeSwingSetup(imported, knee, 0), options);
  EXPECT_NEAR(played.swingTime, simulated.swingTime, kSwingTimeTol);
  RecordProperty("simulated_swing_time_s", formatNumber(simulated.swingTime));
  RecordProperty("imported_swing_time_s", formatNumber(played.swingTime));
  const SwingResult without = simulateSwing(makeSwingSetup(r.p1, knee, kLowering), options);
  EXPECT_GT(std::fabs(without.swingTime - simulated.swingTime), 100 * kSwingTimeTol)
      << "the mass matters at this tolerance";
  RecordProperty("without_mass_swing_time_s", formatNumber(without.swingTime));
}

}  // namespace
}  // namespace swingsim
