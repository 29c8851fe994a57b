#include "identify/bench_data.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace swingsim {

CylinderTrace calcCylinderTrace(const MauchCylinder& cylinder, const std::vector<double>& time,
                                const std::vector<double>& x, const std::vector<double>& xd, double s2Start) {
  CylinderTrace tr;
  tr.latch = calcLatchHistory(time, x, xd, cylinder.params().switches, s2Start);
  tr.force.resize(time.size());
  // Piston acceleration only for an added inertia effect (the same difference estimate again).
  const std::vector<double> xdd = cylinder.params().effects.inertia && time.size() >= 2
                                      ? estimatePistonVelocity(time, xd)
                                      : std::vector<double>(time.size(), 0.0);
  for (std::size_t i = 0; i < time.size(); ++i) {
    tr.force[i] = cylinder.calcForce(x[i], xd[i], xdd[i], tr.latch[i]);
    tr.switches.push_back(calcMauchSwitches(x[i], xd[i], tr.latch[i], cylinder.params().switches));
    tr.gates.push_back(cylinder.calcGates(tr.switches.back()));
  }
  return tr;
}

double NormalNoise::uniform() {
  // 53 random bits -> (0, 1), never 0 so the logarithm is finite.
  return (static_cast<double>(engine_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double NormalNoise::next() {
  if (haveSpare_) {
    haveSpare_ = false;
    return spare_;
  }
  constexpr double kTwoPi = 6.28318530717958647692;
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double a = kTwoPi * uniform();
  spare_ = r * std::sin(a);
  haveSpare_ = true;
  return r * std::cos(a);
}

}  // namespace swingsim
