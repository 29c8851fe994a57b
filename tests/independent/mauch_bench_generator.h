#pragma once
// An independent Mauch bench generator for tests. It shares no code with src/: its own
// switch functions, its own latch integration (classical RK4 on a fine fixed step over the
// continuous piston motion), its own piston trajectory, its own noise. It writes the
// measured-file format a user has (time_s, position_m, force_N) and nothing else, so what
// swingsim reads from it is what it would read from a bench.
//
// Equations: Chien et al. 2014 Eqs. 2-16 (switches S1..S8, latch
// dS2/dt = k (1 - S1) [1/2 - 1/2 tanh((x - xhy)/x0) - S2], 2- and 4-phase force laws), with
// the phase reading documented in docs/mauch.md (x > 0 in flexion; phase 2 = S1 S2 S8,
// phase 3 = (1 - S1) S8). Coefficients: Chien 2014 Table 1 (F90E90).
//
// Piston motion: not Winter's knee angles (swingsim's own generator uses those) but a sum of
// smooth bumps over a stride: loading-response flexion (about 6 mm of piston travel, 15 deg
// of knee flexion on a 25 mm moment arm), a terminal-stance hyperextension dip held about
// 0.1 s (so the latch can complete), swing flexion (about 26 mm, 60 deg), extension back to
// zero at heel strike.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace independent {

struct PhaseLaw {
  double f, k, c;  // N, N/m, N s/m
};

/// What the generator knows of the truth.
struct MauchTruth {
  int phases = 4;
  std::vector<PhaseLaw> laws;    // one per phase
  double velocityWidth = 5e-4;   // m/s (S1)
  double positionWidth = 5e-4;   // m (latch indicator, S8)
  double hyperextension = 5e-5;  // xhy, m
  double latchRate = 1e4;        // 1/s
  // Hidden effects (all off at 0).
  double orifice = 0;          // a in a xd|xd|, N s^2/m^2 (library: orifice_quadratic)
  double coulomb = 0;          // Fc in Fc tanh(xd / coulombWidth), N (library: coulomb_friction)
  double coulombWidth = 0.01;  // m/s
  double positionDamping = 0;  // cx in cx x xd, N s/m^2 (library: position_dependent_damping)
  double movingMass = 0;       // m in m xdd, kg: Newton's second law for the piston, rod and
                               // oil moving with them (library: inertia)
  /// Outside the library: oil/air compliance, the whole force lags its law by a first-order
  /// filter with this time constant (s). 0 = off.
  double complianceLag = 0;
  /// Outside the library: an elastic end stop in deep flexion, K (x - start)^2 beyond `start`
  /// (N/m^2, m), a force of position alone that grows faster than any phase's k x. 0 = off.
  double endStop = 0;
  double endStopStart = 0.02;
};

/// Chien 2014 Table 1, F90E90.
inline std::vector<PhaseLaw> chienTable1(int phases) {
  if (phases == 2) return {{-189.91, 14116, 1415.05}, {-260.12, 28599, 17738.7}};
  return {{-243.72, 29975.3, 17087.9}, {30.95, 2489.92, 928.7}, {-184.5, 10414.6, 501.49}, {-488.12, 563313, 14672.2}};
}

/// One walking condition.
struct Gait {
  std::string name;
  double stride;     // s
  double amplitude;  // multiplies the flexion bumps
  int strides = 3;
};

/// A smooth bump a exp(-((s - c)/w)^2) of piston position (m) over the stride fraction s.
struct PistonBump {
  double a, c, w;
};

/// The bumps of one stride of gait `g`.
inline std::vector<PistonBump> pistonBumps(const Gait& g) {
  return {
      {0.0065 * g.amplitude, 0.15, 0.07},  // loading response flexion
      {-0.0016, 0.50, 0.045},              // terminal stance hyperextension (flat-ish dip)
      {-0.0016, 0.55, 0.045},
      {0.0260 * g.amplitude, 0.74, 0.085},  // swing flexion
  };
}

/// Piston position (m) and velocity (m/s) at time t in a stride of length T.
inline void pistonMotion(double t, const Gait& g, double& x, double& xd) {
  const double T = g.stride;
  const double s = std::fmod(t, T) / T;  // stride fraction
  x = 0;
  xd = 0;
  // Periodic over neighbouring strides.
  for (int shift = -1; shift <= 1; ++shift) {
    for (const PistonBump& b : pistonBumps(g)) {
      const double u = (s - b.c - shift) / b.w;
      const double e = b.a * std::exp(-u * u);
      x += e;
      xd += e * (-2.0 * u / b.w) / T;
    }
  }
}

/// Piston acceleration (m/s^2) at time t: the bumps' second derivative in closed form,
/// d^2/dt^2 [a exp(-u^2)] = a exp(-u^2) (4 u^2 - 2) / (w T)^2 with u = (s - c) / w, s = t / T
/// (not a difference of positions, so it shares nothing with the library's estimate).
inline double pistonAcceleration(double t, const Gait& g) {
  const double T = g.stride;
  const double s = std::fmod(t, T) / T;
  double xdd = 0;
  for (int shift = -1; shift <= 1; ++shift)
    for (const PistonBump& b : pistonBumps(g)) {
      const double u = (s - b.c - shift) / b.w;
      xdd += b.a * std::exp(-u * u) * (4.0 * u * u - 2.0) / (b.w * b.w * T * T);
    }
  return xdd;
}

inline double halfTanh(double v) { return 0.5 + 0.5 * std::tanh(v); }

/// The force law at (x, xd, S2), without the compliance lag.
inline double lawForce(const MauchTruth& m, double x, double xd, double s2) {
  const double s1 = halfTanh(xd / m.velocityWidth);
  const double s8 = halfTanh((x - m.hyperextension) / m.positionWidth);
  double gates[4];
  int n = 0;
  if (m.phases == 2) {
    const double s3 = 1.0 - s1 * (1.0 - s2);
    gates[0] = 1.0 - s3;
    gates[1] = s3;
    n = 2;
  } else {
    gates[0] = s1 * (1.0 - s2) * s8;
    gates[1] = s1 * s2 * s8;
    gates[2] = (1.0 - s1) * s8;
    gates[3] = 1.0 - s8;
    n = 4;
  }
  double F = 0;
  for (int p = 0; p < n; ++p) {
    const PhaseLaw& l = m.laws[static_cast<std::size_t>(p)];
    F += gates[p] * (l.f + l.k * x + l.c * xd);
  }
  F += m.orifice * xd * std::abs(xd);
  F += m.coulomb * std::tanh(xd / m.coulombWidth);
  F += m.positionDamping * x * xd;
  if (x > m.endStopStart) F += m.endStop * (x - m.endStopStart) * (x - m.endStopStart);
  return F;
}

inline double latchRateOfChange(const MauchTruth& m, double x, double xd, double s2) {
  const double s1 = halfTanh(xd / m.velocityWidth);
  const double indicator = 0.5 - 0.5 * std::tanh((x - m.hyperextension) / m.positionWidth);
  return m.latchRate * (1.0 - s1) * (indicator - s2);
}

struct Record {
  std::vector<double> time, position, force, cleanForce;
};

/// Samples at `rate` Hz from heel strike (S2 = 0), integrating the latch (and the lag) with
/// RK4 on `substeps` steps per sample; adds white Gaussian noise of `noise` N.
inline Record generate(const MauchTruth& m, const Gait& g, double noise, std::uint64_t seed, double rate = 361.4,
                       int substeps = 40) {
  Record r;
  const double dt = 1.0 / rate, h = dt / substeps;
  const std::size_t samples = static_cast<std::size_t>(g.strides * g.stride * rate);
  double s2 = 0.0, lagged = 0.0;
  bool lagStarted = false;
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto deriv = [&](double t, double y0, double y1, double& d0, double& d1) {
    double x, xd;
    pistonMotion(t, g, x, xd);
    d0 = latchRateOfChange(m, x, xd, y0);
    d1 = m.complianceLag > 0 ? (lawForce(m, x, xd, y0) - y1) / m.complianceLag : 0.0;
  };
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) * dt;
    double x, xd;
    pistonMotion(t, g, x, xd);
    if (!lagStarted) {
      lagged = lawForce(m, x, xd, s2);
      lagStarted = true;
    }
    // The moving mass acts on the rod directly, outside the oil's compliance lag.
    const double F = (m.complianceLag > 0 ? lagged : lawForce(m, x, xd, s2)) + m.movingMass * pistonAcceleration(t, g);
    r.time.push_back(t);
    r.position.push_back(x);
    r.cleanForce.push_back(F);
    r.force.push_back(F + noise * normal(engine));
    for (int k = 0; k < substeps; ++k) {
      const double tk = t + k * h;
      double a0, a1, b0, b1, c0, c1, d0, d1;
      deriv(tk, s2, lagged, a0, a1);
      deriv(tk + h / 2, s2 + h / 2 * a0, lagged + h / 2 * a1, b0, b1);
      deriv(tk + h / 2, s2 + h / 2 * b0, lagged + h / 2 * b1, c0, c1);
      deriv(tk + h, s2 + h * c0, lagged + h * c1, d0, d1);
      s2 += h / 6 * (a0 + 2 * b0 + 2 * c0 + d0);
      lagged += h / 6 * (a1 + 2 * b1 + 2 * c1 + d1);
    }
  }
  return r;
}

/// Writes a record as a user's bench file.
inline void writeCsv(const Record& r, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(10);
  f << "time_s,position_m,force_N\n";
  for (std::size_t i = 0; i < r.time.size(); ++i) f << r.time[i] << "," << r.position[i] << "," << r.force[i] << "\n";
}

/// RMS of the difference between two forces.
inline double rmsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / static_cast<double>(a.size()));
}

/// Log-uniform draw in [lo, hi].
inline double logUniform(std::mt19937_64& e, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(e));
}

/// A truth with Chien's Table 1 coefficients and switch constants drawn across ranges that
/// keep the bench meaningful (widths well below the motion's own scale, so phases are
/// distinct): velocity width 2e-4..4e-3 m/s, position width 5e-5..4e-4 m, xhy -2e-4..3e-4 m,
/// latch rate 100..2e4 /s. None is swingsim's default.
inline MauchTruth drawTruth(int phases, std::uint64_t seed) {
  std::mt19937_64 e(seed * 7919 + 17);
  MauchTruth m;
  m.phases = phases;
  m.laws = chienTable1(phases);
  m.velocityWidth = logUniform(e, 2e-4, 4e-3);
  m.positionWidth = logUniform(e, 5e-5, 4e-4);
  m.hyperextension = std::uniform_real_distribution<double>(-2e-4, 3e-4)(e);
  m.latchRate = logUniform(e, 100.0, 2e4);
  return m;
}

/// Slow, normal and fast walking as on Chien's bench (stride times of the three speeds;
/// slower walking flexes less).
inline std::vector<Gait> chienGaits() {
  return {{"slow", 1.30, 0.90, 3}, {"normal", 1.10, 1.00, 3}, {"fast", 0.96, 1.08, 3}};
}

}  // namespace independent
