// The independent sweep-table generator (tests/independent/sweep_table_generator.h) against
// swingsim's own sweep: with no hidden effect and no noise, the generator's swing times for
// Burkett's P1-P4 at 0, 0.05, 0.10 and 0.15 m must be swingsim's, read through the files the
// generator writes. Two codes written from the same docs that agree say the docs define the
// swing time; where they disagreed, one of them read the docs wrongly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../cli/release_only.h"
#include "../cli/run_swingsim.h"
#include "../independent/sweep_table_generator.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "sweep/sweep_assumptions.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

namespace fs = std::filesystem;

const std::vector<double> kLowerings = {0.0, 0.05, 0.10, 0.15};

// Tolerance of the cross-check, s: twice the swing time's documented convergence at
// swingsim's accuracy (0.1 ms: docs/speed.md), the generator's own step error being 1e-4 ms
// (SwingTimeConvergesWithTheStep). Measured: 0.002 ms without a bounce, 0.002 ms with
// bounces at accuracy 1e-7. What it resolves: standard gravity (9.80665) instead of
// swingsim's 9.81 moved every time by +0.04 ms; a hip moment without the 1/tau^2 of the time
// scale by 2-19 ms; at swingsim's default accuracy (1e-5) a bouncing swing is up to 0.57 ms
// from its converged value (P2 at 0.05 m, Tc 2 N m, e 0.9), hence 1e-7 there.
constexpr double kAgreeS = 0.2e-3;
// An effect is visible when it moves a swing time by more than this, s: ten times the
// generator's step error (1e-4 ms) and the largest cross-check difference (0.012 ms) both
// lie far below it.
constexpr double kVisibleS = 1e-3;
// Unchanged: within the friction's tail above 4 deg (its tanh gate leaves 3e-4 of Tc at
// the zone's 6 deg), s.
constexpr double kUnchangedS = 1e-5;
// The generator's step error allowed at kSweepStep, s: 20 times below kAgreeS, so the
// cross-check measures swingsim and the docs' reading, not our step (measured: 1e-7 s).
constexpr double kStepErrorS = 1e-5;

// swingsim's sweep (runSweep, through the study reader) of the files the generator wrote
// for `participants` under `model`, at kLowerings and Dormand-Prince `accuracy`, against the
// generator's noiseless table; prints both. Returns the number of swings that bounced.
int crossCheck(const std::string& tag, const std::vector<independent::SweepParticipant>& participants,
               const independent::SweepModel& model, double accuracy) {
  const fs::path dir = testing::freshTempDir("swingsim_indep_sweep", tag);
  const auto files = independent::writeSweepModelFiles(participants, model, dir.string());
  std::ostringstream list;
  for (std::size_t i = 0; i < files.size(); ++i) list << (i ? ", " : "") << files[i];
  std::ofstream(dir / "study.yaml") << "kind: knee-axis-sweep\nname: independent-" << tag << "\nparticipants: ["
                                    << list.str()
                                    << "]\nlowering: {step_m: 0.05, max_m: 0.15, include_published: false}\n"
                                    << "integrator: {method: dormand-prince, accuracy: " << accuracy << "}\n";
  const SweepResults swept = runSweep(loadSweepStudy((dir / "study.yaml").string()), 2);
  int bounced = 0;
  EXPECT_EQ(swept.participants.size(), participants.size());
  std::printf("%s: participant lowering_m generator_ms swingsim_ms diff_ms bounces\n", tag.c_str());
  for (std::size_t i = 0; i < std::min(participants.size(), swept.participants.size()); ++i) {
    const auto& ps = swept.participants[i];
    EXPECT_EQ(ps.points.size(), kLowerings.size()) << ps.name;
    for (std::size_t j = 0; j < std::min(kLowerings.size(), ps.points.size()); ++j) {
      const auto& point = ps.points[j];
      EXPECT_NEAR(point.lowering, kLowerings[j], 1e-12);
      const auto ours = independent::simulateSweepSwing(participants[i], model, {}, kLowerings[j]);
      EXPECT_FALSE(ours.hipRangeActed) << "the hip range stop acted: its law (ours is a guess) would matter";
      // Both end, or neither does (the thigh no longer reaches its target).
      EXPECT_EQ(point.ok, ours.ended) << ps.name << " at " << point.lowering << " m: " << point.failure;
      if (!point.ok || !ours.ended) {
        std::printf("%s %.2f %s %s\n", ps.name.c_str(), point.lowering, ours.ended ? "ends" : "no-end",
                    point.ok ? "ends" : "no-end");
        continue;
      }
      const double theirs = point.result.swingTime;
      std::printf("%s %.2f %.3f %.3f %+.3f %d\n", ps.name.c_str(), point.lowering, 1e3 * ours.swingTime, 1e3 * theirs,
                  1e3 * (ours.swingTime - theirs), ours.bounces);
      EXPECT_NEAR(ours.swingTime, theirs, kAgreeS) << ps.name << " at " << point.lowering << " m";
      EXPECT_EQ(ours.bounces, point.result.bounces) << ps.name << " at " << point.lowering << " m";
      bounced += ours.bounces > 0;
    }
  }
  fs::remove_all(dir);
  return bounced;
}

// The files' own values (Table 2 friction, the default stop): the knee never bounces, the
// swing ends when the knee enters the zone at 6 deg, before friction (below 4 deg) and the
// stop (at 0 deg) act.
TEST(SweepTableGenerator, AgreesWithSwingsimsSweepWithoutHiddenEffects) {
  SWINGSIM_RELEASE_ONLY();
  EXPECT_EQ(crossCheck("defaults", independent::burkettParticipants(), independent::SweepModel{}, 1e-5), 0);
}

// A lively stop (e = 0.9) with little or no friction: the knee bounces out of the zone, so
// the stop law, the friction near extension and the settle rule after a bounce decide the
// swing time.
TEST(SweepTableGenerator, AgreesWithSwingsimsSweepWhenTheKneeBounces) {
  SWINGSIM_RELEASE_ONLY();
  independent::SweepModel lively;
  lively.stopRestitution = 0.9;
  for (double friction : {0.0, 2.0}) {
    auto participants = independent::burkettParticipants();
    for (auto& p : participants) p.kneeFrictionNm = friction;
    EXPECT_GE(crossCheck("bounce-Tc" + std::to_string(static_cast<int>(friction)), participants, lively, 1e-7), 3);
  }
}

// The swing-end rule's "in whichever order": with a wide zone (35 deg) and a high thigh
// target (26 deg) P4's knee is back in the zone at 0.15 m before his thigh reaches its
// target, and the swing ends when the thigh does. P2's thigh never gets there from 0.05 m:
// no end on either side.
TEST(SweepTableGenerator, AgreesWithSwingsimsSweepWhenTheThighArrivesLast) {
  SWINGSIM_RELEASE_ONLY();
  independent::SweepModel late;
  late.zoneDeg = 35;
  late.thighTargetDeg = 26;
  const auto participants = independent::burkettParticipants();
  const auto s = independent::simulateSweepSwing(participants[3], late, {}, 0.15);
  EXPECT_GT(s.thighTargetTime, s.kneeEntryTime + 100 * kVisibleS);
  EXPECT_EQ(s.swingTime, s.thighTargetTime);
  crossCheck("thigh-last", participants, late, 1e-5);
}

// The other COM rule, as the files name it (docs/assumptions.md "COM rule").
TEST(SweepTableGenerator, AgreesWithSwingsimsSweepUnderTheProportionalComRule) {
  SWINGSIM_RELEASE_ONLY();
  independent::SweepModel proportional;
  proportional.comRule = independent::ComRule::kProportional;
  crossCheck("proportional", independent::burkettParticipants(), proportional, 1e-5);
}

// The hip effort adaptation (docs/uncertainty.md `hip_effort_adaptation`) as the generator
// reads it, against swingsim's own (calcAdaptedParticipant), for an exponent of either sign.
TEST(SweepTableGenerator, EffortAdaptationIsSwingsims) {
  SWINGSIM_RELEASE_ONLY();
  const fs::path dir = testing::freshTempDir("swingsim_indep_sweep", "effort");
  const auto participants = independent::burkettParticipants();
  const independent::SweepModel model;
  const auto files = independent::writeSweepModelFiles(participants, model, dir.string());
  for (std::size_t i = 0; i < participants.size(); ++i) {
    const Participant loaded = loadParticipant(files[i]);
    const KneeModel knee = loadKneeModel(loaded.kneeModelPath);
    for (double a : {-1.0, 0.5})
      for (double d : {0.05, 0.10}) {
        independent::SweepEffects fx;
        fx.hipEffortExponent = a;
        const auto ours = independent::simulateSweepSwing(participants[i], model, fx, d);
        SwingOptions options;
        options.requireSwingEnd = false;  // NaN where the thigh no longer reaches its target
        const double theirs =
            simulateSwing(makeSwingSetup(calcAdaptedParticipant(loaded, d, a), knee, d), options).swingTime;
        EXPECT_EQ(ours.ended, !std::isnan(theirs)) << loaded.name << " a " << a << " at " << d << " m";
        if (!ours.ended) continue;
        std::printf("effort a=%+.1f %s %.2f m: generator %.3f ms, swingsim %.3f ms\n", a, loaded.name.c_str(), d,
                    1e3 * ours.swingTime, 1e3 * theirs);
        EXPECT_NEAR(ours.swingTime, theirs, kAgreeS) << loaded.name << " a " << a << " at " << d << " m";
      }
  }
  fs::remove_all(dir);
}

TEST(SweepTableGenerator, SwingTimeConvergesWithTheStep) {
  const auto participants = independent::burkettParticipants();
  const independent::SweepModel model;
  for (const auto& p : {participants[0], participants[3]})
    for (double d : {0.0, 0.15}) {
      const double coarse = independent::simulateSweepSwing(p, model, {}, d, 2e-4).swingTime;
      const double used = independent::simulateSweepSwing(p, model, {}, d, independent::kSweepStep).swingTime;
      const double fine = independent::simulateSweepSwing(p, model, {}, d, 2.5e-5).swingTime;
      std::printf("%s %.2f m: step 2e-4 %.4f ms, 1e-4 %.4f ms, 2.5e-5 %.4f ms\n", p.name.c_str(), d, 1e3 * coarse,
                  1e3 * used, 1e3 * fine);
      EXPECT_LT(std::abs(used - fine), kStepErrorS) << p.name << " at " << d << " m";
    }
}

TEST(SweepTableGenerator, LoweringMovesTheKneeAxisAsBurkettDoes) {
  const independent::Leg p1 = independent::burkettParticipants()[0].leg;
  const auto fixed = independent::lowerKneeAxis(p1, 0.10, independent::ComRule::kFixedFromProximal);
  EXPECT_NEAR(fixed.thigh.length, 0.510, 1e-12);
  EXPECT_NEAR(fixed.shank.length, 0.415, 1e-12);
  EXPECT_NEAR(fixed.thigh.length - fixed.thigh.comFromDistal, 0.410 - 0.284, 1e-12);  // from the hip
  EXPECT_NEAR(fixed.shank.length - fixed.shank.comFromDistal, 0.515 - 0.260, 1e-12);  // from the knee
  const auto prop = independent::lowerKneeAxis(p1, 0.10, independent::ComRule::kProportional);
  EXPECT_NEAR(prop.thigh.comFromDistal / prop.thigh.length, 0.284 / 0.410, 1e-12);
  EXPECT_NEAR(prop.shank.comFromDistal / prop.shank.length, 0.260 / 0.515, 1e-12);
  for (const auto& leg : {fixed, prop}) {
    EXPECT_EQ(leg.thigh.inertia, p1.thigh.inertia);
    EXPECT_EQ(leg.shank.inertia, p1.shank.inertia);
    EXPECT_EQ(leg.foot.length, p1.foot.length);
    EXPECT_EQ(leg.foot.comFromDistal, p1.foot.comFromDistal);
  }
  // Less inertia below a lower knee; I_k by hand at 0 m: 0.0161 + 0.785 0.255^2 + 0.0059
  // + 1.030 (0.100^2 + 0.515^2).
  EXPECT_NEAR(independent::kneeInertia(p1), 0.0161 + 0.785 * 0.255 * 0.255 + 0.0059 + 1.030 * (0.01 + 0.515 * 0.515),
              1e-12);
  EXPECT_LT(independent::kneeInertia(fixed), independent::kneeInertia(p1));
  EXPECT_THROW(independent::lowerKneeAxis(p1, 0.42, independent::ComRule::kProportional), std::invalid_argument);
  EXPECT_THROW(independent::lowerKneeAxis(p1, 0.27, independent::ComRule::kFixedFromProximal), std::invalid_argument);
}

// What each hidden effect does to P1's swing time at 0, 0.1 and 0.2 m (printed for the
// docs; "nan": no swing end). The lowering-driven effects are off at the standard
// location; the stop's restitution and the friction act only through a bounce.
TEST(SweepTableGenerator, HiddenEffectsChangeTheSwingTimes) {
  const auto p1 = independent::burkettParticipants()[0];
  const independent::SweepModel model;
  const std::vector<double> lowerings = {0.0, 0.10, 0.20};
  auto times = [&](const independent::SweepEffects& fx) {
    std::vector<double> t;
    for (double d : lowerings) t.push_back(independent::simulateSweepSwing(p1, model, fx, d).swingTime);
    return t;
  };
  const auto base = times({});
  ASSERT_FALSE(std::isnan(base[2]));
  std::printf("P1 none: %.1f %.1f %.1f ms at 0, 0.1, 0.2 m\n", 1e3 * base[0], 1e3 * base[1], 1e3 * base[2]);
  auto effect = [&](const char* name, const independent::SweepEffects& fx) {
    const auto t = times(fx);
    std::printf("P1 %s: %+.1f %+.1f %+.1f ms\n", name, 1e3 * (t[0] - base[0]), 1e3 * (t[1] - base[1]),
                1e3 * (t[2] - base[2]));
    return t;
  };
  for (double a : {1.0, -1.0}) {
    independent::SweepEffects fx;
    fx.hipEffortExponent = a;
    const auto t = effect(a > 0 ? "a=+1" : "a=-1", fx);
    EXPECT_EQ(t[0], base[0]);
    EXPECT_GT(std::abs(t[1] - base[1]), kVisibleS);
  }
  for (double c : {0.1, -0.1}) {  // swing time rises with the time scale (docs/assumptions.md, Hip moment)
    independent::SweepEffects fx;
    fx.timeScaleSlope = c;
    const auto t = effect(c > 0 ? "c=+0.1" : "c=-0.1", fx);
    EXPECT_EQ(t[0], base[0]);
    if (c > 0) {
      EXPECT_GT(t[1], base[1] + kVisibleS);
    } else {
      EXPECT_LT(t[1], base[1] - kVisibleS);
    }
  }
  independent::SweepEffects stop;
  stop.stopRestitution = 0.7;
  stop.kneeFrictionNm = 3.0;  // the knee still does not leave the zone: nothing changes
  auto t = effect("e=0.7,Tc=3", stop);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], base[i], kUnchangedS);
  stop.kneeFrictionNm = 0.0;  // now it bounces at the standard location
  t = effect("e=0.7,Tc=0", stop);
  EXPECT_GT(independent::simulateSweepSwing(p1, model, stop, 0.0).bounces, 0);
  EXPECT_GT(t[0], base[0] + 50 * kVisibleS);  // a bounce costs 100-350 ms
  independent::SweepEffects com;
  com.comRule = independent::ComRule::kProportional;
  t = effect("com=proportional", com);
  EXPECT_EQ(t[0], base[0]);
  EXPECT_GT(std::abs(t[2] - base[2]), kVisibleS);
  independent::SweepEffects retune;
  retune.dampingRetune = 1.0;  // the prosthetist doubles the damping at 0.1 m: outside the library
  t = effect("retune k=1", retune);
  EXPECT_EQ(t[0], base[0]);
  EXPECT_GT(std::abs(t[1] - base[1]), kVisibleS);
  independent::SweepEffects strap;
  strap.strapStiffness = 8.0;  // outside the library
  strap.strapOffset = 0.2;
  t = effect("strap 8 N m/rad", strap);
  EXPECT_GT(std::abs(t[0] - base[0]), kVisibleS);
}

// The noise: the same seed gives the same table; rows scatter about the truth with the SD of
// a mean of 5 trials of Table 3's SD; the CSV carries the trial SD and n.
TEST(SweepTableGenerator, NoiseHasTheSdOfAMeanOfFiveTrials) {
  auto participants = independent::burkettParticipants();
  const independent::SweepModel model;
  const std::vector<double> lowerings = {0.0, 0.05};
  const auto clean = independent::generateSweepTable(participants, lowerings, model, {}, 1, 0.0);
  const auto a = independent::generateSweepTable(participants, lowerings, model, {}, 7);
  const auto b = independent::generateSweepTable(participants, lowerings, model, {}, 7);
  const auto c = independent::generateSweepTable(participants, lowerings, model, {}, 8);
  ASSERT_EQ(a.size(), 8u);
  for (std::size_t i = 0; i < clean.size(); ++i)
    EXPECT_EQ(clean[i].swingTimeS,
              independent::simulateSweepSwing(participants[i / 2], model, {}, lowerings[i % 2]).swingTime);
  double chi2 = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].swingTimeS, b[i].swingTimeS);
    EXPECT_NE(a[i].swingTimeS, c[i].swingTimeS);
    const double sdMean = a[i].sdS / std::sqrt(5.0);
    chi2 += std::pow((a[i].swingTimeS - clean[i].swingTimeS) / sdMean, 2) +
            std::pow((c[i].swingTimeS - clean[i].swingTimeS) / sdMean, 2);
  }
  EXPECT_NEAR(a[0].sdS, 0.031, 1e-12);
  EXPECT_NEAR(a[2].sdS, 0.047, 1e-12);
  // 16 standardized residuals: chi-square with 16 degrees of freedom, 0.1 % to 99.9 %.
  EXPECT_GT(chi2, 3.94);
  EXPECT_LT(chi2, 39.25);
  const fs::path dir = testing::freshTempDir("swingsim_indep_sweep", "csv");
  independent::writeSweepCsv(a, (dir / "table.csv").string());
  std::ifstream in(dir / "table.csv");
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "participant,lowering_m,swing_time_s,sd_s,n");
  EXPECT_EQ(first.rfind("P1,0,", 0), 0u) << first;
  EXPECT_EQ(first.substr(first.size() - 8), ",0.031,5") << first;
  fs::remove_all(dir);
}

// Table 4's own lowerings: P2's thigh no longer reaches its target at 0.18 m under the
// files' time scale; the generator says who and where instead of writing a row.
TEST(SweepTableGenerator, ASwingWithoutAnEndIsNamed) {
  const auto participants = independent::burkettParticipants();
  const auto lowerings = independent::burkettTable4Lowerings();
  try {
    independent::generateSweepTableByParticipant(participants, lowerings, independent::SweepModel{}, {}, 1);
    ADD_FAILURE() << "P2 at 0.18 m has no swing end";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("P2 at lowering 0.18"), std::string::npos) << e.what();
  }
  EXPECT_THROW(independent::generateSweepTableByParticipant(participants, {{0.0}}, independent::SweepModel{}, {}, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace swingsim
