#pragma once
// An independent generator of knee-axis sweep tables for tests: swing time per participant
// and knee-axis lowering, as Burkett 2004 Table 4 reports it, made by a swing model that
// shares no code with src/ (the Kane equations of swing_generator.h, its own fixed-step RK4,
// its own knee, hip and swing-end laws), written from the papers (/work/shared/papers.md)
// and what the docs say swingsim does (docs/assumptions.md, docs/uncertainty.md,
// docs/swing-options.md, docs/formats.md). Hidden sweep-level effects (0 or NaN = off) make
// tables that the files it writes do not explain.
//
// What each part means, and where that meaning comes from:
// - Lowering by d (Burkett 2004, Methods; docs/assumptions.md "COM rule"): the thigh is
//   longer by d, the shank shorter by d, the foot unchanged, inertias about the COMs
//   unchanged. fixed_from_proximal keeps the thigh COM's distance from the hip and the shank
//   COM's distance from the knee; proportional keeps each COM's fraction of its length.
//   Refused when less than 0.10 m of shank would remain or the shank COM would leave it.
// - Hip moment (docs/assumptions.md "Hip moment"): biphasic sine, flexion half-sine then
//   extension half-sine, then nothing; time scale tau: M(t) = base(t / tau) / tau^2.
// - Knee (docs/assumptions.md, docs/formats.md): a constant damping table, moment
//   table x speed / reference speed against the knee's rate (speed_rule linear,
//   extension_factor 1); friction Tc below 4 deg, -Tc tanh(rate / 1 rad/s) x gate(angle),
//   gate = (1 - tanh((angle - 4 deg) / 0.5 deg)) / 2; the hyperextension stop at full
//   extension, M = k p^1.5 into the stop and e^2 k p^1.5 out of it, blended by
//   tanh(p' / 0.05 rad/s) (p the penetration).
// - Swing end (docs/assumptions.md "Swing-end rule", docs/swing-options.md "The settle
//   dwell"): the thigh has reached its target flexion AND the knee, after its peak, is back
//   inside the zone of stability, in whichever order; the swing time is the later of the
//   two, confirmed when the knee then stays inside the zone for the settle dwell. A knee
//   that leaves the zone first (a bounce) ends its swing at its next entry.
// - Hip range: the docs say only "smooth stop outside" -30..90 deg; ours is a stiff spring
//   and damper outside the range (an assumption); SweepSwing says whether it ever acted.
// - Gravity 9.81 m/s^2, swingsim's (docs/export-osim.md).
// - Rows (docs: issue 26's table): the CSV's sd_s is the trial-to-trial SD (Burkett Table 3)
//   and n the trials averaged; a row's noise is sd_s / sqrt(n).
// Agreement with swingsim's own sweep: tests/independent/sweep_table_generator_test.cpp.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "swing_generator.h"

namespace independent {

enum class ComRule { kFixedFromProximal, kProportional };

inline const char* comRuleKey(ComRule rule) {
  return rule == ComRule::kFixedFromProximal ? "fixed_from_proximal" : "proportional";
}

/// One leg at the standard knee-axis location (Burkett Table 2 meaning: COM measured from
/// the distal end; the foot's from the toe).
struct Leg {
  Segment thigh, shank, foot;
};

/// One runner of a sweep: who, his leg, his knee friction, his hip time scale and the
/// trial-to-trial SD of his measured swing time.
struct SweepParticipant {
  std::string name;
  double heightM = 1.8, bodyMassKg = 75;
  Leg leg;
  double kneeFrictionNm = 0;  ///< Tc, Burkett Table 2
  double timeScale = 1;       ///< tau of the hip moment profile
  double trialSdS = 0.03;     ///< s, trial-to-trial SD (Burkett Table 3)
  int trials = 5;             ///< trials averaged per row (Burkett: 5)
};

/// Burkett, Smeathers & Barker 2004 (J Appl Biomech 20:25-37): Table 1 (height, body mass),
/// Table 2 (segments, Tc; P4's "L5" read as 15 N m as docs/assumptions.md does) and Table 3
/// (trial-to-trial SD of the measured swing time, 5 trials). The time scales are the ones
/// participants/p1..p4.yaml store (any truth would do: they are inputs here).
inline std::vector<SweepParticipant> burkettParticipants() {
  return {
      {"P1",
       1.83,
       70,
       {{0.410, 3.350, 0.284, 0.0264}, {0.515, 0.785, 0.260, 0.0161}, {0.240, 1.030, 0.140, 0.0059}},
       10,
       1.088747,
       0.031,
       5},
      {"P2",
       1.83,
       78,
       {{0.435, 5.612, 0.165, 0.0744}, {0.520, 0.905, 0.255, 0.0039}, {0.245, 0.845, 0.145, 0.0073}},
       9,
       1.379699,
       0.047,
       5},
      {"P3",
       1.85,
       76,
       {{0.440, 4.137, 0.335, 0.0241}, {0.540, 0.558, 0.280, 0.0033}, {0.240, 1.020, 0.140, 0.0060}},
       5,
       1.112318,
       0.046,
       5},
      {"P4",
       1.90,
       82,
       {{0.450, 7.905, 0.310, 0.0795}, {0.530, 1.061, 0.290, 0.0171}, {0.220, 0.459, 0.170, 0.0030}},
       15,
       1.395026,
       0.033,
       5},
  };
}

/// What the files say, shared by every participant (their YAML keys in brackets).
struct SweepModel {
  /// m/s^2: swingsim's 9.81 (docs/export-osim.md, "swingsim's value"), not the standard
  /// 9.80665 of swing_generator.h: the difference is 0.04-0.05 ms of swing time.
  double gravity = 9.81;
  // Knee model: a constant damping table (damping_table) and the stop (hyperextension_stop).
  double tableMomentNm = 2.0;                     ///< moment_Nm at every flexion_deg sample
  double referenceDegS = 150.0;                   ///< reference_speed_deg_s (Burkett's dynamometer)
  double stopStiffness = 2e4;                     ///< stiffness_Nm_per_rad1p5 (docs/assumptions.md default)
  double stopRestitution = 0.4;                   ///< restitution (docs/assumptions.md default)
  ComRule comRule = ComRule::kFixedFromProximal;  ///< com_rule
  // hip_moment: biphasic_sine before the time scale.
  double flexionNm = 30, flexionS = 0.20, extensionNm = 15, extensionS = 0.20;
  // initial, hip_range, swing_end.
  double hip0Deg = -15, knee0Deg = 10;
  double hipMinDeg = -30, hipMaxDeg = 90;
  double thighTargetDeg = 20, zoneDeg = 6, settleDwellS = 0.15, timeLimitS = 1.5;
};

/// Hidden sweep-level effects: the truth differs from the files by these (0 / NaN / nullopt
/// = off).
struct SweepEffects {
  /// Hale 1990 effort adaptation (docs/uncertainty.md `hip_effort_adaptation`): both hip
  /// amplitudes x (I_k(d) / I_k(0))^a, I_k the shank + foot inertia about the knee.
  double hipEffortExponent = 0;
  /// The hip time scale changing with lowering: tau(d) = tau0 (1 + c d / 0.1 m).
  double timeScaleSlope = 0;
  double stopRestitution = std::numeric_limits<double>::quiet_NaN();  ///< e for every knee (NaN: the files')
  double kneeFrictionNm = std::numeric_limits<double>::quiet_NaN();   ///< Tc for everyone (NaN: Table 2's)
  std::optional<ComRule> comRule;                                     ///< the truth's COM rule (nullopt: the files')
  /// Outside any library: the prosthetist re-tunes the damping at each lowering, table
  /// x (1 + k d / 0.1 m).
  double dampingRetune = 0;
  /// Outside any library: a biarticular strap, moment s (theta - phi - offset) flexing the
  /// hip and extending the knee. N m/rad, rad.
  double strapStiffness = 0, strapOffset = 0;
};

/// Burkett's knee-axis lowering by `d` m under `rule`; throws std::invalid_argument if less
/// than 0.10 m of shank would remain or the shank COM would leave the shank.
inline Leg lowerKneeAxis(const Leg& leg, double d, ComRule rule) {
  Leg out = leg;
  out.thigh.length += d;
  out.shank.length -= d;
  if (rule == ComRule::kFixedFromProximal) {
    out.thigh.comFromDistal += d;  // distance from the hip kept
    out.shank.comFromDistal -= d;  // distance from the knee kept
  } else {
    out.thigh.comFromDistal *= out.thigh.length / leg.thigh.length;
    out.shank.comFromDistal *= out.shank.length / leg.shank.length;
  }
  if (out.shank.length < 0.10 - 1e-12 || out.shank.comFromDistal < 0)
    throw std::invalid_argument("lowering " + std::to_string(d) + " m leaves " + std::to_string(out.shank.length) +
                                " m of shank with its COM " + std::to_string(out.shank.comFromDistal) +
                                " m above the ankle (need >= 0.10 m and >= 0)");
  return out;
}

/// Shank + foot inertia about the knee, kg m^2: both inertias plus m r^2 of each COM, the
/// foot perpendicular to the shank (its COM forward of the ankle by length - comFromDistal).
inline double kneeInertia(const Leg& leg) {
  const double as = leg.shank.length - leg.shank.comFromDistal;
  const double cf = leg.foot.length - leg.foot.comFromDistal;
  return leg.shank.inertia + leg.shank.mass * as * as + leg.foot.inertia +
         leg.foot.mass * (cf * cf + leg.shank.length * leg.shank.length);
}

/// Everything one swing of the truth needs, after the lowering and the hidden effects.
struct SweepSwingLaw {
  Leg leg;
  double hipScale = 1, timeScale = 1;  // amplitude factor, tau
  double flexionNm, flexionS, extensionNm, extensionS;
  double damping;  // N m s/rad
  double frictionNm, stopStiffness, restitution;
  double strapStiffness, strapOffset;
  double hipMin, hipMax;  // rad
  double gravity;         // m/s^2
};

inline SweepSwingLaw makeSweepSwingLaw(const SweepParticipant& p, const SweepModel& model, const SweepEffects& fx,
                                       double lowering) {
  const double deg = kPi / 180.0;
  const ComRule rule = fx.comRule.value_or(model.comRule);
  SweepSwingLaw law;
  law.leg = lowerKneeAxis(p.leg, lowering, rule);
  law.hipScale = std::pow(kneeInertia(law.leg) / kneeInertia(p.leg), fx.hipEffortExponent);
  law.timeScale = p.timeScale * (1 + fx.timeScaleSlope * lowering / 0.1);
  law.flexionNm = model.flexionNm;
  law.flexionS = model.flexionS;
  law.extensionNm = model.extensionNm;
  law.extensionS = model.extensionS;
  law.damping = model.tableMomentNm / (model.referenceDegS * deg) * (1 + fx.dampingRetune * lowering / 0.1);
  law.frictionNm = std::isnan(fx.kneeFrictionNm) ? p.kneeFrictionNm : fx.kneeFrictionNm;
  law.stopStiffness = model.stopStiffness;
  law.restitution = std::isnan(fx.stopRestitution) ? model.stopRestitution : fx.stopRestitution;
  law.strapStiffness = fx.strapStiffness;
  law.strapOffset = fx.strapOffset;
  law.hipMin = model.hipMinDeg * deg;
  law.hipMax = model.hipMaxDeg * deg;
  law.gravity = model.gravity;
  return law;
}

/// Hip moment of the profile at time t, N m (positive flexes): base(t / tau) / tau^2 times
/// the effort factor, base the flexion then extension half-sine.
inline double sweepHipMoment(const SweepSwingLaw& law, double t) {
  const double s = t / law.timeScale;
  double base = 0;
  if (s < law.flexionS)
    base = law.flexionNm * std::sin(kPi * s / law.flexionS);
  else if (s < law.flexionS + law.extensionS)
    base = -law.extensionNm * std::sin(kPi * (s - law.flexionS) / law.extensionS);
  return law.hipScale * base / (law.timeScale * law.timeScale);
}

// Our hip range stop (the docs give no law): a spring and damper outside the range.
constexpr double kHipRangeStiffness = 500.0;  // N m/rad
constexpr double kHipRangeDamping = 5.0;      // N m s/rad

inline double hipRangeMoment(const SweepSwingLaw& law, double phi, double phiDot) {
  if (phi > law.hipMax) return -kHipRangeStiffness * (phi - law.hipMax) - kHipRangeDamping * phiDot;
  if (phi < law.hipMin) return kHipRangeStiffness * (law.hipMin - phi) - kHipRangeDamping * phiDot;
  return 0.0;
}

/// Knee moment, N m (positive flexes): damping, friction near extension, the stop, the strap.
inline double sweepKneeMoment(const SweepSwingLaw& law, double theta, double thetaDot, double phi) {
  const double deg = kPi / 180.0;
  double M = -law.damping * thetaDot;
  const double gate = 0.5 * (1 - std::tanh((theta - 4 * deg) / (0.5 * deg)));
  M -= law.frictionNm * std::tanh(thetaDot / 1.0) * gate;
  if (theta < 0) {
    const double p = -theta, pDot = -thetaDot, e2 = law.restitution * law.restitution;
    M += law.stopStiffness * std::pow(p, 1.5) * (0.5 * (1 + e2) + 0.5 * (1 - e2) * std::tanh(pDot / 0.05));
  }
  M -= law.strapStiffness * (theta - phi - law.strapOffset);
  return M;
}

inline void sweepDerivatives(const SweepSwingLaw& law, double t, const double* y, double* dy) {
  const double theta = y[0] - y[1], thetaDot = y[2] - y[3];
  const double Mk = sweepKneeMoment(law, theta, thetaDot, y[0]);
  const double Mh =
      sweepHipMoment(law, t) + hipRangeMoment(law, y[0], y[2]) + law.strapStiffness * (theta - y[0] - law.strapOffset);
  dy[0] = y[2];
  dy[1] = y[3];
  chainAccelerations(law.leg.thigh, law.leg.shank, law.leg.foot, y, Mh, Mk, dy + 2, law.gravity);
}

/// One swing's outcome.
struct SweepSwing {
  bool ended = false;
  double swingTime = std::numeric_limits<double>::quiet_NaN();  ///< s (NaN: no end in the time limit)
  double peakKneeDeg = 0;
  int bounces = 0;        ///< times the knee left the zone after entering it
  double minKneeDeg = 0;  ///< deepest knee angle (negative: into the stop)
  double minHipDeg = 0, maxHipDeg = 0;
  bool hipRangeActed = false;  ///< the hip left its range (our stop law then matters)
  double thighTargetTime = std::numeric_limits<double>::quiet_NaN();  ///< s, thigh first at its target
  double kneeEntryTime = std::numeric_limits<double>::quiet_NaN();    ///< s, the knee's last entry into the zone
};

constexpr double kSweepStep = 1e-4;  ///< s, RK4 step (swing time converged to < 0.5 ms: the test)

/// One swing of participant `p` at lowering `d` m with the hidden effects, by RK4 at `step` s.
inline SweepSwing simulateSweepSwing(const SweepParticipant& p, const SweepModel& model, const SweepEffects& fx,
                                     double d, double step = kSweepStep) {
  const double deg = kPi / 180.0;
  const SweepSwingLaw law = makeSweepSwingLaw(p, model, fx, d);
  const double target = model.thighTargetDeg * deg, zone = model.zoneDeg * deg;
  double y[4] = {model.hip0Deg * deg, (model.hip0Deg - model.knee0Deg) * deg, 0.0, 0.0};
  SweepSwing out;
  double peak = model.knee0Deg * deg, minKnee = peak, minHip = y[0], maxHip = y[0];
  double thighTime = std::numeric_limits<double>::quiet_NaN(), entry = thighTime;
  bool inZone = false;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const long steps = std::lround((model.timeLimitS + model.settleDwellS) / step) + 1;
  for (long i = 0; i < steps; ++i) {
    const double t = i * step;
    const double hipPrev = y[0], kneePrev = y[0] - y[1];
    double k1[4], k2[4], k3[4], k4[4], tmp[4];
    sweepDerivatives(law, t, y, k1);
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + step / 2 * k1[j];
    sweepDerivatives(law, t + step / 2, tmp, k2);
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + step / 2 * k2[j];
    sweepDerivatives(law, t + step / 2, tmp, k3);
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + step * k3[j];
    sweepDerivatives(law, t + step, tmp, k4);
    for (int j = 0; j < 4; ++j) y[j] += step / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    const double tn = t + step, hip = y[0], knee = y[0] - y[1];
    auto crossing = [&](double a, double b, double level) { return t + step * (level - a) / (b - a); };
    peak = std::max(peak, knee);
    minKnee = std::min(minKnee, knee);
    minHip = std::min(minHip, hip);
    maxHip = std::max(maxHip, hip);
    if (std::isnan(thighTime) && hipPrev < target && hip >= target) thighTime = crossing(hipPrev, hip, target);
    const bool afterPeak = peak > model.knee0Deg * deg && peak > zone;
    if (!inZone && afterPeak && kneePrev >= zone && knee < zone) {
      inZone = true;
      entry = crossing(kneePrev, knee, zone);
    } else if (inZone && knee >= zone) {
      inZone = false;
      entry = nan;
      ++out.bounces;
    }
    if (inZone && !std::isnan(thighTime)) {
      const double end = std::max(entry, thighTime);
      if (end > model.timeLimitS) break;
      if (tn >= end + model.settleDwellS) {
        out.ended = true;
        out.swingTime = end;
        out.kneeEntryTime = entry;
        break;
      }
    }
  }
  out.peakKneeDeg = peak / deg;
  out.minKneeDeg = minKnee / deg;
  out.minHipDeg = minHip / deg;
  out.maxHipDeg = maxHip / deg;
  out.hipRangeActed = minHip < law.hipMin || maxHip > law.hipMax;
  out.thighTargetTime = thighTime;
  return out;
}

/// One row of a sweep table: the mean of `trials` swings with trial-to-trial SD `sdS`.
struct SweepRow {
  std::string participant;
  double loweringM = 0, swingTimeS = 0, sdS = 0;
  int trials = 5;
};

/// Burkett 2004 Table 4's lowerings (m) of P1..P4, in the order of burkettParticipants().
inline std::vector<std::vector<double>> burkettTable4Lowerings() {
  return {
      {0.0, 0.050, 0.100, 0.150}, {0.0, 0.080, 0.125, 0.180}, {0.0, 0.140, 0.200, 0.240}, {0.0, 0.090, 0.130, 0.175}};
}

/// The sweep table of `participants`, participant i at `lowerings[i]` (m), with the hidden
/// effects `fx`. Each row's time is the truth's swing time plus Gaussian noise of SD
/// noiseScale x trialSdS / sqrt(trials) (the SD of a mean of `trials` trials; noiseScale 0:
/// no noise), drawn from std::mt19937_64(seed) in row order. Throws std::runtime_error
/// naming the participant and lowering if a swing does not end, std::invalid_argument if a
/// lowering leaves too little shank or the lists do not match.
inline std::vector<SweepRow> generateSweepTableByParticipant(const std::vector<SweepParticipant>& participants,
                                                             const std::vector<std::vector<double>>& lowerings,
                                                             const SweepModel& model, const SweepEffects& fx,
                                                             std::uint64_t seed, double noiseScale = 1.0,
                                                             double step = kSweepStep) {
  if (lowerings.size() != participants.size())
    throw std::invalid_argument("independent sweep: " + std::to_string(lowerings.size()) + " lowering lists for " +
                                std::to_string(participants.size()) + " participants");
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<SweepRow> rows;
  for (std::size_t i = 0; i < participants.size(); ++i) {
    const auto& p = participants[i];
    for (double d : lowerings[i]) {
      const SweepSwing s = simulateSweepSwing(p, model, fx, d, step);
      if (!s.ended)
        throw std::runtime_error("independent sweep: " + p.name + " at lowering " + std::to_string(d) +
                                 " m: no swing end within " + std::to_string(model.timeLimitS) + " s");
      const double sdMean = p.trialSdS / std::sqrt(static_cast<double>(p.trials));
      rows.push_back({p.name, d, s.swingTime + noiseScale * sdMean * normal(engine), p.trialSdS, p.trials});
    }
  }
  return rows;
}

/// As above, every participant at the same `lowerings` (m).
inline std::vector<SweepRow> generateSweepTable(const std::vector<SweepParticipant>& participants,
                                                const std::vector<double>& lowerings, const SweepModel& model,
                                                const SweepEffects& fx, std::uint64_t seed, double noiseScale = 1.0,
                                                double step = kSweepStep) {
  return generateSweepTableByParticipant(participants, std::vector<std::vector<double>>(participants.size(), lowerings),
                                         model, fx, seed, noiseScale, step);
}

/// The measured-table CSV a user writes: participant,lowering_m,swing_time_s,sd_s,n
/// (sd_s the trial-to-trial SD, n the trials averaged).
inline void writeSweepCsv(const std::vector<SweepRow>& rows, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  f << "participant,lowering_m,swing_time_s,sd_s,n\n";
  for (const auto& r : rows)
    f << r.participant << "," << r.loweringM << "," << r.swingTimeS << "," << r.sdS << "," << r.trials << "\n";
}

/// The file name writeSweepModelFiles gives a participant: his name in lower case + ".yaml".
inline std::string sweepParticipantFile(const SweepParticipant& p) {
  std::string s = p.name;
  for (auto& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s + ".yaml";
}

/// The files a user has (what `model` says; the hidden effects are in none of them): the
/// knee model `knee.yaml` and one participant YAML per participant (sweepParticipantFile),
/// into `dir`. Returns the participant files' paths.
inline std::vector<std::string> writeSweepModelFiles(const std::vector<SweepParticipant>& participants,
                                                     const SweepModel& model, const std::string& dir) {
  {
    std::ofstream knee(dir + "/knee.yaml");
    if (!knee) throw std::runtime_error("cannot write " + dir + "/knee.yaml");
    knee.precision(10);
    const double m = model.tableMomentNm;
    knee << "kind: damping_table\nname: constant-damping\nsource: independent sweep generator\n"
         << "damping_table:\n  reference_speed_deg_s: " << model.referenceDegS << "\n  speed_rule: linear\n"
         << "  extension_factor: 1.0\n  flexion_deg: [0, 35, 70]\n  moment_Nm: [" << m << ", " << m << ", " << m
         << "]\n"
         << "hyperextension_stop: {engage_flexion_deg: 0, stiffness_Nm_per_rad1p5: " << model.stopStiffness
         << ", restitution: " << model.stopRestitution << "}\n";
  }
  std::vector<std::string> paths;
  for (const auto& q : participants) {
    paths.push_back(dir + "/" + sweepParticipantFile(q));
    std::ofstream p(paths.back());
    if (!p) throw std::runtime_error("cannot write " + paths.back());
    p.precision(10);
    auto seg = [&](const char* name, const Segment& s) {
      p << "  " << name << ": {length_m: " << s.length << ", mass_kg: " << s.mass
        << ", com_from_distal_m: " << s.comFromDistal << ", inertia_kgm2: " << s.inertia << "}\n";
    };
    p << "name: " << q.name
      << "\nsource: independent sweep generator (Burkett 2004 Tables 1-2)\nheight_m: " << q.heightM
      << "\nbody_mass_kg: " << q.bodyMassKg << "\nsegments:\n";
    seg("thigh", q.leg.thigh);
    seg("shank", q.leg.shank);
    seg("foot", q.leg.foot);
    p << "knee_friction_Nm: " << q.kneeFrictionNm << "\nknee_model: knee.yaml\ncom_rule: " << comRuleKey(model.comRule)
      << "\nfoot_com_from: toe\n"
      << "initial: {hip_flexion_deg: " << model.hip0Deg << ", knee_flexion_deg: " << model.knee0Deg
      << ", hip_flexion_rate_deg_s: 0, knee_flexion_rate_deg_s: 0}\n"
      << "hip_range: {min_flexion_deg: " << model.hipMinDeg << ", max_flexion_deg: " << model.hipMaxDeg << "}\n"
      << "swing_end: {thigh_target_flexion_deg: " << model.thighTargetDeg
      << ", zone_of_stability_deg: " << model.zoneDeg << ", time_limit_s: " << model.timeLimitS
      << ", settle_dwell_s: " << model.settleDwellS << "}\n"
      << "toe_clearance: {gait: running}\n"
      << "hip_moment: {profile: biphasic_sine, flexion_amplitude_Nm: " << model.flexionNm
      << ", flexion_duration_s: " << model.flexionS << ", extension_amplitude_Nm: " << model.extensionNm
      << ", extension_duration_s: " << model.extensionS << ", time_scale: " << q.timeScale << "}\n";
  }
  return paths;
}

}  // namespace independent
