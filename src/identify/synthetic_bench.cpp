#include "identify/synthetic_bench.h"

namespace swingsim {

BenchData makeSyntheticBench(const MauchCylinderParams& truth, const KneeAngleStride& stride,
                             const BenchProfileParams& profile, double noise, std::uint64_t seed,
                             const std::string& stem) {
  const MauchCylinder cylinder(truth);
  const BenchProfile prof = makeBenchProfile(stride, profile, cylinder.geometry());
  BenchData d;
  d.path = stem + ".csv";
  d.stem = stem;
  d.time = prof.time;
  d.position = prof.position;
  d.velocity = estimatePistonVelocity(d.time, d.position);
  d.force = calcCylinderTrace(cylinder, d.time, d.position, d.velocity, 0.0).force;
  NormalNoise rng(seed);
  for (double& f : d.force) f += noise * rng.next();
  return d;
}

}  // namespace swingsim
