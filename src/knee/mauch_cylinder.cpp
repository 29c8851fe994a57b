#include "knee/mauch_cylinder.h"

#include <cmath>
#include <stdexcept>

namespace swingsim {

MauchSwitches calcMauchSwitches(double x, double xd, double s2, const MauchSwitchParams& sw) {
  return combineMauchSwitches(0.5 + 0.5 * std::tanh(xd / sw.velocityWidth),                                // Eq. 4
                              s2,                                                                          // Eq. 5
                              0.5 + 0.5 * std::tanh((x - sw.hyperextensionPosition) / sw.positionWidth));  // Eq. 16
}

MauchSwitches combineMauchSwitches(double s1, double s2, double s8) {
  MauchSwitches s;
  s.s1 = s1;
  s.s2 = s2;
  s.s3 = 1.0 - s.s1 * (1.0 - s2);  // Eq. 3
  s.s8 = s8;
  s.s4 = s.s1 * (1.0 - s2) * s.s8;  // Eq. 12
  s.s5 = (1.0 - s.s1) * s.s8;       // Eq. 13
  s.s6 = s.s1 * s2 * s.s8;          // Eq. 14
  s.s7 = 1.0 - s.s8;                // Eq. 15
  return s;
}

double calcLatchDerivative(double x, double xd, double s2, const MauchSwitchParams& sw) {
  // Chien 2014 Eq. 6.
  const double s1 = 0.5 + 0.5 * std::tanh(xd / sw.velocityWidth);
  const double hyperextended = 0.5 - 0.5 * std::tanh((x - sw.hyperextensionPosition) / sw.positionWidth);
  return sw.latchRate * (1.0 - s1) * (hyperextended - s2);
}

std::vector<double> calcPhaseGates(int phases, const MauchSwitches& s) {
  if (phases == 2) return {s.s1 * (1.0 - s.s2), s.s3};  // Eq. 2: 1 - S3 = S1 (1 - S2)
  // Eqs. 8-11 with phases 2 and 3 gated as the paper describes them (see header).
  return {s.s4, s.s6, s.s5, s.s7};
}

std::vector<double> calcLatchHistory(const std::vector<double>& time, const std::vector<double>& x,
                                     const std::vector<double>& xd, const MauchSwitchParams& sw, double s2Start,
                                     int substeps) {
  if (x.size() != time.size() || xd.size() != time.size())
    throw std::invalid_argument("calcLatchHistory: time, x and xd differ in length");
  if (substeps < 1) throw std::invalid_argument("calcLatchHistory: substeps must be >= 1");
  std::vector<double> s2(time.size());
  if (time.empty()) return s2;
  double s = s2Start;
  s2[0] = s;
  for (std::size_t i = 1; i < time.size(); ++i) {
    const double h = (time[i] - time[i - 1]) / substeps;
    for (int j = 0; j < substeps; ++j) {
      // Midpoint of the sub-interval: Eq. 6 is linear in S2, dS2/dt = a (b - S2).
      const double w = (j + 0.5) / substeps;
      const double xm = x[i - 1] + w * (x[i] - x[i - 1]);
      const double vm = xd[i - 1] + w * (xd[i] - xd[i - 1]);
      const double a = sw.latchRate * (0.5 - 0.5 * std::tanh(vm / sw.velocityWidth));
      const double b = 0.5 - 0.5 * std::tanh((xm - sw.hyperextensionPosition) / sw.positionWidth);
      s = b + (s - b) * std::exp(-a * h);
    }
    s2[i] = s;
  }
  return s2;
}

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("MauchCylinder: " + what);
}

}  // namespace

MauchCylinder::MauchCylinder(MauchCylinderParams params) : p_(std::move(params)), geometry_(p_.geometry) {
  require(p_.phases == 2 || p_.phases == 4, "phases must be 2 or 4 (got " + std::to_string(p_.phases) + ")");
  require(static_cast<int>(p_.coefficients.size()) == p_.phases, "expected " + std::to_string(p_.phases) +
                                                                     " phase coefficient sets (got " +
                                                                     std::to_string(p_.coefficients.size()) + ")");
  for (const auto& c : p_.coefficients)
    require(std::isfinite(c.f) && std::isfinite(c.k) && std::isfinite(c.c), "coefficients must be finite");
  const auto& sw = p_.switches;
  require(std::isfinite(sw.velocityWidth) && sw.velocityWidth > 0, "velocity width must be positive, m/s");
  require(std::isfinite(sw.positionWidth) && sw.positionWidth > 0, "position width must be positive, m");
  require(std::isfinite(sw.hyperextensionPosition), "hyperextension position must be finite, m");
  require(std::isfinite(sw.latchRate) && sw.latchRate > 0, "latch rate k must be positive, 1/s");
  require(std::isfinite(p_.initialLatch) && p_.initialLatch >= 0 && p_.initialLatch <= 1,
          "initial latch S2 must be in [0, 1]");
  const auto& e = p_.effects;
  require(!e.hyperextensionPhase || p_.phases == 2,
          "an added hyperextension phase needs a 2-phase model (the 4-phase model has one)");
  require(std::isfinite(e.hyperextension.f) && std::isfinite(e.hyperextension.k) && std::isfinite(e.hyperextension.c) &&
              std::isfinite(e.coulombForce) && std::isfinite(e.orificeCoefficient) && std::isfinite(e.pistonMass) &&
              std::isfinite(e.positionDamping),
          "added effect parameters must be finite");
  require(std::isfinite(e.coulombWidth) && e.coulombWidth > 0, "Coulomb friction width must be positive, m/s");
  expressions_ = CylinderExpressionForces(e.expressions);  // KneeExpressionError is an invalid_argument
}

std::vector<double> MauchCylinder::calcGates(const MauchSwitches& s) const {
  std::vector<double> gates(static_cast<std::size_t>(numPhaseGates()));
  calcGates(s, gates.data());
  return gates;
}

void MauchCylinder::calcGates(const MauchSwitches& s, double* gates) const {
  if (p_.phases == 2) {
    gates[0] = s.s1 * (1.0 - s.s2);  // Eq. 2: 1 - S3 = S1 (1 - S2)
    gates[1] = s.s3;
  } else {
    // Eqs. 8-11 with phases 2 and 3 gated as the paper describes them (see header).
    gates[0] = s.s4;
    gates[1] = s.s6;
    gates[2] = s.s5;
    gates[3] = s.s7;
  }
  if (p_.effects.hyperextensionPhase) {
    // Chien 2014 Eq. 11: outside hyperextension the base phases, inside it the new one.
    for (int i = 0; i < p_.phases; ++i) gates[i] *= s.s8;
    gates[p_.phases] = s.s7;
  }
}

double MauchCylinder::calcForce(double x, double xd, double xdd, double s2) const {
  double gates[kMaxGates];
  calcGates(calcMauchSwitches(x, xd, s2, p_.switches), gates);
  double force = 0;
  for (int i = 0; i < p_.phases; ++i) {
    const auto& c = p_.coefficients[static_cast<std::size_t>(i)];
    force += gates[static_cast<std::size_t>(i)] * (c.f + c.k * x + c.c * xd);
  }
  const auto& e = p_.effects;
  if (e.hyperextensionPhase)
    force += gates[p_.phases] * (e.hyperextension.f + e.hyperextension.k * x + e.hyperextension.c * xd);
  if (e.coulombFriction) force += e.coulombForce * std::tanh(xd / e.coulombWidth);
  if (e.orificeQuadratic) force += e.orificeCoefficient * xd * std::fabs(xd);
  if (e.inertia) force += e.pistonMass * xdd;
  if (e.positionDependentDamping) force += e.positionDamping * x * xd;
  return force + calcExpressionForce(x, xd);
}

std::vector<double> MauchCylinder::calcRegressorRow(double x, double xd, double xdd, double s2) const {
  std::vector<double> row(static_cast<std::size_t>(numCoefficients()));
  calcRegressorRow(x, xd, xdd, s2, row.data());
  return row;
}

void MauchCylinder::calcRegressorRow(double x, double xd, double xdd, double s2, double* row) const {
  double gates[kMaxGates];
  calcGates(calcMauchSwitches(x, xd, s2, p_.switches), gates);
  const int numGates = numPhaseGates();
  for (int i = 0; i < numGates; ++i) {
    *row++ = gates[i];
    *row++ = gates[i] * x;
    *row++ = gates[i] * xd;
  }
  const auto& e = p_.effects;
  if (e.coulombFriction) *row++ = std::tanh(xd / e.coulombWidth);
  if (e.orificeQuadratic) *row++ = xd * std::fabs(xd);
  if (e.inertia) *row++ = xdd;
  if (e.positionDependentDamping) *row++ = x * xd;
}

std::vector<double> MauchCylinder::getCoefficientVector() const {
  std::vector<double> v;
  for (const auto& c : p_.coefficients) {
    v.push_back(c.f);
    v.push_back(c.k);
    v.push_back(c.c);
  }
  const auto& e = p_.effects;
  if (e.hyperextensionPhase) {
    v.push_back(e.hyperextension.f);
    v.push_back(e.hyperextension.k);
    v.push_back(e.hyperextension.c);
  }
  if (e.coulombFriction) v.push_back(e.coulombForce);
  if (e.orificeQuadratic) v.push_back(e.orificeCoefficient);
  if (e.inertia) v.push_back(e.pistonMass);
  if (e.positionDependentDamping) v.push_back(e.positionDamping);
  return v;
}

void setMauchCoefficientVector(MauchCylinderParams& params, const std::vector<double>& b) {
  const std::size_t expected =
      3 * static_cast<std::size_t>(params.phases) + static_cast<std::size_t>(params.effects.numCoefficients());
  if (b.size() != expected || params.coefficients.size() != static_cast<std::size_t>(params.phases))
    throw std::invalid_argument("setMauchCoefficientVector: expected " + std::to_string(expected) +
                                " coefficients (got " + std::to_string(b.size()) + ")");
  std::size_t i = 0;
  for (auto& c : params.coefficients) {
    c.f = b[i++];
    c.k = b[i++];
    c.c = b[i++];
  }
  auto& e = params.effects;
  if (e.hyperextensionPhase) {
    e.hyperextension.f = b[i++];
    e.hyperextension.k = b[i++];
    e.hyperextension.c = b[i++];
  }
  if (e.coulombFriction) e.coulombForce = b[i++];
  if (e.orificeQuadratic) e.orificeCoefficient = b[i++];
  if (e.inertia) e.pistonMass = b[i++];
  if (e.positionDependentDamping) e.positionDamping = b[i++];
}

std::string MauchCylinder::name() const { return "Mauch cylinder (" + std::to_string(p_.phases) + "-phase)"; }

double MauchCylinder::calcMoment(const KneeKinematics& knee, const double* z) const {
  const double x = geometry_.calcPistonPosition(knee.flexion);
  const double arm = geometry_.calcMomentArm(knee.flexion);
  return -calcForce(x, arm * knee.flexionRate, z[0]) * arm;
}

void MauchCylinder::calcStateDerivatives(const KneeKinematics& knee, const double* z, double* zdot) const {
  const double x = geometry_.calcPistonPosition(knee.flexion);
  const double xd = geometry_.calcPistonVelocity(knee.flexion, knee.flexionRate);
  zdot[0] = calcLatchDerivative(x, xd, z[0], p_.switches);
}

}  // namespace swingsim
