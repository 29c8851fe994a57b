#pragma once
// The sweep plant's cases of the calibration study (docs/diagnosis.md, "How far the intervals
// can be trusted (calibration)"): sweep tables from the independent generator
// (tests/independent/sweep_table_generator.h: its own equations, knee, stop and swing-end
// rule), each sweep candidate the generator can hide at a stated size away from the files,
// plus a null, diagnosed as a user's sweep study. As IndependentSweepDiagnosis: every
// participant at 0-200 mm in 50 mm steps where the truth ends a swing, 20 trials a row with
// Burkett Table 3's trial-to-trial SD; unlike it, the truth's hip drive is 4 % slower than the
// files' (kSweepTruthTempo).
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "../independent/sweep_table_generator.h"
#include "identify/diagnosis_engine.h"
#include "study/diagnosis_study.h"

namespace swingsim::calibration {

constexpr int kSweepTrials = 20;           // trials a row (Burkett: 5; 20 as IndependentSweepDiagnosis)
constexpr double kSweepTruthTempo = 1.04;  // the truth's hip time scale over the files'
/// The calibration's seed k draws its records' noise with seed k x this (runCase).
constexpr std::uint64_t kNoiseSeedFactor = 7919;

/// What the truth hides: the generator's hidden effects, its model (the files keep the
/// default SweepModel) and a change to the participants after their files are written.
struct SweepTruth {
  independent::SweepEffects effects;
  independent::SweepModel model;
  std::function<void(independent::SweepParticipant&)> participant;
};

/// The sweep table of `truth` (noise seed `seed`) as a user's sweep study over every sweep
/// candidate, one effect at most: `use` gets its plant and study while their files exist.
inline void withSweepCalibrationPlant(const SweepTruth& truth, std::uint64_t seed, const std::string& tag,
                                      const std::function<void(const DiagnosisPlant&, const DiagnosisStudy&)>& use) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("swingsim-calibration-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const independent::SweepModel files;
  auto participants = independent::burkettParticipants();
  const auto fileNames = independent::writeSweepModelFiles(participants, files, dir.string());
  const std::vector<double> grid = {0.0, 0.05, 0.10, 0.15, 0.20};
  std::vector<std::vector<double>> lowerings;
  for (auto& p : participants) {
    p.timeScale *= kSweepTruthTempo;
    p.trials = kSweepTrials;
    if (truth.participant) truth.participant(p);
    lowerings.emplace_back();
    for (double d : grid)
      if (independent::simulateSweepSwing(p, truth.model, truth.effects, d).ended) lowerings.back().push_back(d);
  }
  independent::writeSweepCsv(
      independent::generateSweepTableByParticipant(participants, lowerings, truth.model, truth.effects, seed),
      (dir / "measured.csv").string());
  {
    std::ofstream sweep(dir / "sweep.yaml");
    sweep << "kind: knee-axis-sweep\nname: calibration\nparticipants: [";
    for (std::size_t i = 0; i < fileNames.size(); ++i)
      sweep << (i ? ", " : "") << fs::path(fileNames[i]).filename().string();
    sweep << "]\nintegrator: {method: dormand-prince, accuracy: 1.0e-5}\n";
    std::ofstream study(dir / "study.yaml");
    study << "kind: sweep-diagnosis\nname: calibration-" << tag << "\nsweep: sweep.yaml\nmeasured: measured.csv\n"
          << "acceptance: {max_effects: 1, whiteness_lags: 2}\n";
  }
  const DiagnosisStudy study = loadDiagnosisStudy((dir / "study.yaml").string());
  const auto plant = loadDiagnosisPlant(study, 0);
  use(*plant, study);
  if (!std::getenv("SWINGSIM_KEEP_TEST_FILES")) fs::remove_all(dir);
}

/// The sweep table of `truth` (noise seed `seed`), diagnosed as a user's sweep study over
/// every sweep candidate, one effect at most.
inline Diagnosis diagnoseSweep(const SweepTruth& truth, std::uint64_t seed, const std::string& tag) {
  Diagnosis dg;
  withSweepCalibrationPlant(truth, seed, tag, [&](const DiagnosisPlant& plant, const DiagnosisStudy& study) {
    dg = runDiagnosis(plant, study.settings);
  });
  return dg;
}

/// One sweep candidate hidden in the truth: what it is, its size and how to hide it.
struct SweepHidden {
  std::string effect, parameter;  ///< library effect ("" null) and the parameter held against the truth
  double truth;                   ///< the parameter's true value
  std::string size;               ///< in words, for the table
  std::function<void(SweepTruth&)> hide;
};

/// A null and each candidate the generator can hide. Sizes are away from the files (and from
/// the candidates' starting values), inside each candidate's range
/// (identify/sweep_effects.cpp). The hip effort and hip tempo sizes are the smallest of 1, 1.5
/// and 2 x the first study's (-1, -0.1) whose RMS change after each participant's mean
/// (calcSweepEffectSize) reaches twice a row's 8.8 ms noise, where the seed-1 likelihood
/// ratios put the acceptance threshold (docs/diagnosis.md).
inline std::vector<SweepHidden> sweepHiddenEffects() {
  using ST = SweepTruth;
  return {
      {"", "", 0, "none (hip drive 4 % slower than the files)", nullptr},
      {"hip_effort_adaptation", "exponent", -1.5, "exponent -1.5", [](ST& t) { t.effects.hipEffortExponent = -1.5; }},
      {"hip_tempo_lowering", "change_per_100mm", -0.15, "time scale -15 % per 100 mm",
       [](ST& t) { t.effects.timeScaleSlope = -0.15; }},
      // One value: a switch, named or not; its "interval" is the value itself.
      {"com_rule_proportional", "", 0, "COMs proportional to the new lengths",
       [](ST& t) { t.effects.comRule = independent::ComRule::kProportional; }},
      {"knee_friction_scale", "scale", 1.6, "Tc x 1.6 in every knee",
       [](ST& t) { t.participant = [](independent::SweepParticipant& p) { p.kneeFrictionNm *= 1.6; }; }},
      {"stop_restitution", "restitution", 0.15, "e 0.15 (files 0.4)", [](ST& t) { t.effects.stopRestitution = 0.15; }},
      {"stop_stiffness", "stiffness_Nm_per_rad1p5", 6e4, "6e4 N m/rad^1.5 (files 2e4)",
       [](ST& t) { t.model.stopStiffness = 6e4; }},
      {"hip_extension_ratio", "ratio", 0.7, "extension 21 N m over flexion 30 N m (files 0.5)",
       [](ST& t) { t.model.extensionNm = 21.0; }},
      {"hip_flexion_duration", "duration_s", 0.24, "flexion half-sine 0.24 s (files 0.20)",
       [](ST& t) { t.model.flexionS = 0.24; }},
      {"hip_extension_duration", "duration_s", 0.25, "extension half-sine 0.25 s (files 0.20)",
       [](ST& t) { t.model.extensionS = 0.25; }},
      {"thigh_target_flexion", "flexion_deg", 25.0, "swing ends at thigh 25 deg (files 20)",
       [](ST& t) { t.model.thighTargetDeg = 25.0; }},
  };
}

/// Every sweep case of the calibration study, one per sweepHiddenEffects().
template <typename Case>
std::vector<Case> sweepCalibrationCases() {
  std::vector<Case> out;
  for (const SweepHidden& h : sweepHiddenEffects()) {
    Case c{"sweep", h.effect, h.parameter, h.truth, h.size, {}};
    c.diagnose = [hide = h.hide](std::uint64_t seed, const std::string& tag) {
      SweepTruth truth;
      if (hide) hide(truth);
      return diagnoseSweep(truth, seed, tag);
    };
    out.push_back(std::move(c));
  }
  return out;
}

/// How far a hidden sweep effect moves the truth's swing times, noise free: over the rows the
/// calibration's tables have (every participant at 0-200 mm where both truths end a swing),
/// the RMS change, the RMS change left after each participant's mean change (what a
/// participant's own time scale can roughly absorb), and the RMS noise of a row's mean.
struct SweepEffectSize {
  int rows = 0;
  double rawRmsS = 0, shapeRmsS = 0, rowNoiseS = 0;
};

inline SweepEffectSize calcSweepEffectSize(const SweepHidden& h) {
  const std::vector<double> grid = {0.0, 0.05, 0.10, 0.15, 0.20};
  double raw2 = 0, shape2 = 0, noise2 = 0;
  SweepEffectSize out;
  for (auto base : independent::burkettParticipants()) {
    base.timeScale *= kSweepTruthTempo;
    base.trials = kSweepTrials;
    SweepTruth truth;
    if (h.hide) h.hide(truth);
    independent::SweepParticipant hidden = base;
    if (truth.participant) truth.participant(hidden);
    const independent::SweepModel files;
    const independent::SweepEffects none;
    std::vector<double> change;
    for (double d : grid) {
      const auto a = independent::simulateSweepSwing(base, files, none, d);
      const auto b = independent::simulateSweepSwing(hidden, truth.model, truth.effects, d);
      if (!a.ended || !b.ended) continue;
      change.push_back(b.swingTime - a.swingTime);
      noise2 += base.trialSdS * base.trialSdS / base.trials;
    }
    double mean = 0;
    for (double v : change) mean += v / static_cast<double>(change.size());
    for (double v : change) {
      raw2 += v * v;
      shape2 += (v - mean) * (v - mean);
      ++out.rows;
    }
  }
  if (out.rows == 0) return out;
  out.rawRmsS = std::sqrt(raw2 / out.rows);
  out.shapeRmsS = std::sqrt(shape2 / out.rows);
  out.rowNoiseS = std::sqrt(noise2 / out.rows);
  return out;
}

}  // namespace swingsim::calibration
