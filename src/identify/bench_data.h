#pragma once
// Cylinder bench data: reading and checking measured files (`time_s,position_m,force_N`),
// the piston velocity estimate shared by the generator and the fit, running a Mauch cylinder
// along a position record, and reproducible measurement noise.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "knee/mauch_cylinder.h"
#include "model/bench_record.h"
#include "numerics/sample_derivative.h"

namespace swingsim {

/// Force, latch and phase gates of a cylinder along a record (velocity already estimated).
struct CylinderTrace {
  std::vector<double> force;               ///< N
  std::vector<double> latch;               ///< S2
  std::vector<MauchSwitches> switches;     ///< all switch values per sample
  std::vector<std::vector<double>> gates;  ///< per sample, per phase
};

/// Runs the cylinder along (time, x, xd) from latch `s2Start` (0 at heel strike).
CylinderTrace calcCylinderTrace(const MauchCylinder& cylinder, const std::vector<double>& time,
                                const std::vector<double>& x, const std::vector<double>& xd, double s2Start = 0.0);

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
