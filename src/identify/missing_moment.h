#pragma once
// The missing knee moment, where it acts: for each measured swing, the knee moment the
// measured motion needs (inverse dynamics through the same leg, swing/reference_swing.h) minus
// the moment the model's knee law applies at the measured state. Derivatives come from a
// local polynomial smoother (numerics/local_polynomial.h) whose noise is propagated into a
// band. Mapped over knee angle and the direction of motion, and said in one line per region
// where it departs from zero beyond its band: the mechanism's place in the measured state,
// where the residual of the angles points at its consequences (docs/diagnosis.md,
// "The missing moment, where it acts").
#include <string>
#include <vector>

#include "identify/swing_model.h"
#include "model/swing_record.h"

namespace swingsim {

/// One region of the measured state where the missing moment departs from zero.
struct MissingMomentRegion {
  bool extending = false;                    ///< the knee extends (rate < 0) in the region, else it flexes
  double moment = 0;                         ///< mean missing moment, N m (+ = flexion)
  double low = 0, high = 0;                  ///< the smallest and largest of its 5-deg bins' means, N m
  double kneeLowDeg = 0, kneeHighDeg = 0;    ///< measured knee flexion range of its samples
  double rateLowDegS = 0, rateHighDegS = 0;  ///< measured knee rate range of its samples
  int samples = 0;
  /// "missing moment: +6.1 N m (4.0 to 8.2) resisting extension at knee 8-20 deg while
  /// extending (-700 to -10 deg/s)".
  std::string describe() const;
};

/// The missing moment at every sample used (the map a figure draws) and its regions.
struct MissingMoment {
  std::vector<double> kneeDeg, kneeRateDegS, momentNm, bandNm;  ///< per sample; band = 1.96 sd of the noise
  std::vector<MissingMomentRegion> regions;
  /// Why it was not computed, or what it leaves out; "" if nothing.
  std::string note;
};

/// The missing moment of `records` under the model `params` on `base` (hip-moment or thigh
/// drive alike: the knee's row needs no hip moment). `references`: per record, a noise-free
/// trajectory near the measured one (the model's own prediction along it); the smoother then
/// smooths only the measured minus the reference, whose curvature is small, so a wide window
/// costs little bias, and the reference's derivatives (by central differences) are added back.
/// An empty list smooths the measured angles themselves. Samples whose smoothing window reaches
/// within 2 deg of full extension (the stop's impact, which no smoother resolves) or past a
/// record's end are left out. Not computed (note says why) for a knee law with states of its
/// own (the Mauch latch).
MissingMoment calcMissingMoment(const SwingBase& base, const SwingModelParams& params,
                                const std::vector<SwingRecord>& records,
                                const std::vector<SwingPrediction>& references = {});

/// One line for a report: the regions ("; "-separated), or that none departs from zero.
std::string describeMissingMoment(const MissingMoment& missing);

}  // namespace swingsim
