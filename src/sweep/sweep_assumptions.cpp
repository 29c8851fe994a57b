#include "sweep/sweep_assumptions.h"

#include <algorithm>
#include <cmath>

#include "core/units.h"
#include "sweep/burkett_published.h"
#include "swing/knee_setup.h"

namespace swingsim {

namespace {

// Half-widths and bounds of the ranges; docs/uncertainty.md gives the reasoning per row.
constexpr double kDefaultTimeScaleSpread = 0.10;                          // x tau, a participant without Table 3 data
constexpr double kExtensionRatioLow = 0.25, kExtensionRatioHigh = 1.0;    // extension / flexion amplitude
constexpr double kDurationLow = 0.15, kDurationHigh = 0.25;               // s, each half-sine, before tau
constexpr double kThighTargetLowDeg = 15, kThighTargetHighDeg = 25;       // deg
constexpr double kFrictionLow = 5, kFrictionHigh = 15;                    // N m, the span of Burkett Table 2
constexpr double kStopStiffnessLow = 1.25e4, kStopStiffnessHigh = 5.0e4;  // N m/rad^1.5 (knee/joint_stop.h)
// docs/assumptions.md, "Sources for the values no paper gives":
constexpr double kRestitutionLow = 0.3, kRestitutionHigh = 0.5;
constexpr double kSettleDwellLow = 0.10, kSettleDwellHigh = 0.20;  // s (model/leg_parameters.h)
constexpr double kAccuracyLow = 3e-6, kAccuracyHigh = 2e-5;

// A range that always contains the nominal value (a file outside the documented span
// widens it rather than being moved).
AssumptionRange around(double nominal, double low, double high) {
  return {nominal, std::min(low, nominal), std::max(high, nominal), true};
}

bool isSineProfile(const SweepVariant& v) {
  return v.participant.hipMoment.kind == HipMomentProfile::Kind::kBiphasicSine;
}

AssumptionRange onlyForSine(const SweepVariant& v, double nominal, double low, double high) {
  if (!isSineProfile(v)) return {nominal, nominal, nominal, false};
  return around(nominal, low, high);
}

// The COM rule, the hip-moment time scale and its extension / flexion ratio.
void addChoiceAndTimeScale(std::vector<SweepAssumption>& table) {
  {
    SweepAssumption a;
    a.key = "com_rule";
    a.name = "COM rule";
    a.unit = "choice";
    a.discrete = true;
    a.choices = {"fixed_from_proximal", "proportional"};
    a.source = "Burkett 2004's sentence on COMs allows both readings (docs/assumptions.md, \"COM rule\"); 50/50";
    a.read = [](const SweepVariant& v) { return v.participant.comRule == ComRule::kProportional ? 1.0 : 0.0; };
    a.calcRange = [read = a.read](const SweepVariant& v) { return AssumptionRange{read(v), 0.0, 1.0, true}; };
    a.apply = [](SweepVariant& v, double x) {
      v.participant.comRule = x >= 0.5 ? ComRule::kProportional : ComRule::kFixedFromProximal;
    };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "hip_time_scale";
    a.name = "hip-moment time scale";
    a.unit = "1";
    a.source =
        "calibrated tau x (1 +- SD/T), SD the trial-to-trial SD of the measured standard-location swing time "
        "and T Table 3's model time (Burkett 2004 Table 3; swing time ~ proportional to tau); +-10 % without "
        "Table 3 data. Not recalibrated per sample";
    a.read = [](const SweepVariant& v) { return v.participant.hipMoment.timeScale; };
    a.calcRange = [](const SweepVariant& v) {
      const double tau = v.participant.hipMoment.timeScale;
      double spread = kDefaultTimeScaleSpread;
      if (const PublishedParticipant* pub = findPublished(v.participant.name))
        spread = pub->table3MeasuredSd / pub->table3Model;
      return around(tau, tau * (1 - spread), tau * (1 + spread));
    };
    a.apply = [](SweepVariant& v, double x) { v.participant.hipMoment.timeScale = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "hip_extension_ratio";
    a.name = "hip extension / flexion amplitude";
    a.unit = "1";
    a.source =
        "not published (Burkett measured it per participant); 0.25-1: from a weak terminal-swing brake to one "
        "as strong as the flexion drive (terminal-swing hip torques rise most with running speed: "
        "Schache 2011, Dorn 2012)";
    a.read = [](const SweepVariant& v) {
      const auto& h = v.participant.hipMoment;
      return h.flexionAmplitude > 0 ? h.extensionAmplitude / h.flexionAmplitude : 0.0;
    };
    a.calcRange = [read = a.read](const SweepVariant& v) {
      return onlyForSine(v, read(v), kExtensionRatioLow, kExtensionRatioHigh);
    };
    a.apply = [](SweepVariant& v, double x) {
      auto& h = v.participant.hipMoment;
      h.extensionAmplitude = x * h.flexionAmplitude;
    };
    table.push_back(a);
  }
}

// The hip moment's half-sine durations and its adaptation to the shank's inertia.
void addHipShape(std::vector<SweepAssumption>& table) {
  {
    SweepAssumption a;
    a.key = "hip_flexion_duration";
    a.name = "hip flexion half-sine duration";
    a.unit = "s";
    a.source =
        "not published; 0.20 s +- 25 % (a stated assumption: the dynamometer's flexion half-cycle at "
        "150 deg/s over 30-40 deg of hip motion)";
    a.read = [](const SweepVariant& v) { return v.participant.hipMoment.flexionDuration; };
    a.calcRange = [read = a.read](const SweepVariant& v) {
      return onlyForSine(v, read(v), kDurationLow, kDurationHigh);
    };
    a.apply = [](SweepVariant& v, double x) { v.participant.hipMoment.flexionDuration = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "hip_extension_duration";
    a.name = "hip extension half-sine duration";
    a.unit = "s";
    a.source = "not published; 0.20 s +- 25 % (a stated assumption, as the flexion duration)";
    a.read = [](const SweepVariant& v) { return v.participant.hipMoment.extensionDuration; };
    a.calcRange = [read = a.read](const SweepVariant& v) {
      return onlyForSine(v, read(v), kDurationLow, kDurationHigh);
    };
    a.apply = [](SweepVariant& v, double x) { v.participant.hipMoment.extensionDuration = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "hip_effort_adaptation";
    a.name = "hip effort adaptation exponent";
    a.unit = "1";
    a.source =
        "Hale 1990: amputees raised hip effort 37-71 % when the shank got heavier, keeping swing time; hip "
        "moment x (I_knee(d) / I_knee(0))^a, a = 0 (replayed unchanged, the files) to 1 (moment in "
        "proportion to the shank + foot inertia about the knee)";
    a.read = [](const SweepVariant& v) { return v.hipEffortExponent; };
    a.calcRange = [](const SweepVariant& v) { return around(v.hipEffortExponent, 0.0, 1.0); };
    a.apply = [](SweepVariant& v, double x) { v.hipEffortExponent = x; };
    table.push_back(a);
  }
}

// The swing-end rule's thigh target and settle dwell, and the knee friction.
void addSwingEndAndFriction(std::vector<SweepAssumption>& table) {
  {
    SweepAssumption a;
    a.key = "thigh_target_flexion";
    a.name = "swing-end thigh target flexion";
    a.unit = "deg";
    a.source =
        "Burkett's \"defined position of flexion\" is not given; 15-25 deg around our 20 deg (25 deg was "
        "tried and left P2 without a swing end from 0.10 m: docs/assumptions.md, \"Swing-end rule\")";
    a.read = [](const SweepVariant& v) { return v.participant.swingEnd.thighTargetFlexion * kRadToDeg; };
    a.calcRange = [read = a.read](const SweepVariant& v) {
      return around(read(v), kThighTargetLowDeg, kThighTargetHighDeg);
    };
    a.apply = [](SweepVariant& v, double x) { v.participant.swingEnd.thighTargetFlexion = x * kDegToRad; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "knee_friction";
    a.name = "knee friction Tc";
    a.unit = "N m";
    a.source =
        "Burkett 2004 Table 2 gives 5-10 N m for P1-P3 and \"L5\" (read 15) for P4: the span 5-15 N m for "
        "everyone, the reading of P4 included";
    a.read = [](const SweepVariant& v) { return v.participant.kneeFriction; };
    a.calcRange = [read = a.read](const SweepVariant& v) { return around(read(v), kFrictionLow, kFrictionHigh); };
    a.apply = [](SweepVariant& v, double x) { v.participant.kneeFriction = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "settle_dwell";
    a.name = "swing-end settle dwell";
    a.unit = "s";
    a.source =
        "no source defines it (a stated assumption): longer than a rebound off the stop and back out of the "
        "zone takes (about 0.1 s at 2-3 rad/s), 0.10-0.20 s (SwingEndRule::settleDwell)";
    a.read = [](const SweepVariant& v) { return v.participant.swingEnd.settleDwell; };
    a.calcRange = [read = a.read](const SweepVariant& v) { return around(read(v), kSettleDwellLow, kSettleDwellHigh); };
    a.apply = [](SweepVariant& v, double x) { v.participant.swingEnd.settleDwell = x; };
    table.push_back(a);
  }
}

// The hyperextension stop's stiffness and restitution, and the integrator accuracy.
void addStopAndIntegrator(std::vector<SweepAssumption>& table) {
  {
    SweepAssumption a;
    a.key = "stop_stiffness";
    a.name = "hyperextension-stop stiffness";
    a.unit = "N m/rad^1.5";
    a.source =
        "no published bumper stiffness (docs/assumptions.md); 1.25e4 keeps a 0.2 kg m^2 shank hitting at 8 rad/s "
        "within Burkett's 4 deg (p = (1.25 I v^2 / k)^0.4), 5e4 is 2.5 times the file's value "
        "(JointStopParams::stiffness)";
    a.read = [](const SweepVariant& v) { return v.knee.spec.stop.stiffness; };
    a.calcRange = [read = a.read](const SweepVariant& v) {
      return around(read(v), kStopStiffnessLow, kStopStiffnessHigh);
    };
    a.apply = [](SweepVariant& v, double x) { v.knee.spec.stop.stiffness = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "stop_restitution";
    a.name = "hyperextension-stop restitution e";
    a.unit = "1";
    a.source =
        "no published bumper restitution; docs/assumptions.md prior 0.3-0.5 at swing impact speeds (linear "
        "spring-dampers with damping ratio 0.2-0.3, osim-rl's knee limit, Hunt-Crossley at c v = 1-2)";
    a.read = [](const SweepVariant& v) { return v.knee.spec.stop.restitution; };
    a.calcRange = [read = a.read](const SweepVariant& v) { return around(read(v), kRestitutionLow, kRestitutionHigh); };
    a.apply = [](SweepVariant& v, double x) { v.knee.spec.stop.restitution = x; };
    table.push_back(a);
  }
  {
    SweepAssumption a;
    a.key = "integrator_accuracy";
    a.name = "integrator accuracy";
    a.unit = "1";
    a.logUniform = true;
    a.source =
        "docs/speed.md, \"Convergence study\": swing times converged to 0.1 ms from 2e-5 down; 3e-6 to "
        "2e-5, drawn uniformly in log(accuracy)";
    a.read = [](const SweepVariant& v) { return v.swing.accuracy; };
    a.calcRange = [read = a.read](const SweepVariant& v) { return around(read(v), kAccuracyLow, kAccuracyHigh); };
    a.apply = [](SweepVariant& v, double x) { v.swing.accuracy = x; };
    table.push_back(a);
  }
}

// The table in its fixed order (the order of the Monte Carlo draws: never reorder).
std::vector<SweepAssumption> makeAssumptions() {
  std::vector<SweepAssumption> table;
  addChoiceAndTimeScale(table);
  addHipShape(table);
  addSwingEndAndFriction(table);
  addStopAndIntegrator(table);
  return table;
}

}  // namespace

const std::vector<SweepAssumption>& sweepAssumptions() {
  static const std::vector<SweepAssumption> table = makeAssumptions();
  return table;
}

double calcAssumptionValue(const SweepAssumption& assumption, const AssumptionRange& range, double u) {
  if (!range.applicable) return range.nominal;
  if (assumption.discrete) return u < 0.5 ? range.low : range.high;
  if (assumption.logUniform && range.low > 0) {
    // exp(log(low)) may round just outside the range.
    const double v = std::exp(std::log(range.low) + u * (std::log(range.high) - std::log(range.low)));
    return std::clamp(v, range.low, range.high);
  }
  return range.low + u * (range.high - range.low);
}

std::vector<AssumptionRange> calcAssumptionRanges(const SweepVariant& variant) {
  std::vector<AssumptionRange> ranges;
  for (const SweepAssumption& a : sweepAssumptions()) ranges.push_back(a.calcRange(variant));
  return ranges;
}

void applyAssumptionDraw(SweepVariant& variant, const std::vector<AssumptionRange>& ranges,
                         const std::vector<double>& u) {
  const auto& table = sweepAssumptions();
  for (std::size_t k = 0; k < table.size(); ++k)
    table[k].apply(variant, calcAssumptionValue(table[k], ranges[k], u[k]));
}

KneeLawSum makeSweepVariantKnee(const SweepVariant& variant) {
  KneeModel model = variant.knee;
  model.law = makeKneeModelLaw(model.spec);
  return makeKneeLaw(variant.participant, model);
}

double calcBelowKneeInertia(const Participant& participant, double lowering) {
  const LegGeometry g = calcLegGeometry(participant, lowering);
  const double shank = g.shankInertia + g.shankMass * g.shankCom * g.shankCom;
  const double footCom2 = g.shankLength * g.shankLength + g.footComForward * g.footComForward;
  return shank + g.footInertia + g.footMass * footCom2;
}

Participant calcAdaptedParticipant(const Participant& participant, double lowering, double exponent) {
  Participant p = participant;
  if (exponent == 0 || lowering == 0) return p;
  const double gain =
      std::pow(calcBelowKneeInertia(participant, lowering) / calcBelowKneeInertia(participant, 0), exponent);
  auto& h = p.hipMoment;
  h.flexionAmplitude *= gain;
  h.extensionAmplitude *= gain;
  for (double& m : h.moments) m *= gain;
  return p;
}

}  // namespace swingsim
