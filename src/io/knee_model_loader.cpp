#include "io/knee_model_loader.h"

#include <set>
#include <stdexcept>
#include <utility>
#include <variant>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/plausible_ranges.h"
#include "io/yaml_archive.h"

namespace swingsim {

// ---- The knee model file format, described once -------------------------------------------

namespace {

std::string mustBeDialSetting(double v) {
  return (v == 0 || v == 90 || v == 180) ? "" : "must be a dial setting: 0, 90 or 180";
}

// Contexts that pick which fields of a struct a map holds.
struct SwitchesOf {};
struct CoulombOf {};
struct OrificeOf {};
struct InertiaOf {};
struct PositionDampingOf {};
struct KneeCoulombOf {};
struct ViscousOf {};
struct AssistOf {};
// Reading a dial setting's coefficient rows: the model's phase count and the phases seen.
struct RowContext {
  int phases;
  std::vector<bool>* seen;
};
// Reading the list of dial settings: the model's phase count and the settings seen.
struct SettingContext {
  int phases;
  std::set<std::pair<double, double>>* seen;  // a set: linear-time check of long lists
};

// Ranges of an impedance state machine's numbers (wide: they catch unit slips, not designs).
constexpr PlausibleRange kKneeStiffnessRange{0, 1e4, "N m/rad", "the Open Source Leg's stiffest state has 99 N m/rad"};
constexpr PlausibleRange kKneeDampingRange{0, 1e3, "N m s/rad", "the Open Source Leg's states have 0.06-3.8 N m s/rad"};
constexpr PlausibleRange kKneeAngleRangeDeg{-30, 180, "deg", "the shank cannot fold through the thigh"};
constexpr PlausibleRange kKneeRateRangeDegS = kJointRateRange;
constexpr PlausibleRange kTorqueLimitRange{0, 2000, "N m", "a knee actuator's peak is some 100 N m"};
constexpr double kMaxLatchTime = 0.01;     // s: a tenth of a swing's 0.1 s time scales
constexpr double kMaxMinTimeInState = 10;  // s: the longest swing a participant file allows

// Reading the states of an impedance state machine: the names seen, and where the previous
// state's transition named the state it goes to (checked when the next state is read).
struct StateListContext {
  std::set<std::string> names;
  bool havePrevious = false;
  bool previousHasTransition = false;
  std::string previousTo, previousWhere;
};

}  // namespace

template <class A>
void serialize(A& a, DampingTableParams& p) {
  a.optionalAngle("reference_speed_deg_s", p.referenceRate, mustBePositive);
  a.choice("speed_rule", p.speedRule,
           {{"linear", DampingSpeedRule::kLinear}, {"constant", DampingSpeedRule::kConstant}}, true);
  a.optionalNumber("extension_factor", p.extensionFactor, mustBeNonNegative);
  a.optionalAngle("smoothing_speed_deg_s", p.smoothingRate, mustBePositive);
  a.angles("flexion_deg", p.flexion);
  a.numbers("moment_Nm", p.moment);
  a.require(p.flexion.size() >= 2, "flexion_deg", "expected at least 2 angles",
            [&] { return std::to_string(p.flexion.size()); });
  a.require(p.moment.size() == p.flexion.size(), "moment_Nm",
            "expected one moment per angle in flexion_deg (" + std::to_string(p.flexion.size()) + ")",
            [&] { return std::to_string(p.moment.size()) + " values"; });
  for (std::size_t i = 0; i < p.flexion.size(); ++i) {
    if (i > 0)
      a.require(p.flexion[i] > p.flexion[i - 1], "flexion_deg", "angles must strictly increase",
                [&] { return formatDegrees(p.flexion[i]) + " after " + formatDegrees(p.flexion[i - 1]); });
    a.require(p.moment[i] >= 0, "moment_Nm", "resisting moments must not be negative",
              [&] { return formatNumber(p.moment[i]); });
  }
}

template <class A>
void serialize(A& a, KneeGeometryParams& g) {
  // The mechanism's links are centimetres long: half a metre is a length in millimetres.
  constexpr double kMaxLinkLength = 0.5;  // m
  const ValueCheck link = [](double v) {
    if (!(v > 0)) return std::string("must be positive");
    return v <= kMaxLinkLength ? std::string()
                               : "expected a link length of at most " + formatNumber(kMaxLinkLength) +
                                     " m (is it in millimetres? the key is in metres)";
  };
  a.optionalNumber("ab_m", g.ab, link);
  a.optionalNumber("ac_m", g.ac, link);
  a.require(g.ab != g.ac, "ac_m", "must differ from ab_m", [&] { return formatNumber(g.ac); });
}

template <class A>
void serialize(A& a, MauchCylinderParams& p, SwitchesOf) {
  a.number("velocity_width_m_per_s", p.switches.velocityWidth, mustBePositive);
  a.number("position_width_m", p.switches.positionWidth, mustBePositive);
  a.number("hyperextension_position_m", p.switches.hyperextensionPosition,
           mustBePlausible(kCylinderPositionRange, "a piston position"));
  a.number("latch_rate_per_s", p.switches.latchRate, mustBePositive);
  a.optionalNumber("initial_latch", p.initialLatch,
                   [](double v) { return v >= 0 && v <= 1 ? "" : "must be in [0, 1]"; });
}

template <class A>
void serialize(A& a, MauchCoefficientRow& r, RowContext context) {
  a.integer("phase", r.phase);
  a.require(r.phase >= 1 && r.phase <= context.phases, "phase",
            "must be a phase number from 1 to " + std::to_string(context.phases),
            [&] { return std::to_string(r.phase); });
  if (A::kReading) {
    std::vector<bool>& seen = *context.seen;
    const auto index = static_cast<std::size_t>(r.phase - 1);
    a.require(!seen[index], "phase", "phase appears twice", [&] { return std::to_string(r.phase); });
    seen[index] = true;
  }
  a.number("f_N", r.coefficients.f, mustBePlausible(kForceRange, "a force"));
  a.number("k_N_per_m", r.coefficients.k, mustBePlausible(kCylinderStiffnessRange, "a stiffness"));
  a.number("c_Ns_per_m", r.coefficients.c, mustBePlausible(kCylinderDampingRange, "a damping"));
}

template <class A>
void serialize(A& a, MauchDialSetting& s, SettingContext context) {
  a.number("flexion_dial_deg", s.flexionDial, mustBeDialSetting);
  a.number("extension_dial_deg", s.extensionDial, mustBeDialSetting);
  if (A::kReading) {
    a.require(context.seen->emplace(s.flexionDial, s.extensionDial).second, "flexion_dial_deg",
              "dial setting appears twice",
              [&] { return "F" + formatNumber(s.flexionDial) + "E" + formatNumber(s.extensionDial); });
  }
  std::vector<bool> seen(static_cast<std::size_t>(context.phases), false);
  a.mapList("coefficients", s.rows, RowContext{context.phases, &seen});
  if (A::kReading)
    for (int i = 0; i < context.phases; ++i)
      a.require(seen[static_cast<std::size_t>(i)], "coefficients",
                "phase " + std::to_string(i + 1) + " is missing; a " + std::to_string(context.phases) +
                    "-phase model needs phases 1 to " + std::to_string(context.phases),
                [&] { return std::to_string(s.rows.size()) + " phases"; });
}

template <class A>
void serialize(A& a, MauchAddedEffects& e, CoulombOf) {
  a.number("force_N", e.coulombForce, [](double v) {
    return v >= 0 ? checkPlausible(v, kForceRange, "a force") : "must not be negative (seal friction opposes motion)";
  });
  a.optionalNumber("width_m_per_s", e.coulombWidth, mustBePositive);
}
template <class A>
void serialize(A& a, MauchAddedEffects& e, OrificeOf) {
  a.number("coefficient_Ns2_per_m2", e.orificeCoefficient);
}
template <class A>
void serialize(A& a, MauchAddedEffects& e, InertiaOf) {
  a.number("mass_kg", e.pistonMass);
}
template <class A>
void serialize(A& a, MauchAddedEffects& e, PositionDampingOf) {
  a.number("coefficient_Ns_per_m2", e.positionDamping);
}
// A user's cylinder force (knee/cylinder_expression.h), as a diagnosis saves an accepted one.
struct CylinderForceOf {};
template <class A>
void serialize(A& a, KneeExpressionParams& x, CylinderForceOf);
template <class A>
void serialize(A& a, MauchPhaseCoefficients& c) {
  a.number("f_N", c.f);
  a.number("k_N_per_m", c.k);
  a.number("c_Ns_per_m", c.c);
}

namespace {

template <class A>
void serializeAddedEffects(A& a, MauchAddedEffects& e, int phases) {
  a.optionalMap("hyperextension_phase", e.hyperextension, e.hyperextensionPhase);
  a.require(!e.hyperextensionPhase || phases == 2 || phases == 0, "hyperextension_phase",
            "only a 2-phase model can add a hyperextension phase (the 4-phase model has one)",
            [&] { return std::to_string(phases) + " phases"; });
  a.optionalMap("coulomb_friction", e, e.coulombFriction, CoulombOf{});
  a.optionalMap("orifice_quadratic", e, e.orificeQuadratic, OrificeOf{});
  a.optionalMap("inertia", e, e.inertia, InertiaOf{});
  a.optionalMap("position_dependent_damping", e, e.positionDependentDamping, PositionDampingOf{});
  bool expressions = !e.expressions.empty();
  if constexpr (A::kReading) expressions = a.has("expressions");
  if (expressions) a.mapList("expressions", e.expressions, CylinderForceOf{});
}

}  // namespace

void serialize(YamlReadArchive& a, MauchAddedEffects& e, int phases) { serializeAddedEffects(a, e, phases); }
void serialize(YamlWriteArchive& a, MauchAddedEffects& e, int phases) { serializeAddedEffects(a, e, phases); }

template <class A>
void serialize(A& a, KneeAddedEffectsParams& p, KneeCoulombOf) {
  a.number("moment_Nm", p.coulombMoment, mustBeNonNegative);
  a.optionalAngle("smoothing_deg_s", p.coulombSmoothingRate, mustBePositive);
}
template <class A>
void serialize(A& a, KneeAddedEffectsParams& p, ViscousOf) {
  a.number("damping_Nm_s_per_rad", p.viscousDamping, mustBeNonNegative);
}
template <class A>
void serialize(A& a, KneeAddedEffectsParams& p, AssistOf) {
  a.number("stiffness_Nm_per_rad", p.assistStiffness, mustBeNonNegative);
}

template <class A>
void serialize(A& a, KneeExpressionParameter& q) {
  a.optionalText("unit", q.unit);
  a.number("value", q.value);
}

// A user's expression under `key`, checked by `check` when read (the parser's message and
// character at the key's line): a knee moment or a cylinder force.
template <class A>
void serializeExpression(A& a, KneeExpressionParams& x, const char* key, void (*check)(const KneeExpressionParams&)) {
  a.text("name", x.name);
  a.text(key, x.expression);
  a.namedMaps("parameters", x.parameters, &KneeExpressionParameter::name);
  if constexpr (A::kReading) {
    std::string problem;
    try {
      check(x);
    } catch (const KneeExpressionError& e) {
      problem = describeKneeExpressionError(x.expression, e);
    }
    a.require(problem.empty(), key, problem, [&] { return x.expression; });
  }
}

template <class A>
void serialize(A& a, KneeExpressionParams& x) {
  serializeExpression(a, x, "knee_moment_Nm", checkKneeExpression);
}

template <class A>
void serialize(A& a, KneeExpressionParams& x, CylinderForceOf) {
  serializeExpression(a, x, "cylinder_force_N", checkCylinderExpression);
}

template <class A>
void serialize(A& a, KneeAddedEffectsParams& p) {
  a.optionalNumber("model_scale", p.modelScale, mustBePositive);
  // The writer writes a law only where it acts; the reader learns from the file.
  bool coulomb = p.coulombMoment != 0, viscous = p.viscousDamping != 0, assist = p.assistStiffness != 0;
  a.optionalMap("coulomb_friction", p, coulomb, KneeCoulombOf{});
  a.optionalMap("viscous_damping", p, viscous, ViscousOf{});
  a.optionalMap("extension_assist_spring", p, assist, AssistOf{});
  // Users' knee moments (knee/knee_expression.h), as a diagnosis saves an accepted one.
  bool expressions = !p.expressions.empty();
  if constexpr (A::kReading) expressions = a.has("expressions");
  if (expressions) a.mapList("expressions", p.expressions);
}

template <class A>
void serialize(A& a, JointStopParams& s) {
  a.optionalAngle("engage_flexion_deg", s.lower, [](double v) {
    return v >= -30 && v <= 30 ? "" : "expected an angle near full extension, -30 to 30 deg";
  });
  a.optionalNumber("stiffness_Nm_per_rad1p5", s.stiffness, mustBePositive);
  a.optionalNumber("restitution", s.restitution, [](double v) {
    return v >= 0 && v <= 1 ? "" : "expected a coefficient of restitution from 0 to 1";
  });
}

template <class A>
void serialize(A& a, ImpedanceTransition& t, StateListContext* context) {
  a.text("to", t.to);
  if constexpr (A::kReading) context->previousWhere = a.yaml().where("to");
  const std::vector<std::pair<std::string, ThresholdSide>> sides = {
      {"any", ThresholdSide::kAny}, {"above", ThresholdSide::kAbove}, {"below", ThresholdSide::kBelow}};
  // A threshold is written only beside its side (read, it is refused without one below).
  a.choice("when_flexion", t.flexionSide, sides, true);
  if (A::kReading || t.flexionSide != ThresholdSide::kAny)
    a.optionalAngle("flexion_deg", t.flexion, mustBePlausible(kKneeAngleRangeDeg, "a knee angle"));
  a.choice("when_rate", t.rateSide, sides, true);
  if (A::kReading || t.rateSide != ThresholdSide::kAny)
    a.optionalAngle("rate_deg_s", t.rate, mustBePlausible(kKneeRateRangeDegS, "a knee speed"));
  a.optionalNumber("min_time_s", t.minTime, [](double v) {
    return v >= 0 && v <= kMaxMinTimeInState
               ? std::string()
               : "expected a time in state from 0 to " + formatNumber(kMaxMinTimeInState) + " s";
  });
  if constexpr (A::kReading) {
    a.require(t.flexionSide == ThresholdSide::kAny || a.has("flexion_deg"), "when_flexion",
              "expected its threshold, flexion_deg, beside it", [] { return std::string("no flexion_deg"); });
    a.require(t.rateSide == ThresholdSide::kAny || a.has("rate_deg_s"), "when_rate",
              "expected its threshold, rate_deg_s, beside it", [] { return std::string("no rate_deg_s"); });
    // A threshold without its side would be ignored: the state would end at once.
    a.require(!a.has("flexion_deg") || t.flexionSide != ThresholdSide::kAny, "flexion_deg",
              "expected its side beside it, when_flexion: above or below",
              [] { return std::string("no side (or when_flexion: any)"); });
    a.require(!a.has("rate_deg_s") || t.rateSide != ThresholdSide::kAny, "rate_deg_s",
              "expected its side beside it, when_rate: above or below",
              [] { return std::string("no side (or when_rate: any)"); });
  }
}

template <class A>
void serialize(A& a, ImpedanceState& s, StateListContext* context) {
  a.text("name", s.name);
  if constexpr (A::kReading) {
    a.require(!s.name.empty(), "name", "expected a state name", [] { return std::string("an empty name"); });
    a.require(context->names.insert(s.name).second, "name", "expected a name no other state has",
              [&] { return s.name; });
    if (context->havePrevious && !context->previousHasTransition)
      throw InputError(context->previousWhere +
                       "expected a transition: every state but the last needs one, to the next state (" + s.name +
                       ") (got none)");
    if (context->havePrevious && context->previousTo != s.name)
      throw InputError(context->previousWhere + "expected the next state in the list, " + s.name + " (got " +
                       context->previousTo + ")");
    context->previousWhere = a.yaml().where("name");
  }
  a.number("stiffness_Nm_per_rad", s.stiffness, mustBePlausible(kKneeStiffnessRange, "a stiffness"));
  a.number("damping_Nm_s_per_rad", s.damping, mustBePlausible(kKneeDampingRange, "a damping"));
  a.angle("equilibrium_deg", s.equilibrium, mustBePlausible(kKneeAngleRangeDeg, "a knee angle"));
  a.optionalMap("transition", s.transition, s.hasTransition, context);
  if constexpr (A::kReading) {
    context->havePrevious = true;
    context->previousHasTransition = s.hasTransition;
    context->previousTo = s.transition.to;
  }
}

template <class A>
void serialize(A& a, ImpedanceStateMachineParams& p) {
  a.choice("mode", p.mode, {{"powered", ImpedanceMode::kPowered}, {"dissipative", ImpedanceMode::kDissipative}});
  a.number("torque_limit_Nm", p.torqueLimit, [](double v) {
    return v > 0 ? checkPlausible(v, kTorqueLimitRange, "a torque limit") : "must be positive";
  });
  a.optionalNumber("latch_time_s", p.latchTime, [](double v) {
    return v > 0 && v <= kMaxLatchTime ? std::string()
                                       : "expected a latch time constant from 0 (exclusive) to " +
                                             formatNumber(kMaxLatchTime) + " s, far below a swing's 0.1 s time scales";
  });
  a.optionalAngle("projection_speed_deg_s", p.projectionRate, mustBePositive);
  StateListContext context;
  a.mapList("states", p.states, &context);
  if constexpr (A::kReading) {
    a.require(!p.states.empty(), "states", "expected at least one state", [] { return std::string("none"); });
    if (p.states.back().hasTransition)
      throw InputError(context.previousWhere +
                       "expected no transition in the last state, which has no state after it (got one to " +
                       p.states.back().transition.to + ")");
  }
}

template <class A>
void serialize(A& a, PneumaticCylinderParams& c) {
  const auto length = [](double v) { return v > 0 && v <= 0.5 ? "" : "expected metres, above 0 and at most 0.5"; };
  a.number("bore_m", c.bore, length);
  a.number("lever_arm_m", c.leverArm, length);
  a.number("chamber_length_m", c.chamberLength, length);
  a.require(c.chamberLength > c.leverArm * PneumaticCylinderParams::kFullFlexion, "chamber_length_m",
            "must exceed the piston's travel to 150 deg of flexion, lever_arm_m x 2.618 = " +
                formatNumber(c.leverArm * PneumaticCylinderParams::kFullFlexion) + " m",
            [&] { return formatNumber(c.chamberLength); });
  const auto valve = [](double v) {
    return v > 0 && v <= 10 ? "" : "expected a valve time from 0 (exclusive) to 10 s";
  };
  a.number("flexion_valve_time_s", c.flexionValveTime, valve);
  a.number("extension_valve_time_s", c.extensionValveTime, valve);
  a.optionalNumber("ambient_pressure_Pa", c.ambientPressure, [](double v) {
    return v >= 5e4 && v <= 1.1e5 ? "" : "expected an ambient pressure from 50000 to 110000 Pa";
  });
}

// Each kind's own keys (the alternatives of KneeKind, model/knee_model.h).
template <class A>
void serializeKind(A& a, DampingTableKnee& k) {
  a.map("damping_table", k.table);
}
template <class A>
void serializeKind(A& a, ImpedanceStateMachineKnee& k) {
  a.map("impedance_state_machine", k.stateMachine);
}
template <class A>
void serializeKind(A& a, PneumaticKnee& k) {
  a.map("pneumatic", k.cylinder);
}
template <class A>
void serializeKind(A& a, MauchKnee& k) {
  MauchCylinderParams& c = k.cylinder;
  a.integer("phases", c.phases);
  a.require(c.phases == 2 || c.phases == 4, "phases", "must be 2 or 4 (Chien 2014 2-phase or 4-phase model)",
            [&] { return std::to_string(c.phases); });
  a.optionalMap("geometry", c.geometry, k.hasGeometry);
  a.map("switches", c, SwitchesOf{});
  a.number("flexion_dial_deg", k.flexionDial, mustBeDialSetting);
  a.number("extension_dial_deg", k.extensionDial, mustBeDialSetting);
  std::set<std::pair<double, double>> seen;
  a.mapList("settings", k.settings, SettingContext{c.phases, &seen});
  if (A::kReading) {
    bool found = false;
    for (const auto& s : k.settings) {
      if (s.flexionDial != k.flexionDial || s.extensionDial != k.extensionDial) continue;
      c.coefficients.assign(static_cast<std::size_t>(c.phases), {});
      for (const auto& r : s.rows) c.coefficients[static_cast<std::size_t>(r.phase - 1)] = r.coefficients;
      found = true;
    }
    a.require(found, "flexion_dial_deg", "no coefficient set in settings for this dial setting",
              [&] { return "F" + formatNumber(k.flexionDial) + "E" + formatNumber(k.extensionDial); });
  }
  a.optionalMap("effects", c.effects, k.hasCylinderEffects, c.phases);
}

// `kind:`'s choices, one per alternative of KneeKind, and the alternative a choice makes.
template <std::size_t... I>
std::vector<std::pair<std::string, std::size_t>> kneeKindChoices(std::index_sequence<I...>) {
  return {{std::variant_alternative_t<I, KneeKind>::kKey, I}...};
}
template <std::size_t... I>
KneeKind makeKneeKind(std::size_t index, std::index_sequence<I...>) {
  KneeKind kind;
  ((index == I ? (kind.emplace<I>(), 0) : 0), ...);
  return kind;
}

template <class A>
void serialize(A& a, KneeModelSpec& k) {
  constexpr auto kinds = std::make_index_sequence<std::variant_size_v<KneeKind>>();
  std::size_t index = k.kind.index();
  a.choice("kind", index, kneeKindChoices(kinds));
  if constexpr (A::kReading) k.kind = makeKneeKind(index, kinds);
  a.optionalText("name", k.name);
  a.optionalText("description", k.description);
  a.optionalText("source", k.source);
  std::visit([&](auto& kind) { serializeKind(a, kind); }, k.kind);
  a.optionalMap("knee_effects", k.kneeEffects, k.hasKneeEffects);
  a.optionalMap("hyperextension_stop", k.stop, k.hasStop);
}

// ---- Reading and writing ------------------------------------------------------------------

namespace {

KneeModel readKneeModel(YamlMap& yaml, const std::string& path) {
  KneeModel model;
  model.path = path;
  YamlReadArchive a(yaml);
  serialize(a, model.spec);
  yaml.finish();
  model.name = model.spec.name.empty() ? fileStem(path) : model.spec.name;
  try {
    model.law = makeKneeModelLaw(model.spec);
  } catch (const std::invalid_argument& e) {
    throw InputError(yaml.where() + e.what());
  }
  return model;
}

}  // namespace

KneeModel loadKneeModel(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readKneeModel(yaml, path);
}

KneeModel parseKneeModel(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readKneeModel(yaml, path);
}

MauchCylinderParams loadMauchCylinder(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  const KneeModel model = readKneeModel(yaml, path);
  const MauchKnee* mauch = model.spec.as<MauchKnee>();
  if (!mauch) yaml.fail("kind", "expected a Mauch cylinder model (kind: mauch)", model.spec.kindKey());
  return mauch->cylinder;
}

MauchAddedEffects readMauchAddedEffects(YamlMap& effects, int phases) {
  MauchAddedEffects e;
  YamlReadArchive a(effects);
  serialize(a, e, phases);
  effects.finish();
  return e;
}

std::string formatKneeModelYaml(const KneeModelSpec& spec, const std::string& header) {
  return writeYamlDocument(spec, "", header);
}

}  // namespace swingsim
