#pragma once
// Mauch knee geometry (Chien 2014 Eq. 1): how the hydraulic cylinder's length bc follows
// the knee flexion angle, and the piston position x the cylinder laws use.
//
// Conventions: knee flexion theta in rad, positive in flexion, negative in
// hyperextension. Piston position x = bc(0) - bc(theta) in m: x = 0 at full extension,
// x > 0 in flexion (the cylinder shortens), x < 0 in hyperextension; xd > 0 while flexing.
//
// Force sign: a cylinder force F (N) is positive when it resists compression, i.e. it is
// the force along +x that the bench machine (or the knee linkage) must apply to the piston
// to move it; a damper with c > 0 then has F * xd >= 0. Its moment on the knee follows from
// virtual work, M * thetadot = -F * xd, so M = -F * dx/dtheta = F * d(bc)/dtheta (N m,
// positive in flexion): a force resisting compression resists flexion.

namespace swingsim {

/// Knee cylinder attachment lengths (Chien 2014 Eq. 1 and Fig. 1), m.
struct KneeGeometryParams {
  double ab = 0.1603;  ///< knee axis to the cylinder's proximal attachment, m
  double ac = 0.0247;  ///< knee axis to the cylinder's distal attachment, m
};

/// Chien 2014 Eq. 1: bc^2 = ac^2 + ab^2 - 2 ac ab cos(alpha), alpha = 90 deg - theta.
/// Valid for |theta| < 90 deg (the moment arm keeps its sign there). Throws
/// std::invalid_argument if ab or ac is not positive and finite, or if ab == ac.
class KneeGeometry {
 public:
  explicit KneeGeometry(KneeGeometryParams params = {});
  const KneeGeometryParams& params() const { return p_; }

  /// Cylinder length bc at knee flexion theta (rad), m.
  double calcCylinderLength(double theta) const;
  /// d(bc)/d(theta), m/rad (negative for |theta| < 90 deg: flexion shortens bc).
  double calcLengthDerivative(double theta) const;
  /// Piston position x = bc(0) - bc(theta), m.
  double calcPistonPosition(double theta) const;
  /// Moment arm dx/dtheta = -d(bc)/d(theta), m/rad (positive for |theta| < 90 deg).
  double calcMomentArm(double theta) const;
  /// Piston velocity xd = dx/dtheta * thetadot, m/s.
  double calcPistonVelocity(double theta, double thetaDot) const;
  /// Knee flexion (rad) for a piston position x (m), the inverse of calcPistonPosition on
  /// |theta| < 90 deg. Throws std::domain_error if x is outside the reachable range.
  double calcFlexion(double x) const;
  /// Knee moment (N m, positive = flexion) from a cylinder force F (N, positive resists
  /// compression): M = -F * dx/dtheta (virtual work).
  double calcKneeMoment(double theta, double force) const { return -force * calcMomentArm(theta); }

 private:
  KneeGeometryParams p_;
  double length0_;  // bc at theta = 0
};

}  // namespace swingsim
