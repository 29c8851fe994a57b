// Failing runs explain themselves (docs/robustness.md): an integrator failure, a swing that never
// ends and a hip driven out of its range each throw RunError with the time, the state and
// the likely cause in words; the CLI turns that into exit code 1 and writes nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "../cli/run_swingsim.h"
#include "core/input_error.h"
#include "identify/bench_data.h"
#include "identify/cylinder_fit.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;
namespace fs = std::filesystem;

// A knee law that breaks once the knee flexes past 30 deg: NaN, as a law with a
// division by a vanishing quantity would return.
class BrokenKnee final : public KneeLaw {
 public:
  std::string name() const override { return "broken"; }
  double calcMoment(const KneeKinematics& knee, const double*) const override {
    return knee.flexion > 30 * kDegToRad ? std::numeric_limits<double>::quiet_NaN() : 0.0;
  }
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<BrokenKnee>(*this); }
};

std::string runErrorOf(const SwingSetup& setup) {
  try {
    simulateSwing(setup);
  } catch (const RunError& e) {
    return e.what();
  }
  return "(no RunError)";
}

// "at t = 0.1234 s: hip flexion 1.2 deg (3 deg/s), knee flexion ..." from describeState.
constexpr const char* kStatePattern = "at t = [0-9.]+ s: hip flexion -?[0-9.]+ deg \\(-?[0-9]+ deg/s\\), knee flexion";

TEST(FailingRuns, IntegratorFailureGivesTimeStateAndCause) {
  const SwingSetup setup =
      makeSwingSetup(loadParticipant("participants/p1.yaml"), std::make_shared<const BrokenKnee>());
  const std::string e = runErrorOf(setup);
  EXPECT_THAT(e, HasSubstr("P1: "));
  EXPECT_THAT(e, ::testing::ContainsRegex(kStatePattern));
  EXPECT_THAT(e, HasSubstr("likely cause"));
  // The default integrator names the failure where it starts, not where Simbody trips
  // over the NaN a step later.
  EXPECT_THAT(e, HasSubstr("is not finite"));
  EXPECT_THAT(e, HasSubstr("returned NaN or infinity"));
}

TEST(FailingRuns, SwingThatNeverEndsGivesTimeStateAndCause) {
  Participant p = loadParticipant("participants/p1.yaml");
  p.hipMoment.flexionAmplitude = 0;  // nothing drives the thigh to its target
  p.hipMoment.extensionAmplitude = 0;
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingSetup setup = makeSwingSetup(p, knee);
  // Decided early (SwingOptions::earlyThighFailure): the leg cannot gain the energy.
  const std::string e = runErrorOf(setup);
  EXPECT_THAT(e, HasSubstr("the swing cannot end (decided at t = "));
  EXPECT_THAT(e, ::testing::ContainsRegex(kStatePattern));
  EXPECT_THAT(e, HasSubstr("the thigh never reached its target flexion of 20 deg and cannot any more"));
  EXPECT_THAT(e, HasSubstr("hip moment too small"));
  // Without the early decision the time limit ends it.
  SwingOptions full;
  full.earlyThighFailure = false;
  std::string late = "(no RunError)";
  try {
    simulateSwing(setup, full);
  } catch (const RunError& error) {
    late = error.what();
  }
  EXPECT_THAT(late, HasSubstr("the swing did not end within the time limit of 1.5 s"));
  EXPECT_THAT(late, ::testing::ContainsRegex(kStatePattern));
  EXPECT_THAT(late, HasSubstr("the thigh never reached its target flexion of 20 deg (hip moment too small"));
}

// Before this check the soft hip stop let the thigh sail ~20 deg past 90 deg and the swing
// "ended" there, which looked like a result.
TEST(FailingRuns, HipDrivenOutOfItsRangeGivesTimeStateAndCause) {
  Participant p = loadParticipant("participants/p1.yaml");
  p.hipMoment.flexionAmplitude = 5000;  // N m: far beyond any hip; slams the thigh into its stop
  p.swingEnd.thighTargetFlexion = 89 * kDegToRad;
  const auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(p, loadKneeModel(p.kneeModelPath)));
  SwingSetup setup = makeSwingSetup(p, knee);
  const std::string e = runErrorOf(setup);
  EXPECT_THAT(e, HasSubstr("left its range"));
  EXPECT_THAT(e, HasSubstr("-30 to 90 deg"));
  EXPECT_THAT(e, ::testing::ContainsRegex(kStatePattern));
  EXPECT_THAT(e, HasSubstr("likely cause"));
}

// The CLI: exit code 1, the message, and no output files.
TEST(FailingRuns, CliExitsOneAndWritesNothing) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim_failing_runs_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ifstream in("participants/p1.yaml");
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  text.replace(text.find("flexion_amplitude_Nm: 30"), 24, "flexion_amplitude_Nm: 0");
  text.replace(text.find("../models"), 9, fs::absolute("models").string());
  std::ofstream(dir / "weak.yaml") << text;
  const swingsim::testing::CliRun run =
      swingsim::testing::runSwingsim(std::string("simulate ") + (dir / "weak.yaml").string() + " --out " +
                                     (dir / "out").string() + " --json " + (dir / "r.json").string());
  const std::string& output = run.output;
  EXPECT_EQ(run.code, 1) << output;
  EXPECT_THAT(output, HasSubstr("swingsim: P1 at lowering 0 m: the swing cannot end"));
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

// A bench record that never comes near full extension (here: the normal-speed record moved
// 8 mm into flexion) leaves the 4-phase model's hyperextension phase without data. Before
// this check the column-scaled regression still reported "rank 12" and returned phase
// coefficients of 1e16 N with exit code 0 and a complete-looking report.
BenchData recordWithoutHyperextension() {
  BenchData d = readBenchCsv("studies/data/mauch2014/normal.csv", 3);
  constexpr double kOffset = 0.008;  // m: the deepest extension becomes x = +8 mm, far above xhy
  for (double& x : d.position) x += kOffset;
  return d;
}

TEST(FailingRuns, SingularRegressionNamesThePhaseTheDataAndTheCause) {
  try {
    fitCylinder(loadMauchCylinder("models/mauch-4phase.yaml"), {recordWithoutHyperextension()});
    ADD_FAILURE() << "a fit with an unidentified phase returned";
  } catch (const RunError& e) {
    // Phase 2 follows the S2 latch, which only hyperextension sets: it is idle too.
    EXPECT_THAT(e.what(), ::testing::ContainsRegex("cannot fit the 4-phase model: phase 2 in [-0-9.e]+, phase 4 in "));
    EXPECT_THAT(
        e.what(),
        HasSubstr(" of 1783 training samples (studies/data/mauch2014/normal.csv; piston position 6.31 to 33.3 mm"));
    EXPECT_THAT(e.what(), HasSubstr("singular regression"));
    EXPECT_THAT(e.what(), HasSubstr("Likely cause: the training record never enters those phases (no hyperextension"));
  }
  // The 2-phase model has no hyperextension phase: the same record fits.
  EXPECT_NO_THROW(fitCylinder(loadMauchCylinder("models/mauch-2phase.yaml"), {recordWithoutHyperextension()}));
}

TEST(FailingRuns, FitCliWithSingularRegressionExitsOneAndWritesNothing) {
  const fs::path dir = fs::temp_directory_path() / ("swingsim_failing_fit_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const BenchData d = recordWithoutHyperextension();
  {
    std::ofstream csv(dir / "far.csv");
    csv.precision(17);
    csv << "time_s,position_m,force_N\n";
    for (std::size_t i = 0; i < d.time.size(); ++i)
      csv << d.time[i] << "," << d.position[i] << "," << d.force[i] << "\n";
  }
  std::ofstream(dir / "study.yaml") << "kind: cylinder-fit\nname: far\nmodels: ["
                                    << fs::absolute("models/mauch-4phase.yaml").string() << "]\ntrain: [far.csv]\n";
  const swingsim::testing::CliRun run =
      swingsim::testing::runSwingsim(std::string("fit ") + (dir / "study.yaml").string() + " --out " +
                                     (dir / "out").string() + " --json " + (dir / "r.json").string());
  const std::string& output = run.output;
  EXPECT_EQ(run.code, 1) << output;
  EXPECT_THAT(output, HasSubstr("swingsim: cannot fit the 4-phase model: phase 2 in "));
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

// Budgets: a swing past its realization or wall-clock budget stops with a
// RunError naming the participant, the lowering, the integrator and what to change.
SwingSetup p1Setup(const KneeModel& model) {
  return makeSwingSetup(loadParticipant("participants/p1.yaml"), model, 0.05);
}

TEST(FailingRuns, RealizationBudgetStopsTheSwingAndSaysWhatToChange) {
  const KneeModel model = loadKneeModel("models/damping-table-default.yaml");
  const SwingSetup setup = p1Setup(model);
  SwingOptions options;
  options.maxRealizations = 100;  // a normal swing takes about 300
  try {
    simulateSwing(setup, options);
    ADD_FAILURE() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_THAT(e.what(), HasSubstr("P1 at lowering 0.05 m: the swing was stopped after "));
    EXPECT_THAT(e.what(), HasSubstr("realizations (the budget of one swing is 100;"));
    EXPECT_THAT(e.what(), HasSubstr("with Dormand-Prince 5(4) over Simbody realizations at accuracy 1e-05"));
    EXPECT_THAT(e.what(), HasSubstr("loosen the accuracy"));
    EXPECT_THAT(e.what(), HasSubstr("damping-table-default.yaml for a value far too large"));
  }
  options.maxRealizations = SwingOptions{}.maxRealizations;
  EXPECT_NO_THROW(simulateSwing(setup, options));  // the default is far above a normal swing
}

TEST(FailingRuns, WallClockBudgetStopsTheSwing) {
  const KneeModel model = loadKneeModel("models/damping-table-default.yaml");
  const SwingSetup setup = p1Setup(model);
  SwingOptions options = makeSimbodyIntegratorOptions();
  options.maxWallSeconds = 0;
  try {
    simulateSwing(setup, options);
    ADD_FAILURE() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_THAT(
        e.what(),
        HasSubstr("P1 at lowering 0.05 m: the swing was stopped after 0 s of computing (the limit for one swing"));
    EXPECT_THAT(e.what(), HasSubstr("with Simbody Runge-Kutta-Merson at accuracy 0.0001"));
  }
}

}  // namespace
}  // namespace swingsim
