#pragma once
// One cylinder bench record (Bench data CSV: time_s, position_m, force_N), in SI units.
#include <string>
#include <vector>

namespace swingsim {

/// One bench file (one condition).
struct BenchData {
  std::string path;
  std::string stem;              ///< file name without directory and extension
  std::vector<double> time;      ///< s, strictly increasing
  std::vector<double> position;  ///< piston position x, m
  std::vector<double> force;     ///< measured cylinder force, N (positive resists compression)
  std::vector<double> velocity;  ///< estimated xd, m/s (estimatePistonVelocity)
};

}  // namespace swingsim
