#include "identify/cylinder_effects.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/input_error.h"
#include "identify/user_cylinder_effect.h"

namespace swingsim {

namespace {

// Latch rate of Chien 2014 (k = 1e4 /s): the no-delay reference for switch_delay.
constexpr double kPublishedLatchRate = 1e4;

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Chien 2014's 4-phase model produced by a hyperextension phase on a 2-phase model (Chien
// 2014 Eqs. 2 and 11): the 2-phase gates times S8 plus S7 = 1 - S8 are the 4-phase gates with
// phases 2 (S1 S2 S8) and 3 ((1 - S1) S8) merged, so splitting the low-force phase into the
// two gives the nesting 4-phase model (start: both at the low-force coefficients).
std::optional<MauchCylinderParams> splitIntoFourPhases(const MauchCylinderParams& p) {
  if (p.phases != 2 || !p.effects.hyperextensionPhase) return std::nullopt;
  MauchCylinderParams q = p;
  q.phases = 4;
  q.coefficients = {p.coefficients[0], p.coefficients[1], p.coefficients[1], p.effects.hyperextension};
  q.effects.hyperextensionPhase = false;
  q.effects.hyperextension = {};
  return q;
}

// position_dependent_damping: every flexion/extension phase keeps non-negative damping
// c + cx x over the recorded stroke (a negative damper would feed energy in).
bool positionDampingIsPhysical(const MauchCylinderParams& p, const std::vector<BenchData>& train, std::string& note) {
  double xMin = 1e300, xMax = -1e300;
  for (const auto& d : train)
    for (double x : d.position) {
      xMin = std::max(0.0, std::min(xMin, x));
      xMax = std::max(xMax, x);
    }
  double worst = 1e300;
  const int flexExtPhases = p.phases == 4 ? 3 : 2;
  for (int ph = 0; ph < flexExtPhases; ++ph) {
    const double c = p.coefficients[static_cast<std::size_t>(ph)].c;
    worst = std::min({worst, c + p.effects.positionDamping * xMin, c + p.effects.positionDamping * xMax});
  }
  note = "damping c + cx x must stay >= 0 over the stroke: lowest " + fmt(worst) + " N s/m";
  return worst >= 0;
}

// switch_delay is on when the latch is at least as slow as the fastest grid value.
bool hasSlowLatch(const MauchCylinderParams& p) {
  return 1.0 / p.switches.latchRate >= describeEffect(EffectId::kSwitchDelay).grid.front();
}

}  // namespace

// The records, in the effect table's order. Column ranks follow
// MauchCylinder::calcRegressorRow: hyperextension (3), Coulomb, orifice, inertia, position.
const std::vector<CylinderEffectRecord>& cylinderEffectRecords() {
  using E = EffectId;
  using K = PlantKind;
  using P = MauchCylinderParams;
  using Train = std::vector<BenchData>;
  static const std::vector<CylinderEffectRecord> table = {
      {{E::kCoulombFriction,
        K::kCylinder,
        "coulomb_friction",
        "a seal friction force of constant size that always opposes the piston's motion",
        "Chien 2014 tried a Coulomb term opposing motion (it made their fit worse)",
        "records at several speeds (its size does not grow with speed)",
        {"force_N", "width_m_per_s"},
        1,
        // tanh width Fc tanh(xd / w), m/s
        {0.002, 0.005, 0.01, 0.02, 0.05},
        1.0,
        false},
       [](const P& p) { return p.effects.coulombFriction; },
       [](P& p, double grid) {
         p.effects.coulombFriction = true;
         p.effects.coulombForce = 0;
         p.effects.coulombWidth = grid;
       },
       [](P& p) { p.effects.coulombFriction = false; },
       [](const P& p) {
         return std::vector<double>{p.effects.coulombForce, p.effects.coulombWidth};
       },
       [](const P& p, const Train&, std::string& note) {
         note = "friction force must oppose motion (force_N > 0): " + fmt(p.effects.coulombForce) + " N";
         return p.effects.coulombForce > 0;
       },
       1,
       1,
       nullptr,
       [](P& model, const P& fromB) {
         model.effects.coulombFriction = true;
         model.effects.coulombForce = 0;
         model.effects.coulombWidth = fromB.effects.coulombWidth;
       }},
      {{E::kOrificeQuadratic,
        K::kCylinder,
        "orifice_quadratic",
        "extra resistance growing with the square of piston speed: turbulent flow through the orifices",
        "Chien 2014: slow gait fits worst, likely non-linear flow through cylinder, orifices and valve",
        "records at clearly different speeds (slow and fast walking)",
        {"coefficient_Ns2_per_m2"},
        1,
        {},
        1.0,
        false},
       [](const P& p) { return p.effects.orificeQuadratic; },
       [](P& p, double) {
         p.effects.orificeQuadratic = true;
         p.effects.orificeCoefficient = 0;
       },
       [](P& p) { p.effects.orificeQuadratic = false; },
       [](const P& p) { return std::vector<double>{p.effects.orificeCoefficient}; },
       [](const P& p, const Train&, std::string& note) {
         note =
             "orifice flow must resist motion (coefficient > 0): " + fmt(p.effects.orificeCoefficient) + " N s^2/m^2";
         return p.effects.orificeCoefficient > 0;
       },
       1,
       2},
      {{E::kInertia,
        K::kCylinder,
        "inertia",
        "a force proportional to piston acceleration: the moving mass of piston, rod and oil",
        "Chien 2014 tried an acceleration term (it did not help on their data)",
        "records with different frequency content (another cadence or a sine sweep)",
        {"mass_kg"},
        1,
        {},
        1.0,
        false},
       [](const P& p) { return p.effects.inertia; },
       [](P& p, double) {
         p.effects.inertia = true;
         p.effects.pistonMass = 0;
       },
       [](P& p) { p.effects.inertia = false; },
       [](const P& p) { return std::vector<double>{p.effects.pistonMass}; },
       [](const P& p, const Train&, std::string& note) {
         note = "moving mass must be positive: " + fmt(p.effects.pistonMass) + " kg";
         return p.effects.pistonMass > 0;
       },
       1,
       3},
      {{E::kPositionDependentDamping,
        K::kCylinder,
        "position_dependent_damping",
        "damping that changes along the stroke (metering grooves, valve opening with position)",
        "Chien 2014's phases have constant damping; the valve geometry varies along the stroke",
        "records with different knee-angle amplitudes",
        {"coefficient_Ns_per_m2"},
        1,
        {},
        1.0,
        false},
       [](const P& p) { return p.effects.positionDependentDamping; },
       [](P& p, double) {
         p.effects.positionDependentDamping = true;
         p.effects.positionDamping = 0;
       },
       [](P& p) { p.effects.positionDependentDamping = false; },
       [](const P& p) { return std::vector<double>{p.effects.positionDamping}; },
       positionDampingIsPhysical,
       1,
       4},
      {{E::kHyperextensionPhase,
        K::kCylinder,
        "hyperextension_phase",
        "a separate force law while the piston is hyperextended (Chien's 4th phase)",
        "Chien 2014 Eq. 11: the 4-phase model adds hyperextension to the 2-phase model",
        "records with longer or deeper hyperextension",
        {"f_N", "k_N_per_m", "c_Ns_per_m"},
        3,
        {},
        1.0,
        false},
       [](const P& p) { return p.effects.hyperextensionPhase; },
       [](P& p, double) {
         p.effects.hyperextensionPhase = true;
         p.effects.hyperextension = {};
       },
       [](P& p) { p.effects.hyperextensionPhase = false; },
       [](const P& p) {
         const auto& h = p.effects.hyperextension;
         return std::vector<double>{h.f, h.k, h.c};
       },
       [](const P& p, const Train&, std::string& note) {
         note = "hyperextension stiffness must push the piston out of hyperextension (k > 0): " +
                fmt(p.effects.hyperextension.k) + " N/m";
         return p.effects.hyperextension.k > 0;
       },
       3,
       0,
       [](const P& p) -> std::string {
         return p.phases != 2 ? "the 4-phase model already has a hyperextension phase" : "";
       },
       nullptr,
       CylinderRefit::kSwitches,
       splitIntoFourPhases},
      // No column: a slower latch is the S2 latch rate k of Chien 2014 Eq. 6.
      {{E::kSwitchDelay,
        K::kCylinder,
        "switch_delay",
        "the valve latch (balance wheel) needs time to turn: swing flexion starts partly with stance resistance",
        "Chien 2014 discussion: the balance-wheel release timing (about 0.1 s) is not reproduced by fast switches",
        "records with longer hyperextension holds (a slow latch completes given time)",
        {"time_constant_s"},
        0,
        // latch time constant 1/k, s (Chien 2014: the balance-wheel delay is "about 0.1 s")
        {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1},
        1.0,
        false},
       hasSlowLatch,
       [](P& p, double grid) { p.switches.latchRate = 1.0 / grid; },
       [](P& p) { p.switches.latchRate = kPublishedLatchRate; },
       [](const P& p) { return std::vector<double>{1.0 / p.switches.latchRate}; },
       [](const P& p, const Train&, std::string& note) {
         note = "latch time constant 1/k > 0: " + fmt(1.0 / p.switches.latchRate) + " s";
         return true;
       },
       0,
       -1,
       [](const P& p) -> std::string {
         return hasSlowLatch(p)
                    ? "the model's latch is already slow (k = " + formatNumber(p.switches.latchRate) + " /s)"
                    : "";
       },
       [](P& model, const P& fromB) {
         model.switches.latchRate = std::min(model.switches.latchRate, fromB.switches.latchRate);
       },
       CylinderRefit::kSwitchesLatch},
  };
  return table;
}

const CylinderEffectRecord& findCylinderEffectRecord(EffectId effect) {
  for (const auto& r : cylinderEffectRecords())
    if (r.id() == effect) return r;
  if (const CylinderEffectRecord* user = findUserCylinderEffectRecord(effect)) return *user;
  throw std::invalid_argument("not a cylinder effect: " + describeEffect(effect).name);
}

std::vector<int> cylinderEffectColumns(const MauchCylinderParams& p, EffectId effect) {
  std::vector<const CylinderEffectRecord*> byColumn;
  for (const auto& r : cylinderEffectRecords())
    if (r.columnRank >= 0) byColumn.push_back(&r);
  std::sort(byColumn.begin(), byColumn.end(),
            [](const auto* a, const auto* b) { return a->columnRank < b->columnRank; });
  int col = 3 * p.phases;
  std::vector<int> cols;
  for (const auto* r : byColumn) {
    if (!r->has(p)) continue;
    if (r->id() == effect)
      for (int i = 0; i < r->columns; ++i) cols.push_back(col + i);
    col += r->columns;
  }
  return cols;
}

}  // namespace swingsim
