#pragma once
// The Mauch S-N-S hydraulic knee cylinder: 2-phase and 4-phase force laws with smooth
// phase switches (Chien 2014 Eqs. 2-16), the S2 hyperextension latch as a continuous
// state (Eq. 6), and the knee moment through the knee geometry (Eq. 1).
//
// Readings of the paper's ambiguous lines (docs/mauch.md says why):
// - x0 is split: a velocity width (m/s) in S1 and a position width (m) in Eq. 6 and S8.
//   Defaults read the published x0 = 0.05 in the unit of xhy (0.005 cm): 0.05 cm(/s).
// - x > 0 in flexion (docs/mauch.md), so S1 = 1 while flexing and S4 selects stance flexion.
// - Phase gates follow the paper's phase descriptions and Table 1 (not Eqs. 9-10 as
//   printed): phase 2 "flexion at end stance and early swing" is gated by S1 S2 S8, and
//   phase 3 "extension" by (1 - S1) S8.
#include <memory>
#include <string>
#include <vector>

#include "knee/cylinder_expression.h"
#include "knee/knee_geometry.h"
#include "knee/knee_law.h"

namespace swingsim {

/// Switch constants (Chien 2014 Eqs. 4, 6, 16).
struct MauchSwitchParams {
  double velocityWidth = 5e-4;           ///< x0 in S1 (Eq. 4), m/s, > 0
  double positionWidth = 5e-4;           ///< x0 in Eq. 6 and S8 (Eq. 16), m, > 0
  double hyperextensionPosition = 5e-5;  ///< xhy, m (0.005 cm)
  double latchRate = 1e4;                ///< k in Eq. 6, 1/s, > 0
};

/// One phase's force law f + k x + c xd.
struct MauchPhaseCoefficients {
  double f = 0;  ///< offset force, N
  double k = 0;  ///< stiffness, N/m
  double c = 0;  ///< damping, N s/m
};

/// Physical effects added to Chien 2014's force law, found by `swingsim diagnose`
/// (docs/diagnosis.md). Each is off unless its flag is set; all add to the cylinder force F
/// (N, positive resists compression). The S2 latch delay (`switch_delay`) needs no field:
/// it is a smaller `MauchSwitchParams::latchRate`.
struct MauchAddedEffects {
  /// A hyperextension phase for a 2-phase model (Chien 2014 Eq. 11, gate S7 = 1 - S8): the
  /// two base gates are multiplied by S8 and this law acts where the piston is hyperextended.
  bool hyperextensionPhase = false;
  MauchPhaseCoefficients hyperextension;
  /// Coulomb (seal) friction Fc tanh(xd / width): Fc in N (> 0 resists motion), width m/s.
  bool coulombFriction = false;
  double coulombForce = 0;
  double coulombWidth = 0.01;
  /// Turbulent orifice flow a xd |xd| (Chien 2014 discussion: non-linear flow), a in N s^2/m^2.
  bool orificeQuadratic = false;
  double orificeCoefficient = 0;
  /// Moving mass m xdd (piston, rod, oil), m in kg. Needs the piston acceleration, which a
  /// knee law cannot see: in a swing simulation this term is left out (its knee inertia
  /// m (dx/dtheta)^2 is ~6e-5 kg m^2 per kg, against ~0.1 kg m^2 for the shank).
  bool inertia = false;
  double pistonMass = 0;
  /// Damping that varies along the stroke, cx x xd (cx in N s/m^2): metering grooves.
  bool positionDependentDamping = false;
  double positionDamping = 0;
  /// Users' forces written as expressions in the piston's position and speed
  /// (knee/cylinder_expression.h), as a diagnosis saves an accepted one. They add no
  /// regression column: a fit subtracts them from the measured force (their parameters are
  /// fitted around the regression, identify/cylinder_plant.h).
  std::vector<KneeExpressionParams> expressions;

  /// Number of regression coefficients the enabled effects add (3 + 1 + 1 + 1 + 1 at most).
  int numCoefficients() const {
    return (hyperextensionPhase ? 3 : 0) + coulombFriction + orificeQuadratic + inertia + positionDependentDamping;
  }
  bool any() const { return numCoefficients() > 0 || !expressions.empty(); }
};

struct MauchCylinderParams {
  int phases = 4;                                    ///< 2 or 4
  std::vector<MauchPhaseCoefficients> coefficients;  ///< one per phase, phase 1 first
  MauchSwitchParams switches;
  KneeGeometryParams geometry;
  /// S2 at the start of a simulation. 1 for a swing that starts at toe-off: the late-stance
  /// hyperextension has released the valve. A bench test starting at heel strike uses 0.
  double initialLatch = 1.0;
  MauchAddedEffects effects;  ///< none in Chien 2014's models
};

/// All switch variables at one instant (Chien 2014 Eqs. 3-4, 12-16), each in [0, 1].
struct MauchSwitches {
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0;
};

/// Switch values at piston position x (m), velocity xd (m/s) and latch state s2.
MauchSwitches calcMauchSwitches(double x, double xd, double s2, const MauchSwitchParams& sw);
/// The same from S1 (Eq. 4), S2 and S8 (Eq. 16) already computed: the products of Eqs. 3,
/// 12-15 (calcMauchSwitches uses it; the switch-constant fit reuses S1 and S8 between starts).
MauchSwitches combineMauchSwitches(double s1, double s2, double s8);

/// dS2/dt (1/s), Chien 2014 Eq. 6: k (1 - S1) [1/2 - 1/2 tanh((x - xhy)/x0) - S2].
double calcLatchDerivative(double x, double xd, double s2, const MauchSwitchParams& sw);

/// Phase gates (weights of each phase's force law, summing to 1) for a 2- or 4-phase model:
/// 2-phase: {S1 (1 - S2), S3} (Eq. 2); 4-phase: {S1 (1 - S2) S8, S1 S2 S8, (1 - S1) S8, 1 - S8}.
std::vector<double> calcPhaseGates(int phases, const MauchSwitches& s);

/// S2 along sampled data: integrates Eq. 6 exactly for coefficients held piecewise constant
/// over `substeps` sub-intervals of each sample interval (x, xd interpolated linearly), so the
/// stiff latch (k = 1e4/s against 361.4 Hz samples) stays stable and in [0, 1].
/// `time` (s) strictly increasing; all vectors the same length. Returns S2 at each sample.
std::vector<double> calcLatchHistory(const std::vector<double>& time, const std::vector<double>& x,
                                     const std::vector<double>& xd, const MauchSwitchParams& sw, double s2Start,
                                     int substeps = 10);

/// Writes a coefficient vector in MauchCylinder::calcRegressorRow's order back into `params`.
/// Throws std::invalid_argument if its size differs from the model's coefficient count.
void setMauchCoefficientVector(MauchCylinderParams& params, const std::vector<double>& b);

/// The Mauch cylinder as a knee law with one state (S2). Throws std::invalid_argument on a
/// phase count other than 2 or 4, a coefficient count that differs from it, non-finite
/// coefficients, or non-positive switch widths or latch rate.
class MauchCylinder final : public KneeLaw {
 public:
  explicit MauchCylinder(MauchCylinderParams params);
  const MauchCylinderParams& params() const { return p_; }
  const KneeGeometry& geometry() const { return geometry_; }
  /// Linear coefficients: 3 per phase, then those of the added effects.
  int numCoefficients() const { return 3 * p_.phases + p_.effects.numCoefficients(); }
  /// Number of phase gates: the model's phases plus an added hyperextension phase.
  int numPhaseGates() const { return p_.phases + (p_.effects.hyperextensionPhase ? 1 : 0); }
  /// Phase gates at these switch values (calcPhaseGates, with an added hyperextension phase).
  std::vector<double> calcGates(const MauchSwitches& s) const;
  /// Most phase gates a model has (4 phases, or 2 plus an added hyperextension phase).
  static constexpr int kMaxGates = 4;
  /// The same gates written to gates[0 .. numPhaseGates()), without allocating (the fit
  /// builds its regression thousands of times).
  void calcGates(const MauchSwitches& s, double* gates) const;

  /// Cylinder force (N, positive resists compression) at piston position x (m), velocity
  /// xd (m/s) and latch S2: sum over phases of gate * (f + k x + c xd) (Eqs. 2, 7-11), plus
  /// the added effects except inertia (acceleration taken as 0).
  double calcForce(double x, double xd, double s2) const { return calcForce(x, xd, 0.0, s2); }
  /// Same with the piston acceleration xdd (m/s^2) for the inertia effect.
  double calcForce(double x, double xd, double xdd, double s2) const;
  /// The regression row for one sample: for each phase p, {g_p, g_p x, g_p xd}, then the
  /// added effects' columns (hyperextension phase {g, g x, g xd}, tanh(xd/width), xd|xd|,
  /// xdd, x xd), so that calcForce = row . getCoefficientVector(). Size numCoefficients().
  std::vector<double> calcRegressorRow(double x, double xd, double s2) const {
    return calcRegressorRow(x, xd, 0.0, s2);
  }
  std::vector<double> calcRegressorRow(double x, double xd, double xdd, double s2) const;
  /// The same row written to row[0 .. numCoefficients()), without allocating.
  void calcRegressorRow(double x, double xd, double xdd, double s2, double* row) const;
  /// Coefficients flattened in the regressor's order.
  std::vector<double> getCoefficientVector() const;
  /// The users' expression forces (N) at x (m), xd (m/s): 0 without any. Part of calcForce,
  /// not of the regressor row.
  double calcExpressionForce(double x, double xd) const {
    return expressions_.empty() ? 0.0 : expressions_.calcForce(x, xd);
  }

  std::string name() const override;
  int numStates() const override { return 1; }
  void initialStates(double* z) const override { z[0] = p_.initialLatch; }
  /// M = -F dx/dtheta (N m, positive = flexion), z[0] = S2.
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  void calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const override;
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<MauchCylinder>(*this); }

 private:
  MauchCylinderParams p_;
  KneeGeometry geometry_;
  CylinderExpressionForces expressions_;
};

}  // namespace swingsim
