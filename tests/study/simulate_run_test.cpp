// One swing as simulate, Python and serve run it (study/simulate_run.h): the same swing as
// the swing layer's own set-up and run, simulate's options, the toe-off overrides and the
// printed summary.
#include "study/simulate_run.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/text_format.h"
#include "core/units.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {
namespace {

const std::string kRoot = SWINGSIM_SOURCE_DIR;

TEST(SimulateRun, IsTheSwingLayersSwingAtTheSameSettings) {
  const Participant p = loadParticipant(kRoot + "/participants/p1.yaml");
  const KneeModel knee = loadKneeModel(kRoot + "/models/mauch-4phase.yaml");
  const AddedMass added{0.5, 0.2};
  const SwingOptions options = makeSimulateOptions(std::nullopt, std::nullopt);
  const SimulateRun run = runSimulate(p, knee, 0.02, added, options);
  const SwingResult direct = simulateSwing(makeSwingSetup(p, knee, 0.02, added), options);
  ASSERT_GT(run.result.swingTime, 0);
  EXPECT_EQ(run.result.swingTime, direct.swingTime);  // the same computation: equal to the bit
  EXPECT_EQ(run.result.realizations, direct.realizations);
  EXPECT_EQ(run.setup.lowering, 0.02);
  EXPECT_EQ(run.setup.added.mass, 0.5);
  EXPECT_EQ(run.setup.participant.kneeModelPath, knee.path);  // the knee in use, not the participant's
}

TEST(SimulateRun, OptionsAreAnIntegratorAtItsConvergedAccuracyUnlessToldOtherwise) {
  const SwingOptions plain = makeSimulateOptions(std::nullopt, std::nullopt);
  EXPECT_TRUE(plain.trackImpactEnergy);  // one swing: the stop-impact bookkeeping is on
  EXPECT_EQ(plain.integrator, SwingOptions{}.integrator);
  EXPECT_EQ(plain.accuracy, SwingOptions{}.accuracy);
  for (const std::string& key : integratorKeys()) {
    const SwingOptions o = makeSimulateOptions(key, std::nullopt);
    EXPECT_EQ(o.integrator, *findIntegrator(key)) << key;
    EXPECT_EQ(o.accuracy, calcConvergedAccuracy(o.integrator)) << key;
    EXPECT_EQ(makeSimulateOptions(key, 3e-5).accuracy, 3e-5) << key;
  }
}

TEST(SimulateRun, ToeOffOverridesChangeOnlyWhatTheyName) {
  Participant p = loadParticipant(kRoot + "/participants/p1.yaml");
  const InitialConditions before = p.initial;
  applyToeOffOverrides(p, {}, "--knee-rate-deg-s");
  EXPECT_EQ(p.initial.hipFlexionRate, before.hipFlexionRate);
  EXPECT_EQ(p.initial.kneeFlexionRate, before.kneeFlexionRate);
  applyToeOffOverrides(p, {1.5, -2.0, KneeStart::kInitial}, "--knee-rate-deg-s");
  EXPECT_EQ(p.initial.hipFlexionRate, 1.5);
  EXPECT_EQ(p.initial.kneeFlexionRate, -2.0);
  EXPECT_EQ(p.initial.kneeStart, KneeStart::kInitial);
}

TEST(SimulateRun, AKneeRateUnderARecordThatSetsTheKneeIsRefusedByTheOptionsName) {
  Participant p = loadParticipant(kRoot + "/participants/winter.yaml");  // thigh drive; its record has the knee
  ToeOffOverrides rate;
  rate.kneeFlexionRate = 1.0;
  try {
    applyToeOffOverrides(p, rate, "knee_rate");
    FAIL() << "a knee rate the record overrides was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("knee_rate: under the measured thigh drive", 0), 0u) << e.what();
  }
  rate.kneeStart = KneeStart::kInitial;  // the participant's initial knee: the rate is used
  applyToeOffOverrides(p, rate, "knee_rate");
  EXPECT_EQ(p.initial.kneeFlexionRate, 1.0);
}

TEST(SimulateRun, TheSummaryPrintsTheRunsOwnNumbers) {
  const KneeModel knee = loadKneeModel(kRoot + "/models/damping-table-default.yaml");
  const SwingOptions options = makeSimulateOptions(std::nullopt, std::nullopt);
  const SimulateRun run = runSimulate(loadParticipant(kRoot + "/participants/p1.yaml"), knee, 0.0, {}, options);
  const std::string text = formatSimulateSummary(run, knee, options);
  EXPECT_EQ(text.rfind(run.setup.participant.name + ", knee lowered 0.000 m, knee model " + knee.name + "\n", 0), 0u)
      << text;
  EXPECT_NE(text.find(fmt("  swing time          %.4f s\n", run.result.swingTime)), std::string::npos) << text;
  EXPECT_NE(text.find(fmt("(%d realizations)", run.result.realizations)), std::string::npos) << text;
  for (const auto& e : run.result.events)
    EXPECT_NE(text.find(fmt(" %s@%.4f", e.name.c_str(), e.time)), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace swingsim
