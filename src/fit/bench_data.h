#pragma once
// Cylinder bench data: reading and checking measured files (`time_s,position_m,force_N`),
// the piston velocity estimate shared by the generator and the fit, running a Mauch cylinder
// along a position record, and reproducible measurement noise.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "knee/mauch_cylinder.h"

namespace swingsim {

/// One bench file (one condition).
struct BenchData {
  std::string path;
  std::string stem;               ///< file name without directory and extension
  std::vector<double> time;       ///< s, strictly increasing
  std::vector<double> position;   ///< piston position x, m
  std::vector<double> force;      ///< measured cylinder force, N (positive resists compression)
  std::vector<double> velocity;   ///< estimated xd, m/s (estimatePistonVelocity)
};

/// Reads a bench CSV. Requires columns time_s, position_m, force_N (others ignored),
/// strictly increasing time, finite numbers, at least `minRows` rows (>= 3) and a position
/// that varies. Throws InputError with `file:line: column: ...`.
BenchData readBenchCsv(const std::string& path, std::size_t minRows);

/// Piston velocity from sampled positions: central differences on the (possibly uneven)
/// time grid, one-sided at both ends. The generator uses the same estimate, so a model
/// fitted to generated data sees exactly the velocity that made the force.
std::vector<double> estimatePistonVelocity(const std::vector<double>& time, const std::vector<double>& x);

/// Force, latch and phase gates of a cylinder along a record (velocity already estimated).
struct CylinderTrace {
  std::vector<double> force;                ///< N
  std::vector<double> latch;                ///< S2
  std::vector<MauchSwitches> switches;      ///< all switch values per sample
  std::vector<std::vector<double>> gates;   ///< per sample, per phase
};

/// Runs the cylinder along (time, x, xd) from latch `s2Start` (0 at heel strike).
CylinderTrace calcCylinderTrace(const MauchCylinder& cylinder, const std::vector<double>& time,
                                const std::vector<double>& x, const std::vector<double>& xd,
                                double s2Start = 0.0);

/// Standard normal deviates from std::mt19937_64 with our own Box-Muller transform, so a
/// seed gives the same numbers on every platform (std::normal_distribution does not).
class NormalNoise {
 public:
  explicit NormalNoise(std::uint64_t seed) : engine_(seed) {}
  double next();

 private:
  double uniform();  // in (0, 1)
  std::mt19937_64 engine_;
  bool haveSpare_ = false;
  double spare_ = 0;
};

}  // namespace swingsim
