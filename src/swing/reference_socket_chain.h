#pragma once
// The reference integrator's leg with a compliant socket (docs/socket.md): residual limb about
// the hip, the socket on a pistoning slide along the limb and a pivot at its end, the shank
// and foot (one rigid body) about the knee below the socket. Four coordinates
// q = (phi, beta, piston, rotation): phi the residual limb from hanging straight down, beta
// the shank body's centre-of-mass line (as in the rigid reference, docs/reference-swing.md),
// the piston (m, + = pulled off the limb) and the socket's rotation on the limb (rad, + =
// flexed). Knee flexion = phi + rotation - beta + gamma. The equations are Lagrange's, in
// the planar form M(q) q'' = Q - sum_b m_b J_b^T (J_b' q' + g): every centre of mass is a sum
// of lengths along directions that are linear in q, so the Jacobians and their convective
// terms are written out exactly (reference_socket_chain.cpp). No Simbody code.
#include <array>

#include "model/leg_parameters.h"

namespace swingsim {

class ReferenceSocketChain {
 public:
  static constexpr int kDof = 4;
  using Vec = std::array<double, kDof>;

  /// `g.socket` must be set (throws std::invalid_argument otherwise). `gamma`: the shank
  /// body's centre-of-mass line off the shank axis, `massMomentShank` its m2 r2 (kg m) and
  /// `inertiaAboutKnee` its m22 (kg m^2), as the rigid reference computes them.
  ReferenceSocketChain(const LegGeometry& g, double gamma, double massMomentShank, double shankMass,
                       double inertiaAboutKnee);

  /// The generalized forces on q. `hipMoment` acts on the limb (phi), `kneeMoment`
  /// (+ = flexion) between socket and shank; the socket's springs and dampers act on their
  /// coordinates; `support` (m/s^2) is the hip's acceleration (a moving hip), zero if fixed.
  struct Forces {
    double hipMoment = 0, kneeMoment = 0;
    std::array<double, 2> support{0.0, 0.0};
  };

  /// Accelerations q'' at (q, u) under `f`.
  Vec calcAcceleration(const Vec& q, const Vec& u, const Forces& f) const;
  /// With phi'' prescribed (the measured thigh drive): the other three accelerations, and the
  /// hip moment the prescription needs (written to `hipMoment`; f.hipMoment is ignored).
  Vec calcAccelerationWithThigh(const Vec& q, const Vec& u, double phiAcc, const Forces& f, double& hipMoment) const;

  /// Kinetic + gravitational potential + socket spring energy (J), potential zero at hip height.
  double calcEnergy(const Vec& q, const Vec& u) const;

  /// The relative angle the knee law sees, rad / rad/s.
  double calcKneeFlexion(const Vec& q) const { return q[0] + q[3] - q[1] + gamma_; }
  double calcKneeFlexionRate(const Vec& u) const { return u[0] + u[3] - u[1]; }
  double gamma() const { return gamma_; }

 private:
  // One body: its centre of mass as terms length * down(w . q), the length growing with the
  // piston when `slides`; its planar angle is its own line's, kDirections[direction] . q (plus
  // a constant).
  struct Term {
    double length;
    bool slides;
    int direction;  // index into kDirections: the limb's, the socket's or the shank's line
  };
  struct Body {
    double mass, inertia;
    int direction;
    std::array<Term, 3> terms;
    int numTerms;
  };
  // M (row-major), and the velocity and gravity part of the right-hand side: -sum m J^T (conv + g + support).
  void assemble(const Vec& q, const Vec& u, const std::array<double, 2>& support, double m[kDof][kDof],
                double rhs[kDof]) const;

  /// The three lines the terms lie along, each an angle w . q.
  static constexpr std::array<Vec, 3> kDirections{{{1, 0, 0, 0}, {1, 0, 0, 1}, {0, 1, 0, 0}}};
  std::array<Body, 3> bodies_{};
  SocketCompliance socket_;
  double gamma_ = 0;
};

}  // namespace swingsim
