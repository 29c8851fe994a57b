#pragma once
// Bench records of the Mauch cylinder generated as `swingsim generate` makes them, and the
// shipped cylinder models, for the cylinder fit's tests (cylinder_fit, cylinder_regression,
// projected_residual, switch_grid_costs).
#include <cstdint>
#include <string>

#include "identify/synthetic_bench.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "knee/bench_profile.h"

namespace swingsim::mauch_bench_fixture {

inline const std::string kRoot = SWINGSIM_SOURCE_DIR;
inline constexpr double kNoise = 25.0;  // N, as in studies/mauch2014-bench.yaml

/// A bench record of `truth` over Winter's knee stride at `stride` s, its amplitude times
/// `scale`, with Gaussian force noise of SD `noise` N drawn from `seed`.
inline BenchData makeBench(const MauchCylinderParams& truth, double stride, double scale, double noise,
                           std::uint64_t seed, const std::string& stem) {
  const auto knee = readKneeAngleStride(kRoot + "/studies/data/winter-natural-cadence.csv", 28, 97);
  BenchProfileParams p;
  p.strideTime = stride;
  p.amplitudeScale = scale;
  return makeSyntheticBench(truth, knee, p, noise, seed, stem);
}

/// A shipped cylinder model, models/FILE.
inline MauchCylinderParams model(const std::string& file) { return loadMauchCylinder(kRoot + "/models/" + file); }

}  // namespace swingsim::mauch_bench_fixture
