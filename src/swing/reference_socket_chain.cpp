#include "swing/reference_socket_chain.h"

#include <cmath>
#include <stdexcept>

#include "core/units.h"

namespace swingsim {

namespace {

using Vec = ReferenceSocketChain::Vec;
constexpr int kN = ReferenceSocketChain::kDof;
enum Coordinate { kPhi = 0, kBeta = 1, kPiston = 2, kRotation = 3 };

double dotQ(const Vec& w, const Vec& q) { return w[0] * q[0] + w[1] * q[1] + w[2] * q[2] + w[3] * q[3]; }

// Solves m x = r for the unknowns from index `skip` on (the leading ones known and already
// taken into r; m symmetric positive definite): Gaussian elimination without pivoting on the
// trailing block. x's leading entries are left 0.
Vec solveTrailing(double m[kN][kN], double r[kN], int skip) {
  for (int k = skip; k < kN; ++k)
    for (int i = k + 1; i < kN; ++i) {
      const double f = m[i][k] / m[k][k];
      for (int j = k; j < kN; ++j) m[i][j] -= f * m[k][j];
      r[i] -= f * r[k];
    }
  Vec x{};
  for (int i = kN - 1; i >= skip; --i) {
    double s = r[i];
    for (int j = i + 1; j < kN; ++j) s -= m[i][j] * x[static_cast<std::size_t>(j)];
    x[static_cast<std::size_t>(i)] = s / m[i][i];
  }
  return x;
}

}  // namespace

ReferenceSocketChain::ReferenceSocketChain(const LegGeometry& g, double gamma, double massMomentShank, double shankMass,
                                           double inertiaAboutKnee)
    : gamma_(gamma) {
  if (!g.socket) throw std::invalid_argument("ReferenceSocketChain: the leg has no socket");
  socket_ = *g.socket;
  const SegmentMassProperties limb = calcResidualLimb(g);
  const double toPivot = g.socketPivotBelowHip, pivotToKnee = g.thighLength - g.socketPivotBelowHip;
  const double r2 = massMomentShank / shankMass;
  enum { kLimb = 0, kSocket = 1, kShank = 2 };  // kDirections
  bodies_[0] = {limb.mass, limb.inertia, kLimb, {{{limb.com, false, kLimb}}}, 1};
  bodies_[1] = {
      socket_.mass, socket_.inertia, kSocket, {{{toPivot, true, kLimb}, {-socket_.comAbovePivot, false, kSocket}}}, 2};
  bodies_[2] = {shankMass,
                inertiaAboutKnee - shankMass * r2 * r2,
                kShank,
                {{{toPivot, true, kLimb}, {pivotToKnee, false, kSocket}, {r2, false, kShank}}},
                3};
}

void ReferenceSocketChain::assemble(const Vec& q, const Vec& u, const std::array<double, 2>& support, double m[kN][kN],
                                    double rhs[kN]) const {
  for (int i = 0; i < kN; ++i) {
    rhs[i] = 0;
    for (int j = 0; j < kN; ++j) m[i][j] = 0;
  }
  double sines[3], cosines[3], rates[3];
  for (std::size_t d = 0; d < kDirections.size(); ++d) {
    const double theta = dotQ(kDirections[d], q);
    sines[d] = std::sin(theta);
    cosines[d] = std::cos(theta);
    rates[d] = dotQ(kDirections[d], u);
  }
  for (const Body& b : bodies_) {
    // J (2 x 4) and J' q' of the body's centre of mass, term by term: for L down(theta),
    // d/dq_j = [slides, j = piston] down + L w_j normal, and the convective acceleration
    // 2 L' theta' normal - L theta'^2 down (normal = d down / d theta).
    double jx[kN] = {}, jy[kN] = {}, cx = 0, cy = 0;
    for (int k = 0; k < b.numTerms; ++k) {
      const Term& t = b.terms[static_cast<std::size_t>(k)];
      const Vec& w = kDirections[static_cast<std::size_t>(t.direction)];
      const double rate = rates[t.direction];
      const double s = sines[t.direction], c = cosines[t.direction];  // down = (s, -c), normal = (c, s)
      const double length = t.length + (t.slides ? q[kPiston] : 0.0);
      for (int j = 0; j < kN; ++j) {
        jx[j] += length * w[static_cast<std::size_t>(j)] * c;
        jy[j] += length * w[static_cast<std::size_t>(j)] * s;
      }
      if (t.slides) {
        jx[kPiston] += s;
        jy[kPiston] -= c;
        cx += 2 * u[kPiston] * rate * c;
        cy += 2 * u[kPiston] * rate * s;
      }
      cx -= length * rate * rate * s;
      cy += length * rate * rate * c;
    }
    const double ax = cx + support[0], ay = cy + kGravity + support[1];
    const Vec& angle = kDirections[static_cast<std::size_t>(b.direction)];
    for (int i = 0; i < kN; ++i) {
      rhs[i] -= b.mass * (jx[i] * ax + jy[i] * ay);
      for (int j = 0; j < kN; ++j)
        m[i][j] += b.mass * (jx[i] * jx[j] + jy[i] * jy[j]) +
                   b.inertia * angle[static_cast<std::size_t>(i)] * angle[static_cast<std::size_t>(j)];
    }
  }
  rhs[kPiston] -= socket_.pistonStiffness * q[kPiston] + socket_.pistonDamping * u[kPiston];
  rhs[kRotation] -= socket_.rotationStiffness * q[kRotation] + socket_.rotationDamping * u[kRotation];
}

Vec ReferenceSocketChain::calcAcceleration(const Vec& q, const Vec& u, const Forces& f) const {
  double m[kN][kN], rhs[kN];
  assemble(q, u, f.support, m, rhs);
  // The knee moment acts on phi + rotation - beta; the hip moment on phi.
  rhs[kPhi] += f.hipMoment + f.kneeMoment;
  rhs[kRotation] += f.kneeMoment;
  rhs[kBeta] -= f.kneeMoment;
  return solveTrailing(m, rhs, 0);
}

Vec ReferenceSocketChain::calcAccelerationWithThigh(const Vec& q, const Vec& u, double phiAcc, const Forces& f,
                                                    double& hipMoment) const {
  double m[kN][kN], rhs[kN];
  assemble(q, u, f.support, m, rhs);
  rhs[kPhi] += f.kneeMoment;
  rhs[kRotation] += f.kneeMoment;
  rhs[kBeta] -= f.kneeMoment;
  // The limb's row, kept before elimination: the hip moment is what it lacks.
  double row0[kN];
  for (int j = 0; j < kN; ++j) row0[j] = m[kPhi][j];
  const double rhs0 = rhs[kPhi];
  for (int i = 1; i < kN; ++i) rhs[i] -= m[i][kPhi] * phiAcc;
  Vec a = solveTrailing(m, rhs, 1);
  a[kPhi] = phiAcc;
  hipMoment = row0[0] * a[0] + row0[1] * a[1] + row0[2] * a[2] + row0[3] * a[3] - rhs0;
  return a;
}

double ReferenceSocketChain::calcEnergy(const Vec& q, const Vec& u) const {
  double m[kN][kN], rhs[kN];
  assemble(q, u, {0.0, 0.0}, m, rhs);
  double kinetic = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j)
      kinetic += 0.5 * u[static_cast<std::size_t>(i)] * m[i][j] * u[static_cast<std::size_t>(j)];
  double potential = 0.5 * socket_.pistonStiffness * q[kPiston] * q[kPiston] +
                     0.5 * socket_.rotationStiffness * q[kRotation] * q[kRotation];
  for (const Body& b : bodies_)
    for (int k = 0; k < b.numTerms; ++k) {
      const Term& t = b.terms[static_cast<std::size_t>(k)];
      const double length = t.length + (t.slides ? q[kPiston] : 0.0);
      potential -= b.mass * kGravity * length * std::cos(dotQ(kDirections[static_cast<std::size_t>(t.direction)], q));
    }
  return kinetic + potential;
}

}  // namespace swingsim
