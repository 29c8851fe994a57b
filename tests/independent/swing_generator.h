#pragma once
// An independent swing generator for tests. It shares no code with src/: its own equations
// of motion (Kane's method in absolute segment angles, not the Lagrangian in (phi, beta) of
// src/swing/reference_swing.cpp), its own fixed-step RK4, its own knee and hip laws, its own
// noise. It writes the measured-file format a user has (time_s, hip_flexion_deg,
// knee_flexion_deg, hip_moment_Nm) and the participant and knee-model YAML a user writes,
// so what swingsim reads from it is what it would read from a lab.
//
// The leg: thigh about a fixed hip; shank and foot as one rigid body about the knee, the
// foot welded at 90 deg to the shank, pointing forward (the participant format's meaning:
// README, Participant YAML). Angles: hip flexion phi (thigh from hanging straight down,
// forward positive), knee flexion theta = phi - psi (psi the shank's absolute angle).
// The swing runs from toe-off until the knee, after its peak, is back below `endKneeDeg`,
// before the extension stop and the friction near extension act (they are not modelled).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace independent {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.80665;  // standard gravity, m/s^2

struct Segment {
  double length, mass, comFromDistal, inertia;  // m, kg, m, kg m^2 about the COM
};

/// A socket that gives on the residual limb (library: socket_compliance; MyoSuite's
/// transfemoral leg, MyoHub/myo_sim osl/assets/myolegs_osl_chain.xml): the socket rides on a
/// slide along the limb and turns about a pivot at the limb's end, each on a spring and a
/// damper. Its mass is part of the thigh segment. rotationStiffness 0: no socket (rigid).
struct SocketTruth {
  double rotationStiffness = 0, rotationDamping = 0;      // N m/rad, N m s/rad
  double pistonStiffness = 20000, pistonDamping = 10000;  // N/m, N s/m
  double mass = 0.849991, comAbovePivot = 0.101169;       // kg, m
  double inertia = 0.0039776, pivotAboveKnee = 0.1127;    // kg m^2, m
};

struct SwingTruth {
  // Burkett 2004 participant P1 (Tables 1 and 2), as in participants/p1.yaml.
  Segment thigh{0.410, 3.350, 0.284, 0.0264};
  Segment shank{0.515, 0.785, 0.260, 0.0161};
  Segment foot{0.240, 1.030, 0.140, 0.0059};  // COM measured from the toe
  /// Knee damping: a constant dynamometer table `tableMoment` N m at `referenceDegS` deg/s,
  /// linear in speed (moment = -table * rate / reference).
  double tableMoment = 2.0;
  double referenceDegS = 150.0;
  /// Extension resistance as a fraction of flexion resistance (the knee file's
  /// extension_factor; swing-phase control knees set the two valves apart).
  double extensionFactor = 1.0;
  // Hidden effects (0 = off).
  double extraViscous = 0;  // N m s/rad (library: knee_viscous_damping)
  double coulomb = 0;       // N m, tanh smoothing `coulombRate` rad/s (library: knee_coulomb_friction)
  double coulombRate = 1.0;
  double assistStiffness = 0;  // N m/rad towards extension (library: extension_assist_spring)
  /// Outside the library: an elastic strap across hip and knee (biarticular), moment
  /// k (theta - phi - offset) flexing the hip and extending the knee. N m/rad.
  double strapStiffness = 0;
  double strapOffset = 0.0;  // rad
  /// Outside the library: a hydraulic cushion that resists extension only near full
  /// extension: -cushion * rate while the knee extends below `cushionBelow`. N m s/rad.
  double cushionDamping = 0;
  double cushionBelow = 20.0 * kPi / 180.0;  // rad
  /// Outside the library: a stiffening that resists flexion only in deep flexion:
  /// -stiffening * (theta - stiffeningFrom) beyond `stiffeningFrom`. N m/rad.
  double stiffening = 0;
  double stiffeningFrom = 55.0 * kPi / 180.0;  // rad
  /// The drive that really acts is this times the recorded hip moment (library:
  /// hip_moment_scale); the CSV keeps the recorded one.
  double hipDriveGain = 1.0;
  /// Hip and knee flexion rates at toe-off, rad/s (library: toe_off_velocity); the participant
  /// file keeps 0.
  double toeOffHipRate = 0.0;
  double toeOffKneeRate = 0.0;
  /// Hidden: the socket's give (off by default). With it the measured thigh is the socket's
  /// (a lab's thigh markers sit on the socket) and the knee is socket to shank.
  SocketTruth socket;
};

/// A hip drive: flexion half-sine then extension half-sine, then nothing.
struct HipDrive {
  std::string name;
  double flexion, flexionTime, extension, extensionTime;  // N m, s
};

inline double hipMoment(const HipDrive& d, double t) {
  if (t < d.flexionTime) return d.flexion * std::sin(kPi * t / d.flexionTime);
  const double u = t - d.flexionTime;
  if (u < d.extensionTime) return -d.extension * std::sin(kPi * u / d.extensionTime);
  return 0.0;
}

/// Slow, normal and fast swings: a weaker and longer, or stronger and shorter, hip drive.
/// Sized so that Burkett's P1 swings like a person walks (peak knee flexion 58-68 deg, peak
/// hip flexion 32-36 deg; Winter 2009 Appendix A, normal cadence, peaks near 65 and 30 deg):
/// a stronger drive takes the hip to its 90 deg range limit, which is not a gait.
inline std::vector<HipDrive> threeDrives() {
  return {{"slow", 14.4, 0.24, 7.2, 0.24}, {"normal", 18.0, 0.20, 9.0, 0.20}, {"fast", 22.8, 0.17, 11.4, 0.17}};
}

struct Vec2 {
  double x, y;
};
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

/// The shank and foot as one rigid body, in the shank frame (x forward along the foot, y up
/// along the shank, origin at the knee): mass, COM and inertia about the COM.
struct ShankBody {
  double mass;
  Vec2 com;
  double inertia;
};

inline ShankBody shankBodyOf(const Segment& shank, const Segment& foot) {
  const double as = shank.length - shank.comFromDistal, L2 = shank.length;
  const double cf = foot.length - foot.comFromDistal;
  const double m2 = shank.mass + foot.mass;
  const Vec2 c{foot.mass * cf / m2, -(shank.mass * as + foot.mass * L2) / m2};
  const double jKnee = shank.inertia + shank.mass * as * as + foot.inertia + foot.mass * (cf * cf + L2 * L2);
  return {m2, c, jKnee - m2 * dot(c, c)};
}

/// Knee moment (N m, positive flexes) from the knee law and the hidden knee effects.
inline double kneeMoment(const SwingTruth& m, double theta, double thetaDot, double phi) {
  const double c = m.tableMoment / (m.referenceDegS * kPi / 180.0) * (thetaDot < 0 ? m.extensionFactor : 1.0);
  double M = -c * thetaDot;
  M += -m.extraViscous * thetaDot - m.coulomb * std::tanh(thetaDot / m.coulombRate) - m.assistStiffness * theta;
  M += -m.strapStiffness * (theta - phi - m.strapOffset);
  if (thetaDot < 0 && theta < m.cushionBelow) M += -m.cushionDamping * thetaDot;
  if (theta > m.stiffeningFrom) M += -m.stiffening * (theta - m.stiffeningFrom);
  return M;
}

/// The strap's moment on the hip (N m, positive flexes the hip).
inline double strapHipMoment(const SwingTruth& m, double theta, double phi) {
  return m.strapStiffness * (theta - phi - m.strapOffset);
}

/// Accelerations (phi'', psi'') of the chain thigh + (shank and foot as one body) by Kane's
/// method: for each generalized speed u_j, the sum over bodies of m a . dv/du_j + I alpha
/// dw/du_j equals the generalized active force. `hipMomentNm` acts on the thigh (positive
/// flexes the hip), `kneeMomentNm` between thigh and shank (positive flexes the knee).
/// Angles and rates in rad and rad/s (y = phi, psi, phi', psi'); `gravity` in m/s^2.
inline void chainAccelerations(const Segment& thigh, const Segment& shank, const Segment& foot, const double* y,
                               double hipMomentNm, double kneeMomentNm, double* acc, double gravity = kG) {
  const double phi = y[0], psi = y[1], phiDot = y[2], psiDot = y[3];
  // Thigh: COM a1 below the hip along the thigh.
  const double a1 = thigh.length - thigh.comFromDistal, L1 = thigh.length;
  const ShankBody body = shankBodyOf(shank, foot);
  const double m2 = body.mass, i2 = body.inertia;
  const Vec2 c = body.com;
  // Unit vectors.
  const Vec2 e1{std::sin(phi), -std::cos(phi)}, n1{std::cos(phi), std::sin(phi)};
  const Vec2 rc{c.x * std::cos(psi) - c.y * std::sin(psi), c.x * std::sin(psi) + c.y * std::cos(psi)};  // R(psi) c
  const Vec2 rcPerp{-rc.y, rc.x};                                                                       // d(R c)/dpsi
  // Partial velocities of the COMs: thigh v1 = a1 n1 phi'; shank v2 = L1 n1 phi' + rcPerp psi'.
  const Vec2 v1phi = a1 * n1, v2phi = L1 * n1, v2psi = rcPerp;
  // Velocity-product accelerations (centripetal).
  const Vec2 a1rest = (-a1 * phiDot * phiDot) * e1;
  const Vec2 a2rest = (-L1 * phiDot * phiDot) * e1 + (-psiDot * psiDot) * rc;
  // Generalized inertia.
  const double M11 = thigh.mass * dot(v1phi, v1phi) + thigh.inertia + m2 * dot(v2phi, v2phi);
  const double M12 = m2 * dot(v2phi, v2psi);
  const double M22 = m2 * dot(v2psi, v2psi) + i2;
  // Generalized active forces: gravity, hip moment, knee moment.
  const Vec2 g1{0, -thigh.mass * gravity}, g2{0, -m2 * gravity};
  const double Q1 = dot(g1, v1phi) + dot(g2, v2phi) + hipMomentNm + kneeMomentNm - thigh.mass * dot(a1rest, v1phi) -
                    m2 * dot(a2rest, v2phi);
  const double Q2 = dot(g2, v2psi) - kneeMomentNm - m2 * dot(a2rest, v2psi);
  const double det = M11 * M22 - M12 * M12;
  acc[0] = (M22 * Q1 - M12 * Q2) / det;
  acc[1] = (M11 * Q2 - M12 * Q1) / det;
}

/// Accelerations (phi'', psi'') of the truth `m` under hip drive `d` at time t (s).
inline void accelerations(const SwingTruth& m, const HipDrive& d, double t, const double* y, double* acc) {
  const double theta = y[0] - y[1], thetaDot = y[2] - y[3];
  const double Mk = kneeMoment(m, theta, thetaDot, y[0]);
  const double Mh = m.hipDriveGain * hipMoment(d, t) + strapHipMoment(m, theta, y[0]);
  chainAccelerations(m.thigh, m.shank, m.foot, y, Mh, Mk, acc);
}

/// The leg with a socket (m.socket), by Kane's method in absolute angles: y = (phi, p,
/// sigma, psi) and their rates: phi the residual limb, p the piston (m, + = down the limb),
/// sigma the socket, psi the shank (all from hanging straight down). The thigh segment is
/// the limb plus the socket (first and second moments about the hip). The socket spring and
/// damper act on sigma - phi, the knee's moment on sigma - psi. Accelerations to `acc` (4).
inline void socketAccelerations(const SwingTruth& m, const HipDrive& d, double t, const double* y, double* acc) {
  const SocketTruth& sk = m.socket;
  const double phi = y[0], p = y[1], sigma = y[2], psi = y[3];
  const double phiDot = y[4], pDot = y[5], sigmaDot = y[6], psiDot = y[7];
  // Limb = thigh - socket.
  const double toPivot = m.thigh.length - sk.pivotAboveKnee, socketCom = toPivot - sk.comAbovePivot;
  const double thighCom = m.thigh.length - m.thigh.comFromDistal;
  const double limbMass = m.thigh.mass - sk.mass;
  const double limbCom = (m.thigh.mass * thighCom - sk.mass * socketCom) / limbMass;
  const double limbInertia = m.thigh.inertia + m.thigh.mass * thighCom * thighCom -
                             (sk.inertia + sk.mass * socketCom * socketCom) - limbMass * limbCom * limbCom;
  const ShankBody body = shankBodyOf(m.shank, m.foot);
  const double m2 = body.mass, i2 = body.inertia;
  const Vec2 c = body.com;
  const Vec2 eP{std::sin(phi), -std::cos(phi)}, nP{std::cos(phi), std::sin(phi)};
  const Vec2 eS{std::sin(sigma), -std::cos(sigma)}, nS{std::cos(sigma), std::sin(sigma)};
  const Vec2 rc{c.x * std::cos(psi) - c.y * std::sin(psi), c.x * std::sin(psi) + c.y * std::cos(psi)};
  const Vec2 rcPerp{-rc.y, rc.x};
  const double r = toPivot + p, a = sk.pivotAboveKnee;
  // Partial velocities (per phi', p', sigma', psi') and velocity-product accelerations.
  const Vec2 zero{0, 0};
  const Vec2 vLimb[4] = {limbCom * nP, zero, zero, zero};
  const Vec2 vSocket[4] = {r * nP, eP, (-sk.comAbovePivot) * nS, zero};
  const Vec2 vShank[4] = {r * nP, eP, a * nS, rcPerp};
  const Vec2 pivotRest = (2 * pDot * phiDot) * nP + (-r * phiDot * phiDot) * eP;
  const Vec2 restLimb = (-limbCom * phiDot * phiDot) * eP;
  const Vec2 restSocket = pivotRest + (sk.comAbovePivot * sigmaDot * sigmaDot) * eS;
  const Vec2 restShank = pivotRest + (-a * sigmaDot * sigmaDot) * eS + (-psiDot * psiDot) * rc;
  const double spin[3][4] = {{1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const double masses[3] = {limbMass, sk.mass, m2}, inertias[3] = {limbInertia, sk.inertia, i2};
  const Vec2* partials[3] = {vLimb, vSocket, vShank};
  const Vec2 rests[3] = {restLimb, restSocket, restShank};
  // Active forces: the drive on the limb, the socket's spring and damper, the knee.
  const double theta = sigma - psi, thetaDot = sigmaDot - psiDot;
  const double Mk = kneeMoment(m, theta, thetaDot, sigma);
  const double socketMoment = -sk.rotationStiffness * (sigma - phi) - sk.rotationDamping * (sigmaDot - phiDot);
  double Q[4] = {m.hipDriveGain * hipMoment(d, t) - socketMoment, -sk.pistonStiffness * p - sk.pistonDamping * pDot,
                 socketMoment + Mk, -Mk};
  double M[4][4] = {};
  for (int b = 0; b < 3; ++b)
    for (int j = 0; j < 4; ++j) {
      Q[j] += dot(Vec2{0, -masses[b] * kG}, partials[b][j]) - masses[b] * dot(rests[b], partials[b][j]);
      for (int k = 0; k < 4; ++k)
        M[j][k] += masses[b] * dot(partials[b][k], partials[b][j]) + inertias[b] * spin[b][j] * spin[b][k];
    }
  for (int k = 0; k < 4; ++k)  // Gaussian elimination (M is positive definite)
    for (int i = k + 1; i < 4; ++i) {
      const double f = M[i][k] / M[k][k];
      for (int j = k; j < 4; ++j) M[i][j] -= f * M[k][j];
      Q[i] -= f * Q[k];
    }
  for (int i = 3; i >= 0; --i) {
    double s = Q[i];
    for (int j = i + 1; j < 4; ++j) s -= M[i][j] * acc[j];
    acc[i] = s / M[i][i];
  }
}

/// One classical RK4 step of y' = f(t, y) (N states).
template <int N, class F>
void rk4Step(F f, double t, double step, double* y) {
  double k1[N], k2[N], k3[N], k4[N], tmp[N];
  f(t, y, k1);
  for (int j = 0; j < N; ++j) tmp[j] = y[j] + step / 2 * k1[j];
  f(t + step / 2, tmp, k2);
  for (int j = 0; j < N; ++j) tmp[j] = y[j] + step / 2 * k2[j];
  f(t + step / 2, tmp, k3);
  for (int j = 0; j < N; ++j) tmp[j] = y[j] + step * k3[j];
  f(t + step, tmp, k4);
  for (int j = 0; j < N; ++j) y[j] += step / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
}

struct SwingSamples {
  std::vector<double> time, hipDeg, kneeDeg, hipMomentNm;
  std::vector<double> cleanKneeDeg;
};

/// From toe-off (hip `hip0Deg`, knee `knee0Deg`, at rest) with RK4 at `step` s, sampled at
/// `rate` Hz; angle noise `noiseDeg` (white, Gaussian) on both angles.
inline SwingSamples generateSwing(const SwingTruth& m, const HipDrive& d, double noiseDeg, std::uint64_t seed,
                                  double hip0Deg = -15.0, double knee0Deg = 10.0, double endKneeDeg = 8.0,
                                  double rate = 500.0, double step = 1e-4) {
  const double deg = kPi / 180.0;
  // Rigid: (phi, psi, rates). With a socket: (phi, p, sigma, psi, rates), the socket at rest
  // and undeflected at toe-off.
  const bool socket = m.socket.rotationStiffness > 0;
  const double hip0 = hip0Deg * deg, shank0 = (hip0Deg - knee0Deg) * deg;
  const double shankRate0 = m.toeOffHipRate - m.toeOffKneeRate;
  double y[8] = {hip0, shank0, m.toeOffHipRate, shankRate0};
  if (socket) {
    const double z[8] = {hip0, 0, hip0, shank0, m.toeOffHipRate, 0, m.toeOffHipRate, shankRate0};
    std::copy(z, z + 8, y);
  }
  // The lab's thigh (the socket's, where the markers are) and knee.
  auto thighOf = [&] { return socket ? y[2] : y[0]; };
  auto kneeOf = [&] { return socket ? y[2] - y[3] : y[0] - y[1]; };
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  SwingSamples s;
  const int perSample = static_cast<int>(std::lround(1.0 / (rate * step)));
  double peak = 0;
  for (int i = 0; i < 100000; ++i) {
    const double t = i / rate;
    const double knee = kneeOf() / deg;
    peak = std::max(peak, knee);
    if (i > 10 && peak > knee0Deg + 20.0 && knee < endKneeDeg) break;
    if (t > 1.5) throw std::runtime_error("independent swing did not return within 1.5 s");
    s.time.push_back(t);
    s.hipDeg.push_back(thighOf() / deg + noiseDeg * normal(engine));
    s.kneeDeg.push_back(knee + noiseDeg * normal(engine));
    s.cleanKneeDeg.push_back(knee);
    s.hipMomentNm.push_back(hipMoment(d, t));
    for (int k = 0; k < perSample; ++k) {
      const double tk = t + k * step;
      if (socket) {
        rk4Step<8>(
            [&](double tt, const double* yy, double* out) {
              std::copy(yy + 4, yy + 8, out);
              socketAccelerations(m, d, tt, yy, out + 4);
            },
            tk, step, y);
        continue;
      }
      rk4Step<4>(
          [&](double tt, const double* yy, double* out) {
            out[0] = yy[2];
            out[1] = yy[3];
            accelerations(m, d, tt, yy, out + 2);
          },
          tk, step, y);
    }
  }
  return s;
}

inline void writeSwingCsv(const SwingSamples& s, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  f << "time_s,hip_flexion_deg,knee_flexion_deg,hip_moment_Nm\n";
  for (std::size_t i = 0; i < s.time.size(); ++i)
    f << s.time[i] << "," << s.hipDeg[i] << "," << s.kneeDeg[i] << "," << s.hipMomentNm[i] << "\n";
}

/// The participant and knee-model YAML of the truth (a user's files), into `dir`.
inline void writeSwingModelFiles(const SwingTruth& m, const std::string& dir) {
  std::ofstream knee(dir + "/knee.yaml");
  knee << "kind: damping_table\nname: constant-damping\nsource: independent test generator\n"
       << "damping_table:\n  reference_speed_deg_s: " << m.referenceDegS << "\n  speed_rule: linear\n"
       << "  extension_factor: " << m.extensionFactor << "\n  flexion_deg: [0, 35, 70]\n  moment_Nm: [" << m.tableMoment
       << ", " << m.tableMoment << ", " << m.tableMoment << "]\n"
       << "hyperextension_stop: {engage_flexion_deg: 0, stiffness_Nm_per_rad1p5: 20000, restitution: 0.4}\n";
  std::ofstream p(dir + "/participant.yaml");
  auto seg = [&](const char* name, const Segment& s) {
    p << "  " << name << ": {length_m: " << s.length << ", mass_kg: " << s.mass
      << ", com_from_distal_m: " << s.comFromDistal << ", inertia_kgm2: " << s.inertia << "}\n";
  };
  p << "name: INDEP\nsource: independent test generator\nheight_m: 1.83\nbody_mass_kg: 70\nsegments:\n";
  seg("thigh", m.thigh);
  seg("shank", m.shank);
  seg("foot", m.foot);
  p << "knee_friction_Nm: 0\nknee_model: knee.yaml\ncom_rule: fixed_from_proximal\nfoot_com_from: toe\n"
    << "initial: {hip_flexion_deg: -15, knee_flexion_deg: 10, hip_flexion_rate_deg_s: 0, knee_flexion_rate_deg_s: 0}\n"
    << "hip_range: {min_flexion_deg: -30, max_flexion_deg: 90}\n"
    << "swing_end: {thigh_target_flexion_deg: 20, zone_of_stability_deg: 6, time_limit_s: 1.5, settle_dwell_s: 0.15}\n"
    << "hip_moment: {profile: biphasic_sine, flexion_amplitude_Nm: 30, flexion_duration_s: 0.20, "
       "extension_amplitude_Nm: 15, extension_duration_s: 0.20, time_scale: 1.0}\n";
}

}  // namespace independent
