#pragma once
// The missing cylinder force, where it acts: along every bench record (training and held out),
// the measured force minus the model's at the measured piston motion, binned over piston
// position and the direction of motion, and said in one line per region where it departs from
// zero beyond the measurement noise. The cylinder's counterpart of the swing's missing moment
// (identify/missing_moment.h): a bench measures the force itself, so no inverse dynamics or
// smoother is needed (docs/diagnosis.md, "The cylinder's missing force").
#include <string>
#include <vector>

#include "identify/bench_data.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

/// The rule both missing quantities (this force and the swing's moment) share: a bin departs
/// from zero when its mean is beyond this many standard errors, the normal 99.9 % two-sided
/// point with a Bonferroni allowance for about 30 bins (3.5 sd, p = 0.00047), and has at
/// least this many samples.
constexpr double kMissingRegionZ = 3.5;
constexpr int kMissingRegionMinSamples = 5;
/// Width of the cylinder's position bins, mm: a tenth of a swing's stroke (about 26 mm).
constexpr double kMissingForceBinMm = 2.0;

/// One region of the measured state where the missing force departs from zero.
struct MissingForceRegion {
  bool extending = false;                        ///< the piston extends (speed < 0), else it compresses
  double force = 0;                              ///< mean missing force, N (+ resists compression)
  double low = 0, high = 0;                      ///< the smallest and largest of its bins' means, N
  double positionLowMm = 0, positionHighMm = 0;  ///< measured piston position range of its samples
  double speedLowMmS = 0, speedHighMmS = 0;      ///< measured piston speed range of its samples
  int samples = 0;
  /// "missing force: +95 N (40 to 160) resisting compression at piston 20-28 mm while
  /// compressing (2 to 180 mm/s)".
  std::string describe() const;
};

/// The missing force at every sample (the map a figure draws) and its regions.
struct MissingForce {
  std::vector<double> positionMm, speedMmS, forceN, noiseN;  ///< per sample; noise: its record's sd, N
  std::vector<MissingForceRegion> regions;                   ///< the largest (force x samples) first
};

/// The missing force of `records` under `params` (each record starting unlatched, S2 = 0, as
/// bench records do), with each record's force noise `noise` (N, same order).
MissingForce calcMissingForce(const MauchCylinderParams& params, const std::vector<BenchData>& records,
                              const std::vector<double>& noise);

/// One line for a report: the three largest regions ("; "-separated), or that none departs
/// from zero.
std::string describeMissingForce(const std::vector<MissingForceRegion>& regions);

}  // namespace swingsim
